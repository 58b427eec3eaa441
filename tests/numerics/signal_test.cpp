// Butterworth low-pass, zero-phase filtering and PSDs (numerics/signal.hpp) against closed forms.
#include "inerta/numerics/signal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "inerta/error.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_signal {

using namespace inerta::numerics;
using std::numbers::pi;

namespace {
/// The analog Butterworth magnitude at the pre-warped frequency (f_s/π)·tan(πf/f_s).
double prewarped_analog(double f, double fc, double fs, int n) {
  const double fa = fs / pi * std::tan(pi * f / fs), fac = fs / pi * std::tan(pi * fc / fs);
  return 1 / std::sqrt(1 + std::pow(fa / fac, 2 * n));
}
std::vector<double> sine(double A, double f, double fs, std::size_t n, double phase = 0, double offset = 0) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = offset + A * std::sin(2 * pi * f * static_cast<double>(i) / fs + phase);
  return x;
}
/// Amplitude of the component at f (least squares on sin and cos) over samples [from, to).
double amplitude(const std::vector<double>& x, double f, double fs, std::size_t from, std::size_t to) {
  double ss = 0, sc = 0, cc = 0, xs = 0, xc = 0;
  for (std::size_t i = from; i < to; ++i) {
    const double s = std::sin(2 * pi * f * static_cast<double>(i) / fs), c = std::cos(2 * pi * f * static_cast<double>(i) / fs);
    ss += s * s, sc += s * c, cc += c * c, xs += x[i] * s, xc += x[i] * c;
  }
  const double det = ss * cc - sc * sc, a = (xs * cc - xc * sc) / det, b = (xc * ss - xs * sc) / det;
  return std::hypot(a, b);
}
/// The deterministic test signal of the SciPy comparisons below.
std::vector<double> mixed(std::size_t n, double fs) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    x[i] = std::sin(2 * pi * 3 * t) + 0.5 * std::sin(2 * pi * 60 * t) + 0.2 * std::cos(2 * pi * 130 * t + 0.3) +
           0.01 * static_cast<double>(i) + 1.0;
  }
  return x;
}
}  // namespace

TEST(Butterworth, UnitDcGainAndTheCutoffAtMinus3dB) {
  for (int n : {1, 2, 3, 4, 5, 8}) {
    const SosFilter f = butterworth_lowpass(20, 1000, n);
    EXPECT_EQ(f.order, n);
    EXPECT_EQ(f.sections.size(), static_cast<std::size_t>((n + 1) / 2));
    EXPECT_NEAR(f.dc_gain(), 1, 1e-12) << n;
    EXPECT_NEAR(f.magnitude(0), 1, 1e-12) << n;
    EXPECT_NEAR(f.magnitude(20), 1 / std::sqrt(2.0), 1e-12) << n;
    EXPECT_NEAR(f.magnitude(500), 0, 1e-9) << n;  // zeros at z = −1
  }
}

