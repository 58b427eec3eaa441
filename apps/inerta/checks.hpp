#pragma once
// Validators for numeric command-line options (issue 15): every number is finite and in its range,
// every count a whole number in its range, checked before any cast; a bad value is a usage error
// (exit 105) naming the option.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <string>

#include "inerta/error.hpp"

namespace inerta::cli {

/// A number obeying a library rule (inerta::NumberRule: the same rule and message as the Python
/// argument it mirrors).
inline CLI::Validator number_rule(const NumberRule& rule) {
  return CLI::Validator(
      [=](std::string& s) {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v)) return fmt::format("expected a finite number, got '{}'", s);
        return rule.check(v, s);
      },
      rule.what);
}

/// A count obeying a library rule (inerta::CountRule).
inline CLI::Validator count_rule(const CountRule& rule) {
  return CLI::Validator(
      [=](std::string& s) {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v)) return fmt::format("expected a whole number, got '{}'", s);
        return rule.check(v, s);
      },
      fmt::format("{} … {}", rule.lo, rule.hi));
}

/// A finite number in [lo, hi]; `what` describes the range and unit, e.g. "> 0 s" (NumberRule's words).
inline CLI::Validator number_in(double lo, double hi, const std::string& what) {
  return CLI::Validator(
      [=](std::string& s) {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v)) return fmt::format("expected a finite number, got '{}'", s);
        return NumberRule{lo, hi, what.c_str()}.check(v, s);
      },
      what);
}

/// A positive finite number (below 1e300), `unit` for the message.
inline CLI::Validator positive(const std::string& unit) { return number_in(1e-300, 1e300, "> 0 " + unit); }

/// A whole number in [lo, hi] (CountRule's words).
inline CLI::Validator count_in(long lo, long hi) { return count_rule(CountRule{lo, hi}); }

}  // namespace inerta::cli
