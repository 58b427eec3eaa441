#pragma once
// Rational admittance and a state-space realisation of a network's force–length law.
//
// A strut carrying the network transmits F(s) = G(s)·u(s), u = l − l_ref, with the dynamic
// stiffness G(s) = s·Y(s) (spec/03 §3.1). G = N/D is split by polynomial division into a direct
// part and a strictly proper rest:
//
//   F = d2·l̈ + d1·l̇ + d0·u + C x,   ẋ = A x + B u
//
// d2 is an inerter directly across the terminals (it enters the mass matrix with the exact l̈ of
// eq. 3.20), d1 a direct damper, d0 a direct spring; x are the internal states (internal nodes),
// realised in controllable canonical form and scaled so that every state is a displacement of
// the order of u (x₁ → u at steady state).
#include <Eigen/Dense>
#include <vector>

#include "inerta/network/network.hpp"

namespace inerta::network {

using Poly = std::vector<double>;  ///< coefficients, ascending powers of s

/// Y(s) = P(s)/Q(s) of a simplified network (no 0/∞ values; not Open/Rigid).
struct Rational {
  Poly num, den;
  std::complex<double> operator()(std::complex<double> s) const;
};
Rational rational_admittance(const Network& simplified);

struct Realisation {
  double d0 = 0, d1 = 0, d2 = 0;
  Eigen::MatrixXd A;
  Eigen::VectorXd B, C;
  int n_states() const { return static_cast<int>(B.size()); }
  /// G(s) = d0 + d1 s + d2 s² + C (sI − A)⁻¹ B
  std::complex<double> dynamic_stiffness(std::complex<double> s) const;
  /// Static stiffness G(0) and the steady internal state for a constant u: x = −A⁻¹B u.
  double static_stiffness() const;
  Eigen::VectorXd steady_state(double u) const;
};

/// Realisation of a simplified network (throws NetworkError for Open or Rigid).
Realisation realise(const Network& simplified);

}  // namespace inerta::network