TEST(Butterworth, DigitalResponseIsTheAnalogOneAtThePrewarpedFrequency) {
  for (int n : {1, 2, 4, 5, 7})
    for (double fs : {200.0, 1000.0, 5000.0})
      for (double fc : {5.0, 20.0, 0.3 * fs})
        for (double r : {0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
          const double f = r * fs / 2;
          EXPECT_NEAR(butterworth_lowpass(fc, fs, n).magnitude(f), prewarped_analog(f, fc, fs, n), 1e-9)
              << "n " << n << " fs " << fs << " fc " << fc << " f " << f;
        }
}

TEST(Butterworth, SectionsMatchSciPy) {
  // scipy.signal.butter(4, 20, fs=1000, output='sos') (SciPy 1.10): the same poles, the gain put in
  // the first section; ours are each of unit DC gain, so compare the denominators and the product.
  const SosFilter f = butterworth_lowpass(20, 1000, 4);
  ASSERT_EQ(f.sections.size(), 2u);
  // Our k = 1 pair (a = 2 sin(π/8), the lighter damped) is SciPy's second row, and vice versa.
  EXPECT_NEAR(f.sections[0].a1, -1.89341560e+00, 1e-8);
  EXPECT_NEAR(f.sections[0].a2, 9.08464413e-01, 1e-8);
  EXPECT_NEAR(f.sections[1].a1, -1.77831349e+00, 1e-8);
  EXPECT_NEAR(f.sections[1].a2, 7.92447472e-01, 1e-8);
  EXPECT_NEAR(f.sections[0].b0 * f.sections[1].b0, 1.32937289e-05, 1e-13);
}

TEST(Butterworth, RefusesBadDesigns) {
  EXPECT_THROW(butterworth_lowpass(20, 40), inerta::InvalidArgument);  // at Nyquist
  EXPECT_THROW(butterworth_lowpass(30, 40), inerta::InvalidArgument);
  EXPECT_THROW(butterworth_lowpass(0, 1000), inerta::InvalidArgument);
  EXPECT_THROW(butterworth_lowpass(-5, 1000), inerta::InvalidArgument);
  EXPECT_THROW(butterworth_lowpass(20, 0), inerta::InvalidArgument);
  EXPECT_THROW(butterworth_lowpass(NAN, 1000), inerta::InvalidArgument);
  EXPECT_THROW(butterworth_lowpass(20, 1000, 0), inerta::InvalidArgument);
  try {
    butterworth_lowpass(20, 30);
    FAIL();
  } catch (const inerta::InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("Nyquist frequency f_s/2 = 15 Hz"), std::string::npos) << e.what();
  }
}

TEST(Filtfilt, KeepsAConstantExactlyWithNoEndTransients) {
  for (int n : {1, 2, 4, 5})
    for (double fs : {200.0, 1000.0, 10000.0}) {
      const SosFilter f = butterworth_lowpass(20, fs, n);
      const std::vector<double> x(200, 73.25);
      const auto y = filtfilt(f, x);
      ASSERT_EQ(y.size(), x.size());
      for (double v : y) EXPECT_NEAR(v, 73.25, 1e-12) << n << " " << fs;
    }
  // A ramp keeps its value away from the ends — zero phase, no lag (a causal pass lags it by its
  // group delay). At the ends the step initial state does not match a ramp: a small transient.
  std::vector<double> ramp(2000);
  for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = 2 + 0.5 * static_cast<double>(i) / 1000;
  const auto y = filtfilt(butterworth_lowpass(20, 1000), ramp);
  for (std::size_t i = 600; i < 1400; ++i) EXPECT_NEAR(y[i], ramp[i], 1e-9) << i;
  const auto causal = filter(butterworth_lowpass(20, 1000), ramp);
  EXPECT_GT(ramp[1000] - causal[1000], 1e-4);
}

TEST(Filtfilt, SinesKeepTheSquaredMagnitudeAndNoPhase) {
  const double fs = 1000;
  const SosFilter f = butterworth_lowpass(20, fs, 4);
  const std::size_t n = 4000, from = 1000, to = 3000;  // away from the ends
  for (double fsig : {5.0, 20.0, 100.0}) {
    const double A = 3;
    const auto x = sine(A, fsig, fs, n, 0.4);
    const auto y = filtfilt(f, x);
    const double H = f.magnitude(fsig);
    EXPECT_NEAR(amplitude(y, fsig, fs, from, to) / A, H * H, 1e-6) << fsig;
    // Zero phase: the output is the input scaled.
    for (std::size_t i = from; i < to; i += 97) EXPECT_NEAR(y[i], H * H * x[i], 1e-6 * A) << fsig << " " << i;
  }
  EXPECT_NEAR(std::pow(f.magnitude(20), 2), 0.5, 1e-12);  // −6 dB at the cutoff
  EXPECT_LT(std::pow(f.magnitude(100), 2), 1e-5);           // (1/5)^8-ish
}

