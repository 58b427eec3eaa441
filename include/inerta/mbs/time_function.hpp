#pragma once
// Scalar functions of time f(t) with exact first and second derivatives, used by point forces and
// driving constraints (spec/02 §2.1, §2.3: a driving row C = q − f(t) needs C_t = −f′ and f″ in γ,
// eq. 4.3). The factories check their arguments (validate); the fields stay public, so a function
// assembled by hand is checked by the elements that take it (PointForce, PointTorque).
//
//   constant      offset
//   sine          offset + amplitude sin(2π frequency t + phase)
//   table         through (t_k, v_k): a C² cubic spline with natural ends (f″ = 0 at the first and
//                 last point), continued outside the table as the straight line with the end
//                 value and end slope (still C², f″ = 0 there); or, with Interpolation::Linear,
//                 piecewise linear (f″ = 0, f′ jumps at every point), held at the end values outside.
//   ramp          offset + slope (min(max(t, start), end) − start): a corner at start and at end
//   step          offset + height s(τ), τ = (t − start)/rise clamped to [0, 1],
//                 s = 10τ³ − 15τ⁴ + 6τ⁵ (quintic smoothstep: s′ = s″ = 0 at both ends, C²)
//   chirp         offset + amplitude sin φ(t), instantaneous frequency φ′/2π from frequency (f0)
//                 at t = 0 to f1 at t = duration, linearly or (Sweep::Logarithmic) geometrically;
//                 before 0 it stays at f0, after `duration` at f1 (C¹; f″ jumps by a finite amount)
//   sum_of_sines  offset + Σ amplitudes_i sin(2π frequencies_i t + phases_i)
//   polynomial    Σ_k coefficients_k (t − t0)^k
//   road          offset + h(v (t − delay)): an ISO 8608 random profile (mbs/road.hpp), see road().
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "inerta/mbs/road.hpp"

namespace inerta::numerics {
class CubicSpline;
}  // namespace inerta::numerics

namespace inerta::mbs {

struct TimeFunction {
  enum class Kind { Constant, Sine, Table, Ramp, Step, Chirp, SumOfSines, Polynomial, Road };
  enum class Interpolation { Spline, Linear };
  enum class Sweep { Linear, Logarithmic };

  Kind kind = Kind::Constant;
  double offset = 0.0;       ///< Constant value; the mean of sine, chirp, step (its start value), ...
  double amplitude = 0.0;    ///< Sine, chirp; step: its height (file key `height`: offset → offset + height)
  double frequency = 0.0;    ///< Hz; chirp: the start frequency f0
  double phase = 0.0;        ///< rad (sine)
  std::vector<double> t, v;  ///< Table points, times strictly increasing
  Interpolation interpolation = Interpolation::Spline;
  double slope = 0.0;        ///< Ramp, units/s
  double start = 0.0;        ///< Ramp, step: s
  double end = std::numeric_limits<double>::infinity();  ///< Ramp: s (> start; ∞ = no end)
  double rise = 0.0;         ///< Step: rise time, s (> 0)
  double f1 = 0.0;           ///< Chirp: end frequency, Hz
  double duration = 0.0;     ///< Chirp: s (> 0)
  Sweep sweep = Sweep::Linear;
  std::vector<double> amplitudes, frequencies, phases;  ///< Sum of sines (Hz, rad)
  std::vector<double> coefficients;                     ///< Polynomial c0, c1, ...
  double t0 = 0.0;                                      ///< Polynomial: expansion point, s
  RoadProfile road_profile;                             ///< Road: what it was generated from
  /// Table (spline) and road: the interpolant, made by the factory (shared by copies).
  std::shared_ptr<const numerics::CubicSpline> spline;

  /// The factories throw inerta::InvalidArgument for what validate() rejects.
  static TimeFunction constant(double value);
  static TimeFunction sine(double amplitude, double frequency_hz, double phase = 0.0, double offset = 0.0);
  /// Points (t[k], v[k]), at least one, times strictly increasing (one point: a constant).
  static TimeFunction table(std::vector<double> t, std::vector<double> v,
                            Interpolation interpolation = Interpolation::Spline);
  static TimeFunction ramp(double slope, double start = 0.0, double offset = 0.0,
                           double end = std::numeric_limits<double>::infinity());
  static TimeFunction step(double height, double rise, double start = 0.0, double offset = 0.0);
  /// f0 > 0 and f1 > 0 for a logarithmic sweep; both ≥ 0 for a linear one.
  static TimeFunction chirp(double amplitude, double f0, double f1, double duration, Sweep sweep = Sweep::Linear,
                            double offset = 0.0);
  /// Phases empty (all 0) or one per amplitude; frequencies ≥ 0 (Hz).
  static TimeFunction sum_of_sines(std::vector<double> amplitudes, std::vector<double> frequencies,
                                   std::vector<double> phases = {}, double offset = 0.0);
  /// At least one coefficient.
  static TimeFunction polynomial(std::vector<double> coefficients, double t0 = 0.0);
  /// A seeded random road (ISO 8608, mbs/road.hpp): h(x) = Σ_k a_k cos(2π n_k x + φ_k) with
  /// n_k = k/L (L = length) for every k with n_min ≤ n_k ≤ n_max, a_k = sqrt(2 G_d(n_k)/L) (so
  /// Σ a_k²/2 = Σ G_d(n_k) Δn, Δn = 1/L) and φ_k uniform in [0, 2π) drawn in order of k from
  /// std::mt19937_64(seed) (std::uniform_real_distribution). h is evaluated exactly on a grid
  /// of spacing Δx ≤ 1/(16 n_max) by an inverse FFT and interpolated by a periodic cubic spline
  /// (C², period L), which is the function: f, f′, f″ are those of that spline, in time t' = x/v.
  /// InvalidArgument unless the class is A–H, speed > 0, 0 < n_min < n_max, length ≥ 1/n_min,
  /// delay ≥ 0, or if the grid would exceed 2^24 points.
  static TimeFunction road(const RoadProfile& profile, double offset = 0.0);

  /// InvalidArgument unless every number is finite and each kind's ranges hold (see the factories).
  /// The parameter it names is the model file's key: value; amplitude, frequency, phase, offset;
  /// points or points[k]; slope, start, end; rise; f1, duration; amplitudes, frequencies, phases;
  /// coefficients; class, speed, n_min, n_max, length, delay.
  void validate() const;

  /// False for a function with corners after t = 0, whose f′ jumps and whose f″ (a Dirac there) is
  /// not represented: a linear table with 2 or more points, a ramp with start > 0 or a finite end.
  /// Such a function drives a coordinate only through the Baumgarte terms at its corners.
  bool smooth() const;

  double value(double time) const;
  double d1(double time) const;  ///< df/dt (at a corner: the derivative after it)
  double d2(double time) const;  ///< d²f/dt²
};

}  // namespace inerta::mbs
