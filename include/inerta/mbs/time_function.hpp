#pragma once
// Scalar functions of time f(t) with first and second derivatives, used by point forces and
// driving constraints (spec/02 §2.1, §2.3).
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

  static TimeFunction constant(double value);
  static TimeFunction sine(double amplitude, double frequency_hz, double phase = 0.0, double offset = 0.0);

  double value(double time) const;
  double d1(double time) const;  ///< df/dt
  double d2(double time) const;  ///< d²f/dt² (zero on table segments)
};

}  // namespace inerta::mbs
