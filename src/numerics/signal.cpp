#include "inerta/numerics/signal.hpp"

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "inerta/error.hpp"

namespace inerta::numerics {

namespace {
using std::numbers::pi;

void check_finite(const std::vector<double>& x, const char* what) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) throw InvalidArgument(fmt::format("{}: sample {} is not a finite number ({})", what, i, x[i]));
}

void check_rate(double fs, const char* what) {
  if (!(fs > 0) || !std::isfinite(fs))
    throw InvalidArgument(fmt::format("{}: sample rate must be > 0 (Hz), got {}", what, fs));
}

/// Steady-state section states for a unit step at the cascade's input (z1, z2 of each section).
std::vector<std::array<double, 2>> step_states(const SosFilter& f) {
  std::vector<std::array<double, 2>> zi;
  double gain_in = 1;  // steady-state input of the section for a unit step at the cascade's input
  for (const Biquad& s : f.sections) {
    const double g = (s.b0 + s.b1 + s.b2) / (1 + s.a1 + s.a2);
    // y = g u in steady state: z1 = y − b0 u, z2 = b2 u − a2 y.
    zi.push_back({gain_in * (g - s.b0), gain_in * (s.b2 - s.a2 * g)});
    gain_in *= g;
  }
  return zi;
}

/// Runs the cascade in place over x with the given initial states.
void run(const SosFilter& f, std::vector<double>& x, std::vector<std::array<double, 2>> z) {
  for (std::size_t k = 0; k < f.sections.size(); ++k) {
    const Biquad& s = f.sections[k];
    double z1 = z[k][0], z2 = z[k][1];
    for (double& v : x) {
      const double u = v, y = s.b0 * u + z1;
      z1 = s.b1 * u - s.a1 * y + z2;
      z2 = s.b2 * u - s.a2 * y;
      v = y;
    }
  }
}
}  // namespace

double SosFilter::magnitude(double f, double* phase) const {
  const double w = 2 * pi * f / sample_rate;
  const std::complex<double> z1 = std::polar(1.0, -w), z2 = z1 * z1;
  std::complex<double> H = 1;
  for (const Biquad& s : sections) H *= (s.b0 + s.b1 * z1 + s.b2 * z2) / (1.0 + s.a1 * z1 + s.a2 * z2);
  if (phase) *phase = std::arg(H);
  return std::abs(H);
}

double SosFilter::dc_gain() const {
  double g = 1;
  for (const Biquad& s : sections) g *= (s.b0 + s.b1 + s.b2) / (1 + s.a1 + s.a2);
  return g;
}

SosFilter butterworth_lowpass(double fc, double fs, int order) {
  const char* what = "Butterworth low-pass";
  check_rate(fs, what);
  if (order < 1 || order > 20)
    throw InvalidArgument(fmt::format("{}: order must be between 1 and 20, got {}", what, order));
  if (!(fc > 0) || !std::isfinite(fc))
    throw InvalidArgument(fmt::format("{}: cutoff must be > 0 (Hz), got {}", what, fc));
  if (!(fc < fs / 2))
    throw InvalidArgument(fmt::format(
        "{}: cutoff {} Hz must be below the Nyquist frequency f_s/2 = {} Hz (sample rate {} Hz, step {} s)", what,
        fc, fs / 2, fs, 1 / fs));
  SosFilter f;
  f.sample_rate = fs, f.order = order;
  const double W = std::tan(pi * fc / fs), W2 = W * W;
  for (int k = 1; k <= order / 2; ++k) {
    const double a = 2 * std::sin(pi * (2 * k - 1) / (2.0 * order));
    const double d0 = 1 + a * W + W2, a1 = 2 * (W2 - 1) / d0, a2 = (1 - a * W + W2) / d0;
    // b0 = W²/d0 = (1 + a1 + a2)/4 algebraically; taken from the rounded a1, a2 so that the DC gain
    // is 1 to rounding (1 + a1 + a2 is small at low f_c/f_s and would otherwise lose digits).
    const double b0 = (1 + a1 + a2) / 4;
    f.sections.push_back({b0, 2 * b0, b0, a1, a2});
  }
  if (order % 2) {
    const double a1 = (W - 1) / (W + 1), b0 = (1 + a1) / 2;  // = W/(1 + W)
    f.sections.push_back({b0, b0, 0, a1, 0});
  }
  return f;
}

std::vector<double> filter(const SosFilter& f, const std::vector<double>& x) {
  std::vector<double> y = x;
  run(f, y, std::vector<std::array<double, 2>>(f.sections.size(), {0, 0}));
  return y;
}

std::size_t filtfilt_padding(const SosFilter& f) { return 3 * static_cast<std::size_t>(f.order + 1); }