TEST(Filtfilt, MatchesSciPySosfiltfilt) {
  // scipy.signal.sosfiltfilt(butter(n, 20, fs=1000, output='sos'), x) with the default odd padding
  // of 3(n + 1) samples, SciPy 1.10.
  const auto x = mixed(500, 1000);
  const auto y = filtfilt(butterworth_lowpass(20, 1000, 4), x);
  EXPECT_NEAR(y[0], 1.1849034420624767, 1e-10);
  EXPECT_NEAR(y[1], 1.193690018609466, 1e-10);
  EXPECT_NEAR(y[100], 2.9516530837315513, 1e-10);
  EXPECT_NEAR(y[250], 2.4999999068079686, 1e-10);
  EXPECT_NEAR(y[498], 6.074902384999621, 1e-10);
  EXPECT_NEAR(y[499], 6.073344427577, 1e-10);
  const auto y5 = filtfilt(butterworth_lowpass(20, 1000, 5), x);
  EXPECT_NEAR(y5[0], 1.187565101684009, 1e-10);
  EXPECT_NEAR(y5[250], 2.500000456541297, 1e-10);
  EXPECT_NEAR(y5[499], 6.087052078035775, 1e-10);
}

TEST(Filtfilt, NeedsMoreSamplesThanItsPadding) {
  const SosFilter f = butterworth_lowpass(20, 1000, 4);
  EXPECT_EQ(filtfilt_padding(f), 15u);
  EXPECT_THROW(filtfilt(f, std::vector<double>(15, 1.0)), inerta::InvalidArgument);
  EXPECT_NO_THROW(filtfilt(f, std::vector<double>(16, 1.0)));
  try {
    filtfilt(f, std::vector<double>(10, 1.0));
    FAIL();
  } catch (const inerta::InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("needs more than 15 samples"), std::string::npos) << e.what();
  }
  std::vector<double> bad(100, 1.0);
  bad[40] = NAN;
  EXPECT_THROW(filtfilt(f, bad), inerta::InvalidArgument);
}

TEST(Filter, CausalStepResponseSettlesToTheDcGain) {
  const SosFilter f = butterworth_lowpass(20, 1000, 4);
  const auto y = filter(f, std::vector<double>(2000, 1.0));
  EXPECT_NEAR(y.front(), f.sections[0].b0 * f.sections[1].b0, 1e-15);
  EXPECT_NEAR(y.back(), 1, 1e-9);
}

TEST(Sampling, UniformRateAndRefusals) {
  std::vector<double> t;
  for (int i = 0; i < 1000; ++i) t.push_back(0.3 + i * 1e-3);
  EXPECT_NEAR(uniform_sample_rate(t), 1000, 1e-6);
  auto gap = t;
  gap.erase(gap.begin() + 500);
  EXPECT_THROW(uniform_sample_rate(gap), inerta::InvalidArgument);
  auto repeated = t;
  repeated.insert(repeated.begin() + 300, repeated[300]);
  EXPECT_THROW(uniform_sample_rate(repeated), inerta::InvalidArgument);
  EXPECT_THROW(uniform_sample_rate({1.0}), inerta::InvalidArgument);
  EXPECT_THROW(uniform_sample_rate({2.0, 1.0}), inerta::InvalidArgument);
}

TEST(Welch, ParsevalOnWhiteNoise) {
  // ∫ S df is the variance; for n samples of N(0, σ²) the sample variance has a relative standard
  // error sqrt(2/n) ≈ 0.7 % at n = 40 000 — the Hann weighting of the segments enlarges it a little.
  std::mt19937_64 rng(7);
  const double sigma = 2.5, fs = 500;
  std::normal_distribution<double> N(0, sigma);
  std::vector<double> x(40000);
  for (double& v : x) v = N(rng);
  const Spectrum s = welch(x, fs, {.segment = 512});
  EXPECT_EQ(s.f.size(), 257u);
  EXPECT_DOUBLE_EQ(s.resolution, fs / 512);
  EXPECT_EQ(s.segments, static_cast<int>((40000 - 512) / 256 + 1));
  EXPECT_NEAR(s.f.back(), fs / 2, 1e-12);
  EXPECT_NEAR(s.integral() / (sigma * sigma), 1, 0.03);
  // Flat at 2σ²/f_s: the band average is within its (small) statistical error.
  const double level = 2 * sigma * sigma / fs;
  EXPECT_NEAR(s.integral(50, 200) / 150 / level, 1, 0.03);
  double mean = 0;
  for (std::size_t k = 1; k + 1 < s.S.size(); ++k) mean += s.S[k];
  EXPECT_NEAR(mean / static_cast<double>(s.S.size() - 2) / level, 1, 0.03);
  // The periodogram integrates to the record's (biased) variance exactly.
  double m = 0, v = 0;
  for (double a : x) m += a;
  m /= static_cast<double>(x.size());
  for (double a : x) v += (a - m) * (a - m);
  v /= static_cast<double>(x.size());
  EXPECT_NEAR(periodogram(x, fs).integral(), v, 1e-9 * v);
}

