#pragma once
// Typed errors. Every error message names what failed and the quantities involved.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace inerta {

/// Bad input in a model or study file: "file:line: key: what is wrong; expected ...".
struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A non-physical or inconsistent argument given to a library constructor or function (negative
/// stiffness, zero mass, NaN, an unknown handle). File readers turn it into a ModelError naming
/// the file, line and key.
struct InvalidArgument : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
  /// A bad value of one named parameter of `element` ("spring 'k1'"):
  /// what() = "spring 'k1': k: must be >= 0 (N/m), got -5" with problem = "must be >= 0 (N/m), got -5".
  /// The parameter is named as in the model file (k, free_length, mass, points[2], ...), so that a
  /// file reader can point at the line of that key.
  InvalidArgument(const std::string& element, const std::string& parameter, const std::string& problem)
      : std::invalid_argument(element + ": " + parameter + ": " + problem), parameter_(parameter), problem_(problem) {}
  /// The offending parameter; empty if the error is not about one parameter.
  const std::string& parameter() const noexcept { return parameter_; }
  /// The message without the element and the parameter (what() if there is no parameter).
  const char* problem() const noexcept { return parameter_.empty() ? what() : problem_.c_str(); }

 private:
  std::string parameter_, problem_;
};

/// Numerical failure (assembly not converging, singular constraints, integrator failure, ...).
/// The message carries the simulated time and the quantities involved.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A numeric argument's rule, shared by the CLI option and the Python argument that mirror each
/// other: finite and in [lo, hi]; `what` says so in words ("> 0 s, at most 1e7 s").
struct NumberRule {
  double lo, hi;
  const char* what;
  /// "" if v obeys the rule, else the message ("0 is out of range; expected > 0 s, at most 1e7 s",
  /// "expected a finite number, got 'nan'"); `text` is v as the user wrote it.
  std::string check(double v, const std::string& text) const {
    if (!(v == v) || v - v != 0) return "expected a finite number, got '" + text + "'";
    if (!(v >= lo && v <= hi)) return text + " is out of range; expected " + what;
    return {};
  }
};

/// A count's rule (cycles, spans, points), shared like NumberRule: a whole number in [lo, hi].
struct CountRule {
  long lo, hi;
  /// "" if v obeys the rule, else the message ("expected a whole number, got '2.5'",
  /// "0 is out of range; expected 1 … 100000").
  std::string check(double v, const std::string& text) const {
    if (!(v == v) || v - v != 0 || v != std::floor(v))
      return "expected a whole number, got '" + text + "'";
    if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)))
      return text + " is out of range; expected " + std::to_string(lo) + " … " + std::to_string(hi);
    return {};
  }
};

/// The library's own check of an options field by the rule its CLI option and Python argument use:
/// InvalidArgument "name: message" (v written with up to 15 significant digits).
template <class Rule>
void require(const Rule& rule, double v, const char* name) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", v);
  if (const std::string e = rule.check(v, text); !e.empty()) throw InvalidArgument(std::string(name) + ": " + e);
}

}  // namespace inerta
