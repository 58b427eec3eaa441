#pragma once
// Typed errors. Every error message names what failed and the quantities involved.
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

}  // namespace inerta
