#include "inerta/mbs/parameter_check.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"

namespace inerta::mbs::check {

std::string Element::describe() const { return name.empty() ? std::string(kind) : fmt::format("{} '{}'", kind, name); }

void fail(const Element& who, const std::string& parameter, const std::string& problem) {
  throw InvalidArgument(who.describe(), parameter, problem);
}

namespace {
// "must be >= 0 (N/m), got -5", or without a unit "must be >= 0 (got -5)".
[[noreturn]] void fail_value(const Element& who, const std::string& parameter, std::string_view condition, double v,
                             std::string_view unit) {
  fail(who, parameter,
       unit.empty() ? fmt::format("must be {} (got {})", condition, v)
                    : fmt::format("must be {} ({}), got {}", condition, unit, v));
}
}  // namespace

double finite(const Element& who, const std::string& parameter, double v, std::string_view unit) {
  if (!std::isfinite(v)) fail_value(who, parameter, "a finite number", v, unit);
  return v;
}
double nonnegative(const Element& who, const std::string& parameter, double v, std::string_view unit) {
  finite(who, parameter, v, unit);
  if (!(v >= 0)) fail_value(who, parameter, ">= 0", v, unit);
  return v;
}
double positive(const Element& who, const std::string& parameter, double v, std::string_view unit) {
  finite(who, parameter, v, unit);
  if (!(v > 0)) fail_value(who, parameter, "> 0", v, unit);
  return v;
}

}  // namespace inerta::mbs::check
