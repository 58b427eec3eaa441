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
};

/// Numerical failure (assembly not converging, singular constraints, integrator failure, ...).
/// The message carries the simulated time and the quantities involved.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace inerta
