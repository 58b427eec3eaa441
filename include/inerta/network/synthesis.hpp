#pragma once
// Synthesis of a series–parallel spring/damper/inerter network from a positive-real admittance
// (docs/synthesis.md): Foster pole removals, damper removals of min Re, and Bott–Duffin steps
// (Bott & Duffin, J. Appl. Phys. 1949; Guillemin, Synthesis of Passive Networks, ch. 9).
#include <string>

#include "inerta/network/network.hpp"
#include "inerta/network/realisation.hpp"

namespace inerta::network {

struct Synthesis {
  Network network;          ///< element values bound; names k1, k2, …, c1, …, b1, … unique
  int elements = 0;
  int reactive = 0;         ///< springs + inerters
  int degree = 0;           ///< McMillan degree of Y (after cancelling common factors)
  bool bott_duffin = false; ///< a Bott–Duffin step was needed
  bool minimal_reactive = false;  ///< reactive == degree
  std::string method;       ///< "Foster/ladder" or "Bott–Duffin"
};

/// A network whose admittance is y. Throws NetworkError(…, 0) if y is not positive real
/// (positive_real(y) with its default tolerance), inerta::InvalidArgument for bad coefficients.
Synthesis synthesise(const Rational& y);

}  // namespace inerta::network
