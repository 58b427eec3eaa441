#pragma once
// Linearisation about a static equilibrium (spec/02 §2.5) and modes (spec/06 §6.3).
//
// Independent coordinates ξ: a subset of q chosen by coordinate partitioning (QR of C_q with column
// pivoting at the equilibrium: the pivot columns are dependent), q = q_e + N ξ with N = [I; −C_d⁻¹ C_i]
// in the partition, so ξ are named coordinates with their own sign and Nt (the rows of the
// independent coordinates) is a left inverse of N. The state X = [ξ; ξ̇; z] (z: internal states of network struts) obeys
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
  Eigen::MatrixXd N;             ///< n × d: q − q_e = N ξ to first order
  Eigen::MatrixXd Nt;            ///< d × n: ξ = Nt (q − q_e) (selects the independent coordinates)
  std::vector<int> independent;  ///< the coordinates ξ are (indices into q, ascending)
  Eigen::MatrixXd A;        ///< (2d + nz)², state [ξ; ξ̇; z]
  Eigen::MatrixXd M, C, K;  ///< d × d reduced mass (incl. inerters), damping and stiffness (z held)
  int dof = 0, nz = 0;
};

/// Linearises `model` about the equilibrium `x` (q̇ = 0) at time t.
LinearModel linearise(const Model& model, const State& x, double t = 0.0);

/// The names of the state X = [ξ; ξ̇; z]: "bar1.theta", "bar1.theta_dot", "strut.z0".
std::vector<std::string> state_names(const Model& model, const LinearModel& lin);

struct Mode {
  std::complex<double> eigenvalue;
  double frequency_hz = 0;         ///< |λ| / 2π (the natural frequency of the damped mode)
  double damped_frequency_hz = 0;  ///< Im λ / 2π (0 for a real mode)
  double damping_ratio = 0;        ///< −Re λ / |λ|
  Eigen::VectorXd shape;     ///< real part of N ξ (body coordinates), normalised to max |·| = 1
  std::string description;   ///< the dominant coordinates, e.g. "head.y 100 %, upper_main.theta 31 %"
};

/// Oscillatory and real modes (one per conjugate pair), sorted by frequency; modes with |λ| below
/// 1e-6 rad/s (rigid-body or neutral) are left out. Shapes are scaled so that their largest
/// component is +1 (deterministic sign).
std::vector<Mode> modes(const Model& model, const LinearModel& lin);

struct UndampedMode {
  double frequency_hz = 0;  ///< ω/2π from K φ = ω² M φ (reduced M, K; network states held)
  Eigen::VectorXd shape;    ///< N φ (body coordinates), largest component +1
  std::string description;
};

/// The undamped natural frequencies and shapes of (M, K), ascending; zero and negative ω² (a
/// mechanism or an unstable equilibrium) are kept with frequency 0 or −|ω|/2π. Empty if M is not
/// positive definite.
std::vector<UndampedMode> undamped_modes(const Model& model, const LinearModel& lin);

/// Linearisation with inputs and outputs (spec/02 §2.5): named inputs u are point loads (a
/// point_force or point_torque element: u adds to its value, N or N·m) and driving joints (u adds to
/// the prescribed coordinate, m or rad); outputs y are any outputs of the model. With the input
/// rates (a driving joint also prescribes u̇ and ü),
///   Ẋ = A X + B0 u + B1 u̇ + B2 ü,   y = Cy X + D0 u + D1 u̇ + D2 ü,   X = [ξ; ξ̇; z],
/// where a driven input moves only dependent coordinates (q = q_e + N ξ + G u, Nt G = 0).
struct LinearSystem {
  LinearModel lin;
  std::vector<std::string> inputs, outputs;
  std::vector<bool> motion;  ///< per input: a driving joint (true) or a load (false)
  /// Per input: the index of its driving joint in model.joints, or −1 for a load.
  std::vector<int> joint;
  Eigen::MatrixXd B0, B1, B2, Cy, D0, D1, D2;
};

/// InvalidArgument naming the unknown input or output (and the known names), or an input that is
/// neither a load nor a driving joint.
LinearSystem linearise(const Model& model, const State& x, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs, double t = 0.0);

}  // namespace inerta::mbs
