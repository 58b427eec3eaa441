#include "inerta/mbs/time_function.hpp"

#include <fmt/format.h>

#include <unsupported/Eigen/FFT>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "inerta/error.hpp"
#include "inerta/mbs/parameter_check.hpp"
#include "inerta/numerics/cubic_spline.hpp"

namespace inerta::mbs {

namespace {
constexpr double kPi = std::numbers::pi;

void finite_list(const check::Element& who, const std::string& key, const std::vector<double>& v,
                 std::string_view unit = {}) {
  for (std::size_t k = 0; k < v.size(); ++k) check::finite(who, fmt::format("{}[{}]", key, k), v[k], unit);
}

// The chirp's phase φ(t) and its derivatives φ′, φ″ (rad, rad/s, rad/s²), t clamped to [0, T]
// and continued with the end frequencies outside.
struct Phase {
  double p, w, a;
};
Phase chirp_phase(const TimeFunction& f, double t) {
  const double f0 = f.frequency, f1 = f.f1, T = f.duration;
  if (t <= 0) return {2 * kPi * f0 * t, 2 * kPi * f0, 0.0};
  auto inside = [&](double s) -> Phase {
    if (f.sweep == TimeFunction::Sweep::Linear) {
      const double k = (f1 - f0) / T;  // Hz/s
      return {2 * kPi * (f0 * s + 0.5 * k * s * s), 2 * kPi * (f0 + k * s), 2 * kPi * k};
    }
    const double r = std::log(f1 / f0) / T;  // 1/s: f(s) = f0 e^{r s}
    if (std::abs(r) < 1e-300) return {2 * kPi * f0 * s, 2 * kPi * f0, 0.0};
    const double e = std::exp(r * s);
    return {2 * kPi * f0 * (e - 1) / r, 2 * kPi * f0 * e, 2 * kPi * f0 * r * e};
  };
  if (t <= T) return inside(t);
  const Phase end = inside(T);
  return {end.p + 2 * kPi * f1 * (t - T), 2 * kPi * f1, 0.0};
}

// Quintic smoothstep s(τ) = 10τ³ − 15τ⁴ + 6τ⁵ and its derivatives in τ.
double smooth0(double u) { return u * u * u * (10 + u * (-15 + 6 * u)); }
double smooth1(double u) { return 30 * u * u * (1 - u) * (1 - u); }
double smooth2(double u) { return 60 * u * (1 - u) * (1 - 2 * u); }

// Index of the table segment containing time (clamped to the first/last segment).
std::size_t segment(const std::vector<double>& t, double time) {
  auto it = std::upper_bound(t.begin(), t.end(), time);
  std::size_t k = it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1;
  return std::min(k, t.size() - 2);
}

// A size ≥ n whose only prime factors are 2, 3 and 5 (a fast FFT).
std::size_t fft_size(std::size_t n) {
  for (std::size_t m = std::max<std::size_t>(n, 2);; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

constexpr std::size_t kMaxRoadGrid = std::size_t{1} << 22;

// validate(), with `made` = false for a factory that has not made its spline yet.
void check_function(const TimeFunction& f, bool made);
}  // namespace

void TimeFunction::validate() const { check_function(*this, true); }

namespace {
void check_function(const TimeFunction& f, bool made) {
  using Kind = TimeFunction::Kind;
  using Interpolation = TimeFunction::Interpolation;
  using Sweep = TimeFunction::Sweep;
  const auto& [kind, offset, amplitude, frequency, phase, t, v, interpolation, slope, start, end, rise, f1, duration,
               sweep, amplitudes, frequencies, phases, coefficients, t0, road_profile, spline] = f;
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
      if (made && interpolation == Interpolation::Spline && t.size() >= 2 && !spline)
        check::fail(who, "points", "a spline table must be made by TimeFunction::table (it holds the spline)");
      return;
    }
    case Kind::Ramp: {
      const check::Element who{"ramp function", ""};
      check::finite(who, "slope", slope, "1/s");
      check::finite(who, "start", start, "s");
      check::finite(who, "offset", offset);
      if (std::isnan(end) || !(end > start))
        check::fail(who, "end", fmt::format("must be after start = {} s (got {})", start, end));
      return;
    }
    case Kind::Step: {
      const check::Element who{"step function", ""};
      check::finite(who, "height", amplitude);
      check::positive(who, "rise", rise, "s");
      check::finite(who, "start", start, "s");
      check::finite(who, "offset", offset);
      return;
    }
    case Kind::Chirp: {
      const check::Element who{"chirp function", ""};
      check::finite(who, "amplitude", amplitude);
      check::finite(who, "offset", offset);
      check::positive(who, "duration", duration, "s");
      if (sweep == Sweep::Logarithmic) {
        check::positive(who, "f0", frequency, "Hz");
        check::positive(who, "f1", f1, "Hz");
      } else {
        check::nonnegative(who, "f0", frequency, "Hz");
        check::nonnegative(who, "f1", f1, "Hz");
      }
      return;
    }
    case Kind::SumOfSines: {
      const check::Element who{"sum_of_sines function", ""};
      if (amplitudes.empty()) check::fail(who, "amplitudes", "expected at least one amplitude");
      if (frequencies.size() != amplitudes.size())
        check::fail(who, "frequencies",
                    fmt::format("has {} frequencies for {} amplitudes; give one per amplitude", frequencies.size(),
                                amplitudes.size()));
      if (!phases.empty() && phases.size() != amplitudes.size())
        check::fail(who, "phases",
                    fmt::format("has {} phases for {} amplitudes; give one per amplitude (or none: all 0)",
                                phases.size(), amplitudes.size()));
      finite_list(who, "amplitudes", amplitudes);
      for (std::size_t k = 0; k < frequencies.size(); ++k)
        check::nonnegative(who, fmt::format("frequencies[{}]", k), frequencies[k], "Hz");
      finite_list(who, "phases", phases, "rad");
      check::finite(who, "offset", offset);
      return;
    }
    case Kind::Polynomial: {
      const check::Element who{"polynomial function", ""};
      if (coefficients.empty()) check::fail(who, "coefficients", "expected at least one coefficient [c0, c1, ...]");
      finite_list(who, "coefficients", coefficients);
      check::finite(who, "t0", t0, "s");
      return;
    }
    case Kind::Road: {
      const check::Element who{"road function", ""};
      const RoadProfile& r = road_profile;
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(r.road_class)));
      if (c < 'A' || c > 'H') check::fail(who, "class", fmt::format("expected an ISO 8608 class A to H, got '{}'", r.road_class));
      check::positive(who, "speed", r.speed, "m/s");
      check::positive(who, "n_min", r.n_min, "cycles/m");
      check::finite(who, "n_max", r.n_max, "cycles/m");
      if (!(r.n_max > r.n_min))
        check::fail(who, "n_max", fmt::format("must be > n_min = {} cycles/m (got {})", r.n_min, r.n_max));
      check::finite(who, "length", r.length, "m");
      if (!(r.length * r.n_min >= 1 - 1e-9))
        check::fail(who, "length",
                    fmt::format("must be at least the longest wavelength 1/n_min = {:g} m (got {:g} m; the profile "
                                "repeats after its length: at speed {:g} m/s that is duration = length / speed)",
                                1 / r.n_min, r.length, r.speed));
      check::nonnegative(who, "delay", r.delay, "s");
      check::finite(who, "offset", offset);
      if (16 * r.n_max * r.length > static_cast<double>(kMaxRoadGrid))
        check::fail(who, "length",
                    fmt::format("{:g} m with n_max = {:g} cycles/m needs a grid of {:.3g} points (at most {}); "
                                "shorten the profile or lower n_max",
                                r.length, r.n_max, 16 * r.n_max * r.length, kMaxRoadGrid));
      if (made && !spline) check::fail(who, "class", "a road must be made by TimeFunction::road (it holds the profile)");
      return;
    }
  }
}
}  // namespace

