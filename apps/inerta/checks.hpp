#pragma once
// Validators for numeric command-line options (issue 15): every number is finite and in its range,
// every count a whole number in its range, checked before any cast; a bad value is a usage error
// (exit 105) naming the option.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
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

/// A finite number in [lo, hi]; `what` describes the range and unit, e.g. "> 0 s".
inline CLI::Validator number_in(double lo, double hi, const std::string& what) {
  return CLI::Validator(
      [=](std::string& s) {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v) || !std::isfinite(v)) return fmt::format("expected a finite number, got '{}'", s);
        if (!(v >= lo && v <= hi)) return fmt::format("{} is out of range; expected {}", s, what);
        return std::string();
      },
      what);
}

/// A positive finite number (below 1e300), `unit` for the message.
inline CLI::Validator positive(const std::string& unit) { return number_in(1e-300, 1e300, "> 0 " + unit); }

/// A whole number in [lo, hi].
inline CLI::Validator count_in(long lo, long hi) {
  return CLI::Validator(
      [=](std::string& s) {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v) || !std::isfinite(v) || v != std::floor(v))
          return fmt::format("expected a whole number, got '{}'", s);
        if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)))
          return fmt::format("{} is out of range; expected {} … {}", s, lo, hi);
        return std::string();
      },
      fmt::format("{} … {}", lo, hi));
}

}  // namespace inerta::cli
