#pragma once
// Linear analysis of any model (spec/02 §2.5): the state-space model from named inputs to named
// outputs, frequency responses, and the random response by Lyapunov equations (white noise,
// ISO 8608 road profiles with wheelbase delays).
#include <complex>
#include <string>
#include <vector>

#include "inerta/mbs/linearisation.hpp"
#include "inerta/mbs/model.hpp"

namespace inerta::analysis {

/// Ẏ = A Y + B u,  y = C Y + D u + D1 u̇ + D2 ü  (D1, D2 zero unless an output responds directly to a
/// driven input's rate or acceleration). Y = X − T0 u − T1 u̇ with X = [ξ; ξ̇; z] of mbs::linearise
/// (T0 = B1 + A B2, T1 = B2: Y = X unless a driven input acts through a damper or inerter), so the
/// model is proper: B = B0 + A T0, D = Cy T0 + D0, D1 := Cy T1 + D1.
struct StateSpace {
  std::string model;
  std::vector<std::string> states, inputs, outputs;
  std::vector<std::string> input_units;  ///< "m" or "rad" (driving joint), "N or N·m" (load)
  Eigen::MatrixXd A, B, C, D, D1, D2;
  Eigen::MatrixXd T0, T1;  ///< the state shift above
  mbs::LinearSystem system;
  /// True if D1 or D2 has a non-zero entry (relative to the output's scale).
  bool has_rate_feedthrough() const;
};

/// The state space of `model` about the state `x` (a static equilibrium, or an assembled
/// configuration) at time t. InvalidArgument for unknown inputs or outputs (mbs::linearise).
StateSpace state_space(const mbs::Model& model, const mbs::State& x, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs, double t = 0.0);

/// About the static equilibrium at t = 0 (assembled, then mbs::static_equilibrium).
StateSpace state_space(const mbs::Model& model, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs);

/// H(j 2π f) = C (j ω I − A)⁻¹ B + D + j ω D1 − ω² D2, outputs × inputs, per frequency (Hz).
std::vector<Eigen::MatrixXcd> frequency_response(const StateSpace& ss, const std::vector<double>& f_hz);

/// Stationary random response: output covariance and rms.
struct RandomResponse {
  std::vector<std::string> outputs;
  Eigen::VectorXd rms;        ///< per output, its unit
  Eigen::MatrixXd covariance;  ///< outputs × outputs
};

/// Under white noise on the inputs with intensity W (inputs × inputs): E[u(t) u(s)ᵀ] = W δ(t − s).
/// For a two-sided PSD S0 per rad/s, W = 2π S0; for a one-sided PSD G per Hz, W = G / 2.
/// With W = I the rms are the H2 norms of the transfer functions. NumericalError if the model is
/// not asymptotically stable; InvalidArgument for an output with a non-zero D, D1 or D2 term on a
/// noisy input (its variance is infinite).
RandomResponse white_noise_response(const StateSpace& ss, const Eigen::MatrixXd& W);

/// ISO 8608 road: one-sided displacement PSD G_d(n) = G_d(n0) (n/n0)⁻², n0 = 0.1 cycles/m, travelled at
/// speed v: the road velocity is white noise of intensity 2π² n0² G_d(n0) v (m²/s). Each named input
/// (a driving joint) sees the road delayed by its `delay` (s, e.g. wheelbase / v); a delay is a
/// Padé approximant of order `pade_order`.
struct Road {
  double gd0 = 256e-6;  ///< G_d(n0), m³ (class C geometric mean)
  double speed = 20;    ///< m/s
  std::vector<std::string> inputs;  ///< the driving joints that see the road
  std::vector<double> delays;       ///< s, per input (empty: all 0)
  int pade_order = 8;
};

/// White-noise velocity intensity of an ISO 8608 road, m²/s (Road).
double road_velocity_intensity(double gd0, double speed);

/// Errors as white_noise_response; InvalidArgument if an output follows the road displacement
/// statically (its rms grows without bound: use a relative output such as a deflection).
RandomResponse road_response(const StateSpace& ss, const Road& road);

}  // namespace inerta::analysis
