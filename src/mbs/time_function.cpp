#include "inerta/mbs/time_function.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "inerta/mbs/parameter_check.hpp"

namespace inerta::mbs {

void TimeFunction::validate() const {
  switch (kind) {
    case Kind::Constant:
      check::finite({"constant function", ""}, "value", offset);
      return;
    case Kind::Sine: {
      const check::Element who{"sine function", ""};
      check::finite(who, "amplitude", amplitude);
      check::nonnegative(who, "frequency", frequency, "Hz");
      check::finite(who, "phase", phase, "rad");
      check::finite(who, "offset", offset);
      return;
    }
    case Kind::Table: {
      const check::Element who{"table function", ""};
      if (t.empty()) check::fail(who, "points", "expected at least one [t, value] pair");
      if (t.size() != v.size())
        check::fail(who, "points", fmt::format("has {} times but {} values", t.size(), v.size()));
      for (std::size_t k = 0; k < t.size(); ++k) {
        const std::string at = fmt::format("points[{}]", k);
        check::finite(who, at, t[k], "s");
        check::finite(who, at, v[k]);
        if (k > 0 && !(t[k] > t[k - 1]))
          check::fail(who, at, fmt::format("times must be strictly increasing (t = {} after t = {})", t[k], t[k - 1]));
      }
      return;
    }
  }
}

TimeFunction TimeFunction::constant(double value) {
  TimeFunction f;
  f.offset = value;
  f.validate();
  return f;
}

TimeFunction TimeFunction::table(std::vector<double> t, std::vector<double> v) {
  TimeFunction f;
  f.kind = Kind::Table;
  f.t = std::move(t);
  f.v = std::move(v);
  f.validate();
  return f;
}

TimeFunction TimeFunction::sine(double amplitude, double frequency_hz, double phase, double offset) {
  TimeFunction f;
  f.kind = Kind::Sine;
  f.amplitude = amplitude;
  f.frequency = frequency_hz;
  f.phase = phase;
  f.offset = offset;
  f.validate();
  return f;
}

namespace {
// Index of the table segment containing time (clamped to the first/last segment).
std::size_t segment(const std::vector<double>& t, double time) {
  auto it = std::upper_bound(t.begin(), t.end(), time);
  std::size_t k = it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1;
  return std::min(k, t.size() - 2);
}
}  // namespace

double TimeFunction::value(double time) const {
  switch (kind) {
    case Kind::Constant:
      return offset;
    case Kind::Sine:
      return offset + amplitude * std::sin(2 * std::numbers::pi * frequency * time + phase);
    case Kind::Table: {
      if (t.size() == 1 || time <= t.front()) return v.front();
      if (time >= t.back()) return v.back();
      std::size_t k = segment(t, time);
      double s = (time - t[k]) / (t[k + 1] - t[k]);
      return v[k] + s * (v[k + 1] - v[k]);
    }
  }
  return 0.0;
}

double TimeFunction::d1(double time) const {
  switch (kind) {
    case Kind::Constant:
      return 0.0;
    case Kind::Sine: {
      double w = 2 * std::numbers::pi * frequency;
      return amplitude * w * std::cos(w * time + phase);
    }
    case Kind::Table: {
      if (t.size() == 1 || time <= t.front() || time >= t.back()) return 0.0;
      std::size_t k = segment(t, time);
      return (v[k + 1] - v[k]) / (t[k + 1] - t[k]);
    }
  }
  return 0.0;
}

double TimeFunction::d2(double time) const {
  if (kind != Kind::Sine) return 0.0;
  double w = 2 * std::numbers::pi * frequency;
  return -amplitude * w * w * std::sin(w * time + phase);
}

}  // namespace inerta::mbs