std::vector<double> filtfilt(const SosFilter& f, const std::vector<double>& x) {
  const std::size_t n = x.size(), pad = filtfilt_padding(f);
  if (n <= pad)
    throw InvalidArgument(fmt::format(
        "zero-phase filter: an order-{} filter needs more than {} samples (3(order + 1), the end extension), got {}",
        f.order, pad, n));
  check_finite(x, "zero-phase filter");
  // The filtering is linear and a constant m passes with the gain g² (g = dc_gain(), 1 for a
  // low-pass): filtfilt(x) = g² m + filtfilt(x − m). Filtering the deviations from the mean keeps the
  // rounding of the recursion (amplified ~1/(1 + a1 + a2) at a low f_c/f_s) relative to the
  // fluctuation, not to the mean level; a constant passes to the last bit.
  double m = 0;
  for (double v : x) m += v;
  m /= static_cast<double>(n);
  // Odd reflection about both end samples.
  std::vector<double> e;
  e.reserve(n + 2 * pad);
  for (std::size_t i = pad; i >= 1; --i) e.push_back(2 * (x.front() - m) - (x[i] - m));
  for (double v : x) e.push_back(v - m);
  for (std::size_t i = 1; i <= pad; ++i) e.push_back(2 * (x.back() - m) - (x[n - 1 - i] - m));
  const auto zi = step_states(f);
  auto scaled = [&](double v) {
    auto z = zi;
    for (auto& s : z) s[0] *= v, s[1] *= v;
    return z;
  };
  run(f, e, scaled(e.front()));
  std::reverse(e.begin(), e.end());
  run(f, e, scaled(e.front()));
  std::reverse(e.begin(), e.end());
  const double g = f.dc_gain(), level = g * g * m;
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = level + e[pad + i];
  return y;
}

double uniform_sample_rate(const std::vector<double>& t, double rel_tol) {
  const char* what = "sampling";
  if (t.size() < 2) throw InvalidArgument(fmt::format("{}: needs at least 2 times, got {}", what, t.size()));
  check_finite(t, what);
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0))
    throw InvalidArgument(fmt::format("{}: times must increase (t from {} to {} s)", what, t.front(), t.back()));
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double h = t[i] - t[i - 1];
    if (std::abs(h - dt) > rel_tol * dt)
      throw InvalidArgument(fmt::format(
          "{}: not uniform: step {} from t = {:.9g} s to t = {:.9g} s is {:.9g} s, the mean step is {:.9g} s (tolerance {:g} relative)",
          what, i, t[i - 1], t[i], h, dt, rel_tol));
  }
  return 1 / dt;
}

double Spectrum::integral() const {
  double s = 0;
  for (double v : S) s += v;
  return s * resolution;
}

double Spectrum::integral(double lo, double hi) const {
  double s = 0;
  for (std::size_t k = 0; k < S.size(); ++k)
    if (f[k] >= lo && f[k] <= hi) s += S[k];
  return s * resolution;
}

Spectrum welch(const std::vector<double>& x, double fs, const WelchOptions& o) {
  const char* what = "power spectral density";
  check_rate(fs, what);
  const std::size_t n = x.size();
  if (n < 4) throw InvalidArgument(fmt::format("{}: needs at least 4 samples, got {}", what, n));
  check_finite(x, what);
  if (!(o.overlap >= 0 && o.overlap < 1))
    throw InvalidArgument(fmt::format("{}: overlap must be in [0, 1), got {}", what, o.overlap));
  std::size_t L = o.segment;
  if (L == 0) {
    L = 1;
    while (2 * L <= n / 4) L *= 2;
    if (L < 16) L = n;
  }
  if (L < 4 || L > n)
    throw InvalidArgument(fmt::format("{}: segment of {} samples must be between 4 and the record's {}", what, L, n));
  const std::size_t step = std::max<std::size_t>(1, L - static_cast<std::size_t>(std::llround(o.overlap * static_cast<double>(L))));
  std::vector<double> w(L, 1.0);
  if (o.window == Window::Hann)
    for (std::size_t i = 0; i < L; ++i) w[i] = std::pow(std::sin(pi * static_cast<double>(i) / static_cast<double>(L)), 2);
  double w2 = 0;
  for (double v : w) w2 += v * v;

  Spectrum r;
  const std::size_t nf = L / 2 + 1;
  r.resolution = fs / static_cast<double>(L);
  r.f.resize(nf), r.S.assign(nf, 0.0);
  for (std::size_t k = 0; k < nf; ++k) r.f[k] = static_cast<double>(k) * r.resolution;
  Eigen::FFT<double> fft;
  std::vector<double> seg(L);
  std::vector<std::complex<double>> X;
  for (std::size_t start = 0; start + L <= n; start += step) {
    double mean = 0;
    for (std::size_t i = 0; i < L; ++i) mean += x[start + i];
    mean /= static_cast<double>(L);
    for (std::size_t i = 0; i < L; ++i) seg[i] = (x[start + i] - mean) * w[i];
    fft.fwd(X, seg);
    for (std::size_t k = 0; k < nf; ++k) r.S[k] += std::norm(X[k]);
    ++r.segments;
  }
  const double scale = 1 / (fs * w2 * r.segments);
  for (std::size_t k = 0; k < nf; ++k) r.S[k] *= (k == 0 || 2 * k == L ? 1.0 : 2.0) * scale;
  return r;
}

Spectrum periodogram(const std::vector<double>& x, double fs, Window window) {
  return welch(x, fs, {.segment = x.size(), .overlap = 0, .window = window});
}

}  // namespace inerta::numerics
