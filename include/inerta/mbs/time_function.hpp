#pragma once
// Scalar functions of time f(t) with first and second derivatives, used by point forces and
// driving constraints (spec/02 §2.1, §2.3). The factories check their arguments (validate); the
// fields stay public, so a function assembled by hand is checked by the elements that take it
// (PointForce, PointTorque).
#include <vector>

namespace inerta::mbs {

struct TimeFunction {
  enum class Kind { Constant, Sine, Table };
  Kind kind = Kind::Constant;
  double offset = 0.0;       ///< Constant value, or the sine's mean.
  double amplitude = 0.0;    ///< Sine: f = offset + amplitude sin(2π frequency t + phase).
  double frequency = 0.0;    ///< Hz.
  double phase = 0.0;        ///< rad.
  std::vector<double> t, v;  ///< Table: piecewise linear in t (strictly increasing), held outside.

  /// The factories throw inerta::InvalidArgument for what validate() rejects.
  static TimeFunction constant(double value);
  static TimeFunction sine(double amplitude, double frequency_hz, double phase = 0.0, double offset = 0.0);
  /// Points (t[k], v[k]), at least one, times strictly increasing.
  static TimeFunction table(std::vector<double> t, std::vector<double> v);

  /// InvalidArgument unless every number is finite, a sine's frequency is >= 0 (Hz) and a table has
  /// as many values as times, at least one point and strictly increasing times. The parameter it
  /// names is the model file's key: value; amplitude, frequency, phase, offset; points or points[k].
  void validate() const;

  double value(double time) const;
  double d1(double time) const;  ///< df/dt
  double d2(double time) const;  ///< d²f/dt² (zero on table segments)
};

}  // namespace inerta::mbs
