#pragma once
// Linearisation about a static equilibrium (spec/02 §2.5) and modes (spec/06 §6.3).
//
// Independent coordinates ξ: q = q_e + N ξ with N an orthonormal basis of the null space of C_q at
// the equilibrium (SVD). The state X = [ξ; ξ̇; z] (z: internal states of network struts) obeys
// Ẋ = A X to first order, with A from central differences of the nonlinear right-hand side:
// ξ̈ = Nᵀ q̈(q_e + N ξ, N ξ̇, z) (q̈ from eq. 4.12, whose constraint forces Nᵀ removes), ż = f_z.
// The inerter mass terms (eq. 3.33) are in q̈, so they are in A; M_r = Nᵀ (M + M_I) N is reported.
#include <complex>
#include <string>
#include <vector>

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

struct LinearModel {
  State equilibrium;
  double t = 0;
  Eigen::MatrixXd N;        ///< n × d basis of independent coordinates
  Eigen::MatrixXd A;        ///< (2d + nz)², state [ξ; ξ̇; z]
  Eigen::MatrixXd M, C, K;  ///< d × d reduced mass (incl. inerters), damping and stiffness (z held)
  int dof = 0, nz = 0;
};

/// Linearises `model` about the equilibrium `x` (q̇ = 0) at time t.
LinearModel linearise(const Model& model, const State& x, double t = 0.0);

struct Mode {
  std::complex<double> eigenvalue;
  double frequency_hz = 0;   ///< |λ| / 2π (undamped natural frequency)
  double damping_ratio = 0;  ///< −Re λ / |λ|
  Eigen::VectorXd shape;     ///< real part of N ξ (body coordinates), normalised to max |·| = 1
  std::string description;   ///< the dominant coordinates, e.g. "head.y 100 %, upper_main.theta 31 %"
};

/// Oscillatory and real modes (one per conjugate pair), sorted by frequency; modes with |λ| below
/// 1e-6 rad/s (rigid-body or neutral) are left out.
std::vector<Mode> modes(const Model& model, const LinearModel& lin);

}  // namespace inerta::mbs