TimeFunction TimeFunction::constant(double value) {
  TimeFunction f;
  f.offset = value;
  f.validate();
  return f;
}

TimeFunction TimeFunction::table(std::vector<double> t, std::vector<double> v, Interpolation interpolation) {
  TimeFunction f;
  f.kind = Kind::Table;
  f.t = std::move(t);
  f.v = std::move(v);
  f.interpolation = interpolation;
  check_function(f, false);
  if (interpolation == Interpolation::Spline && f.t.size() >= 2)
    f.spline = std::make_shared<const numerics::CubicSpline>(f.t, f.v, numerics::CubicSpline::Ends::Natural);
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

TimeFunction TimeFunction::ramp(double slope, double start, double offset, double end) {
  TimeFunction f;
  f.kind = Kind::Ramp;
  f.slope = slope, f.start = start, f.offset = offset, f.end = end;
  f.validate();
  return f;
}

TimeFunction TimeFunction::step(double height, double rise, double start, double offset) {
  TimeFunction f;
  f.kind = Kind::Step;
  f.amplitude = height, f.rise = rise, f.start = start, f.offset = offset;
  f.validate();
  return f;
}

TimeFunction TimeFunction::chirp(double amplitude, double f0, double f1, double duration, Sweep sweep, double offset) {
  TimeFunction f;
  f.kind = Kind::Chirp;
  f.amplitude = amplitude, f.frequency = f0, f.f1 = f1, f.duration = duration, f.sweep = sweep, f.offset = offset;
  f.validate();
  return f;
}

TimeFunction TimeFunction::sum_of_sines(std::vector<double> amplitudes, std::vector<double> frequencies,
                                        std::vector<double> phases, double offset) {
  TimeFunction f;
  f.kind = Kind::SumOfSines;
  f.amplitudes = std::move(amplitudes), f.frequencies = std::move(frequencies), f.phases = std::move(phases);
  f.offset = offset;
  f.validate();
  if (f.phases.empty()) f.phases.assign(f.amplitudes.size(), 0.0);
  return f;
}

TimeFunction TimeFunction::polynomial(std::vector<double> coefficients, double t0) {
  TimeFunction f;
  f.kind = Kind::Polynomial;
  f.coefficients = std::move(coefficients), f.t0 = t0;
  f.validate();
  return f;
}

TimeFunction TimeFunction::road(const RoadProfile& profile, double offset) {
  TimeFunction f;
  f.kind = Kind::Road;
  f.road_profile = profile;
  f.offset = offset;
  check_function(f, false);
  RoadProfile& r = f.road_profile;
  r.road_class = static_cast<char>(std::toupper(static_cast<unsigned char>(r.road_class)));
  const double L = r.length, G0 = iso8608_gd0(r.road_class);
  const std::size_t N = fft_size(static_cast<std::size_t>(std::ceil(16 * r.n_max * L)));
  const auto k_lo = static_cast<std::size_t>(std::ceil(r.n_min * L - 1e-9));
  const auto k_hi = static_cast<std::size_t>(std::floor(r.n_max * L + 1e-9));
  if (k_hi < std::max<std::size_t>(k_lo, 1))
    check::fail({"road function", ""}, "length",
                fmt::format("{:g} m holds no wavenumber k/length in [n_min, n_max]; lengthen it", L));
  // h_j = Σ_k a_k cos(2π k j/N + φ_k) = Re[(1/N) Σ_k X_k e^{2πi kj/N}] with X_k = N a_k e^{iφ_k}.
  std::mt19937_64 gen(r.seed);
  std::uniform_real_distribution<double> uniform(0.0, 2 * kPi);
  std::vector<std::complex<double>> X(N, 0.0), h(N);
  for (std::size_t k = std::max<std::size_t>(k_lo, 1); k <= k_hi; ++k) {
    const double n = static_cast<double>(k) / L;
    const double a = std::sqrt(2 * G0 * std::pow(n / kIso8608N0, -2.0) / L);
    X[k] = static_cast<double>(N) * std::polar(a, uniform(gen));
  }
  Eigen::FFT<double> fft;
  fft.inv(h, X);
  const double dt = L / static_cast<double>(N) / r.speed;  // grid spacing in time
  std::vector<double> ts(N + 1), ys(N + 1);
  for (std::size_t j = 0; j <= N; ++j) ts[j] = static_cast<double>(j) * dt, ys[j] = h[j % N].real();
  f.spline = std::make_shared<const numerics::CubicSpline>(std::move(ts), std::move(ys),
                                                           numerics::CubicSpline::Ends::Periodic);
  return f;
}

bool TimeFunction::smooth() const {
  if (kind == Kind::Table) return interpolation == Interpolation::Spline || t.size() < 2;
  if (kind == Kind::Ramp) return slope == 0 || (start <= 0 && std::isinf(end));
  return true;
}

double TimeFunction::value(double time) const {
  switch (kind) {
    case Kind::Constant:
      return offset;
    case Kind::Sine:
      return offset + amplitude * std::sin(2 * kPi * frequency * time + phase);
    case Kind::Table: {
      if (t.size() == 1) return v.front();
      if (interpolation == Interpolation::Spline) return spline->value(time);
      if (time <= t.front()) return v.front();
      if (time >= t.back()) return v.back();
      std::size_t k = segment(t, time);
      double s = (time - t[k]) / (t[k + 1] - t[k]);
      return v[k] + s * (v[k + 1] - v[k]);
    }
    case Kind::Ramp:
      return offset + slope * (std::clamp(time, start, end) - start);
    case Kind::Step:
      return offset + amplitude * smooth0(std::clamp((time - start) / rise, 0.0, 1.0));
    case Kind::Chirp:
      return offset + amplitude * std::sin(chirp_phase(*this, time).p);
    case Kind::SumOfSines: {
      double s = offset;
      for (std::size_t i = 0; i < amplitudes.size(); ++i)
        s += amplitudes[i] * std::sin(2 * kPi * frequencies[i] * time + phases[i]);
      return s;
    }
    case Kind::Polynomial: {
      double s = 0;  // Horner
      for (std::size_t i = coefficients.size(); i-- > 0;) s = s * (time - t0) + coefficients[i];
      return s;
    }
    case Kind::Road:
      return offset + spline->value(time - road_profile.delay);
  }
  return 0.0;
}

double TimeFunction::d1(double time) const {
  switch (kind) {
    case Kind::Constant:
      return 0.0;
    case Kind::Sine: {
      double w = 2 * kPi * frequency;
      return amplitude * w * std::cos(w * time + phase);
    }
    case Kind::Table: {
      if (t.size() == 1) return 0.0;
      if (interpolation == Interpolation::Spline) return spline->slope(time);
      if (time < t.front() || time >= t.back()) return 0.0;
      std::size_t k = segment(t, time);
      return (v[k + 1] - v[k]) / (t[k + 1] - t[k]);
    }
    case Kind::Ramp:
      return time >= start && time < end ? slope : 0.0;
    case Kind::Step: {
      const double u = (time - start) / rise;
      return u > 0 && u < 1 ? amplitude * smooth1(u) / rise : 0.0;
    }
    case Kind::Chirp: {
      const Phase p = chirp_phase(*this, time);
      return amplitude * std::cos(p.p) * p.w;
    }
    case Kind::SumOfSines: {
      double s = 0;
      for (std::size_t i = 0; i < amplitudes.size(); ++i) {
        const double w = 2 * kPi * frequencies[i];
        s += amplitudes[i] * w * std::cos(w * time + phases[i]);
      }
      return s;
    }
    case Kind::Polynomial: {
      double s = 0;
      for (std::size_t i = coefficients.size(); i-- > 1;) s = s * (time - t0) + static_cast<double>(i) * coefficients[i];
      return s;
    }
    case Kind::Road:
      return spline->slope(time - road_profile.delay);
  }
  return 0.0;
}

double TimeFunction::d2(double time) const {
  switch (kind) {
    case Kind::Constant:
    case Kind::Ramp:
      return 0.0;
    case Kind::Sine: {
      double w = 2 * kPi * frequency;
      return -amplitude * w * w * std::sin(w * time + phase);
    }
    case Kind::Table:
      return t.size() >= 2 && interpolation == Interpolation::Spline ? spline->curvature(time) : 0.0;
    case Kind::Step: {
      const double u = (time - start) / rise;
      return u > 0 && u < 1 ? amplitude * smooth2(u) / (rise * rise) : 0.0;
    }
    case Kind::Chirp: {
      const Phase p = chirp_phase(*this, time);
      return amplitude * (-std::sin(p.p) * p.w * p.w + std::cos(p.p) * p.a);
    }
    case Kind::SumOfSines: {
      double s = 0;
      for (std::size_t i = 0; i < amplitudes.size(); ++i) {
        const double w = 2 * kPi * frequencies[i];
        s -= amplitudes[i] * w * w * std::sin(w * time + phases[i]);
      }
      return s;
    }
    case Kind::Polynomial: {
      double s = 0;
      for (std::size_t i = coefficients.size(); i-- > 2;)
        s = s * (time - t0) + static_cast<double>(i * (i - 1)) * coefficients[i];
      return s;
    }
    case Kind::Road:
      return spline->curvature(time - road_profile.delay);
  }
  return 0.0;
}

// ISO 8608 --------------------------------------------------------------------------------------

double iso8608_gd0(char road_class) {
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(road_class)));
  if (c < 'A' || c > 'H')
    throw InvalidArgument("ISO 8608 road", "class", fmt::format("expected a class A to H, got '{}'", road_class));
  return 16e-6 * std::pow(4.0, c - 'A');
}

double iso8608_psd(char road_class, double n) {
  if (!(n > 0) || !std::isfinite(n))
    throw InvalidArgument("ISO 8608 road", "n", fmt::format("must be > 0 (cycles/m), got {}", n));
  return iso8608_gd0(road_class) * std::pow(n / kIso8608N0, -2.0);
}

double iso8608_velocity_psd(char road_class, double speed) {
  if (!(speed >= 0) || !std::isfinite(speed))
    throw InvalidArgument("ISO 8608 road", "speed", fmt::format("must be >= 0 (m/s), got {}", speed));
  return 4 * kPi * kPi * kIso8608N0 * kIso8608N0 * iso8608_gd0(road_class) * speed;
}

double iso8608_variance(char road_class, double n_min, double n_max) {
  if (!(n_min > 0) || !(n_max >= n_min) || !std::isfinite(n_max))
    throw InvalidArgument("ISO 8608 road", "n_max",
                          fmt::format("expected 0 < n_min <= n_max (cycles/m), got {} and {}", n_min, n_max));
  return iso8608_gd0(road_class) * kIso8608N0 * kIso8608N0 * (1 / n_min - 1 / n_max);
}

}  // namespace inerta::mbs