TEST(Welch, SineGivesAPeakAtItsFrequencyWithPowerAHalfASquared) {
  const double fs = 1024, A = 4;
  for (double f0 : {64.0, 37.3}) {  // on a bin and between bins
    const auto x = sine(A, f0, fs, 16384, 0.2, 70.0);  // a mean, removed
    const Spectrum s = welch(x, fs, {.segment = 1024});
    std::size_t peak = 0;
    for (std::size_t k = 1; k < s.S.size(); ++k)
      if (s.S[k] > s.S[peak]) peak = k;
    EXPECT_NEAR(s.f[peak], f0, s.resolution / 2 + 1e-12) << f0;
    EXPECT_NEAR(s.integral(f0 - 4 * s.resolution, f0 + 4 * s.resolution) / (A * A / 2), 1, 2e-3) << f0;
    EXPECT_LT(s.S[0], 1e-3 * s.S[peak]) << f0;  // mean removed
  }
}

TEST(Welch, MatchesSciPyWelchAndPeriodogram) {
  // scipy.signal.welch(x, 1000, window='hann', nperseg=128, noverlap=64) (density, constant
  // detrend) and scipy.signal.periodogram(x, 1000), SciPy 1.10.
  const auto x = mixed(500, 1000);
  const Spectrum s = welch(x, 1000, {.segment = 128});
  EXPECT_EQ(s.segments, 6);
  EXPECT_NEAR(s.S[0] / 0.0007110405585984829, 1, 1e-10);
  EXPECT_NEAR(s.S[1] / 0.011869137252836642, 1, 1e-10);
  EXPECT_NEAR(s.S[3] / 3.349543995019807e-05, 1, 1e-10);
  EXPECT_NEAR(s.S[8] / 0.009352153267146335, 1, 1e-10);
  EXPECT_NEAR(s.S[64] / 1.5982998236406295e-14, 1, 1e-6);
  const Spectrum p = periodogram(x, 1000);
  EXPECT_NEAR(p.S[0], 0, 1e-20);
  EXPECT_NEAR(p.S[1] / 0.7753437797803787, 1, 1e-10);
  EXPECT_NEAR(p.S[2] / 0.2354945983526468, 1, 1e-10);
  EXPECT_NEAR(p.S[250] / 1.2594428233671905e-05, 1, 1e-8);
}

TEST(Welch, AutomaticSegmentAndRefusals) {
  std::vector<double> x(5000, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.1 * static_cast<double>(i));
  EXPECT_EQ(welch(x, 100).resolution, 100.0 / 1024);  // largest power of two ≤ 5000/4
  EXPECT_EQ(welch(std::vector<double>(40, 1.0), 100).segments, 1);  // too short: one segment
  EXPECT_THROW(welch({1, 2, 3}, 100), inerta::InvalidArgument);
  EXPECT_THROW(welch(x, 100, {.segment = 6000}), inerta::InvalidArgument);
  EXPECT_THROW(welch(x, 100, {.segment = 2}), inerta::InvalidArgument);
  EXPECT_THROW(welch(x, 100, {.segment = 256, .overlap = 1.0}), inerta::InvalidArgument);
  EXPECT_THROW(welch(x, -1), inerta::InvalidArgument);
}
}  // namespace test_numerics_signal
