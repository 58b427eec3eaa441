// Time functions (mbs/time_function.hpp): exact derivatives of every kind (against central
// differences), the spline table's end conditions and convergence, the smoothstep's ends, the
// chirp's phase, and the ISO 8608 road generator's variance and spectrum (mbs/road.hpp).
#include "inerta/mbs/time_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/numerics/signal.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_time_function {

namespace {

using inerta::mbs::TimeFunction;
using TF = TimeFunction;
constexpr double kPi = std::numbers::pi;

// f′ and f″ against central differences of f and f′ (step h), relative to the scale of each.
void expect_derivatives(const TF& f, double t, double h = 1e-5, double tol = 1e-6) {
  const double d1 = (f.value(t + h) - f.value(t - h)) / (2 * h);
  const double d2 = (f.d1(t + h) - f.d1(t - h)) / (2 * h);
  EXPECT_NEAR(f.d1(t), d1, tol * (1 + std::abs(d1))) << "f' at t = " << t;
  EXPECT_NEAR(f.d2(t), d2, tol * (1 + std::abs(d2))) << "f'' at t = " << t;
}

TEST(TimeFunction, EveryKindHasExactDerivatives) {
  const std::vector<TF> fs = {
      TF::sine(0.3, 2.5, 0.4, 1),
      TF::table({0, 0.5, 1.2, 2, 3}, {0, 0.2, -0.1, 0.4, 0.4}),
      TF::ramp(2.0, -1.0, 0.5),
      TF::step(0.2, 0.8, 0.3, 0.1),
      TF::chirp(0.1, 1, 5, 2),
      TF::chirp(0.1, 1, 5, 2, TF::Sweep::Logarithmic),
      TF::sum_of_sines({0.1, 0.05, 0.02}, {0.5, 3, 7}, {0, 1, 2}, 0.3),
      TF::polynomial({1, -2, 0.5, 0.25}, 0.7),
  };
  for (const TF& f : fs)
    for (double t : {0.05, 0.37, 0.81, 1.13, 1.77, 2.6, 3.4}) expect_derivatives(f, t);
}

TEST(TimeFunction, SplineTableInterpolatesWithNaturalEndsAndLinearContinuation) {
  const std::vector<double> t{0, 0.5, 1.2, 2, 3}, v{0, 0.2, -0.1, 0.4, 0.1};
  const TF f = TF::table(t, v);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(f.value(t[k]), v[k], 1e-14);
  EXPECT_NEAR(f.d2(0), 0, 1e-12);  // natural ends
  EXPECT_NEAR(f.d2(3), 0, 1e-12);
  // Outside: the straight line with the end value and slope (C² at the ends).
  EXPECT_NEAR(f.value(-1), v[0] - f.d1(0), 1e-12);
  EXPECT_NEAR(f.value(4), v[4] + f.d1(3), 1e-12);
  EXPECT_EQ(f.d2(-1), 0.0);
  // C² at an interior knot: f″ from both sides agree.
  EXPECT_NEAR(f.d2(1.2 - 1e-9), f.d2(1.2 + 1e-9), 1e-6);
  EXPECT_TRUE(f.smooth());
}

TEST(TimeFunction, SplineTableOfLinearDataIsExactlyLinear) {
  // A constant-speed crank: θ = ω t from t = 0, with f′ = ω already at the first point.
  const double w = 3.0;
  const TF f = TF::table({0, 1, 2, 5}, {0, w, 2 * w, 5 * w});
  for (double t : {0.0, 0.3, 1.7, 4.9, 6.0}) {
    EXPECT_NEAR(f.value(t), w * t, 1e-12);
    EXPECT_NEAR(f.d1(t), w, 1e-12);
    EXPECT_NEAR(f.d2(t), 0, 1e-12);
  }
}

TEST(TimeFunction, SplineTableConvergesAtFourthOrder) {
  // Interior error of the interpolant of sin(t) on [0, 2π]: O(h⁴) (×1/16 per halving).
  auto err = [](int n) {
    std::vector<double> t, v;
    for (int i = 0; i <= n; ++i) t.push_back(2 * kPi * i / n), v.push_back(std::sin(t.back()));
    const TF f = TF::table(t, v);
    double e = 0;
    for (double s = 2.0; s <= 4.3; s += 0.01) e = std::max(e, std::abs(f.value(s) - std::sin(s)));
    return e;
  };
  const double r = err(40) / err(80);
  EXPECT_GT(r, 12.0);
  EXPECT_LT(r, 20.0);
}

TEST(TimeFunction, LinearTableIsHeldOutsideAndHasCorners) {
  const TF f = TF::table({0, 1, 2}, {0, 1, 1}, TF::Interpolation::Linear);
  EXPECT_DOUBLE_EQ(f.value(0.5), 0.5);
  EXPECT_DOUBLE_EQ(f.d1(0.0), 1.0);  // the slope after the first point
  EXPECT_DOUBLE_EQ(f.d1(-0.1), 0.0);
  EXPECT_DOUBLE_EQ(f.value(3), 1.0);
  EXPECT_DOUBLE_EQ(f.d2(0.5), 0.0);
  EXPECT_FALSE(f.smooth());
  EXPECT_TRUE(TF::table({0}, {2}, TF::Interpolation::Linear).smooth());
}

TEST(TimeFunction, RampHasCornersAtStartAndEnd) {
  const TF f = TF::ramp(2, 1, 0.5, 3);
  EXPECT_DOUBLE_EQ(f.value(0), 0.5);
  EXPECT_DOUBLE_EQ(f.value(2), 2.5);
  EXPECT_DOUBLE_EQ(f.value(10), 4.5);
  EXPECT_DOUBLE_EQ(f.d1(1), 2);
  EXPECT_DOUBLE_EQ(f.d1(3), 0);
  EXPECT_FALSE(f.smooth());
  EXPECT_TRUE(TF::ramp(2).smooth());  // from t = 0, no end: no corner in a run
}

TEST(TimeFunction, StepIsQuinticSmoothstep) {
  const double h = 0.2, rise = 0.8, t0 = 0.3, off = 0.1;
  const TF f = TF::step(h, rise, t0, off);
  EXPECT_DOUBLE_EQ(f.value(0), off);
  EXPECT_DOUBLE_EQ(f.value(t0 + rise + 1), off + h);
  EXPECT_NEAR(f.value(t0 + rise / 2), off + h / 2, 1e-15);  // symmetric
  // f′ and f″ vanish at both ends of the rise (C²); the peak speed is 15/8 h/rise at mid-rise.
  for (double t : {t0, t0 + rise}) {
    EXPECT_NEAR(f.d1(t), 0, 1e-15);
    EXPECT_NEAR(f.d2(t), 0, 1e-12);
  }
  EXPECT_NEAR(f.d1(t0 + rise / 2), 15.0 / 8 * h / rise, 1e-12);
}

TEST(TimeFunction, ChirpPhaseAndFrequencies) {
  const double A = 0.1, f0 = 1, f1 = 5, T = 2;
  const TF lin = TF::chirp(A, f0, f1, T);
  // φ(T) = 2π (f0 + f1)/2 · T; the instantaneous frequency φ′/2π: f0 at 0, f1 at T.
  const double phiT = 2 * kPi * (f0 + f1) / 2 * T;
  EXPECT_NEAR(lin.value(T), A * std::sin(phiT), 1e-12);
  EXPECT_NEAR(lin.d1(0), A * 2 * kPi * f0, 1e-12);
  EXPECT_NEAR(lin.d1(T), A * std::cos(phiT) * 2 * kPi * f1, 1e-10);
  // After the sweep it stays at f1: f(T + 1/f1) = f(T).
  EXPECT_NEAR(lin.value(T + 1 / f1), lin.value(T), 1e-12);
  // Logarithmic: φ(T) = 2π f0 T (k − 1)/ln k, k = f1/f0.
  const TF lg = TF::chirp(A, f0, f1, T, TF::Sweep::Logarithmic);
  const double k = f1 / f0;
  EXPECT_NEAR(lg.value(T), A * std::sin(2 * kPi * f0 * T * (k - 1) / std::log(k)), 1e-12);
  EXPECT_NEAR(lg.d1(T), A * std::cos(2 * kPi * f0 * T * (k - 1) / std::log(k)) * 2 * kPi * f1, 1e-9);
}

TEST(TimeFunction, PolynomialAboutT0) {
  const TF p = TF::polynomial({1, -2, 0.5}, 2);  // 1 − 2 (t − 2) + 0.5 (t − 2)²
  EXPECT_DOUBLE_EQ(p.value(4), 1 - 4 + 2);
  EXPECT_DOUBLE_EQ(p.d1(4), -2 + 2);
  EXPECT_DOUBLE_EQ(p.d2(4), 1);
}

TEST(TimeFunction, FactoriesNameTheParameter) {
  auto param = [](auto make) -> std::string {
    try {
      make();
    } catch (const inerta::InvalidArgument& e) {
      return e.parameter();
    }
    return "(no error)";
  };
  EXPECT_EQ(param([] { TF::ramp(1, 2, 0, 1); }), "end");
  EXPECT_EQ(param([] { TF::step(1, 0); }), "rise");
  EXPECT_EQ(param([] { TF::chirp(1, 0, 5, 1, TF::Sweep::Logarithmic); }), "f0");
  EXPECT_EQ(param([] { TF::chirp(1, 1, 5, -1); }), "duration");
  EXPECT_EQ(param([] { TF::sum_of_sines({1, 2}, {1}); }), "frequencies");
  EXPECT_EQ(param([] { TF::sum_of_sines({1}, {1}, {0, 1}); }), "phases");
  EXPECT_EQ(param([] { TF::sum_of_sines({1}, {-1}); }), "frequencies[0]");
  EXPECT_EQ(param([] { TF::polynomial({}); }), "coefficients");
  inerta::mbs::RoadProfile r;
  r.speed = 10, r.length = 100;
  r.road_class = 'J';
  EXPECT_EQ(param([&] { TF::road(r); }), "class");
  r.road_class = 'C', r.speed = 0;
  EXPECT_EQ(param([&] { TF::road(r); }), "speed");
  r.speed = 10, r.length = 50;  // < 1/n_min = 90.9 m
  EXPECT_EQ(param([&] { TF::road(r); }), "length");
  r.length = 100, r.n_max = 0.01;
  EXPECT_EQ(param([&] { TF::road(r); }), "n_max");
  // A hand-made spline table without its spline is refused (elements validate what they take).
  TF hand;
  hand.kind = TF::Kind::Table, hand.t = {0, 1}, hand.v = {0, 1};
  EXPECT_EQ(param([&] { hand.validate(); }), "points");
}

// ISO 8608 ------------------------------------------------------------------------------------

TEST(Road, ClassTable) {
  using inerta::mbs::iso8608_gd0;
  EXPECT_DOUBLE_EQ(iso8608_gd0('A'), 16e-6);
  EXPECT_DOUBLE_EQ(iso8608_gd0('B'), 64e-6);
  EXPECT_DOUBLE_EQ(iso8608_gd0('c'), 256e-6);
  EXPECT_DOUBLE_EQ(iso8608_gd0('H'), 16e-6 * std::pow(4, 7));
  EXPECT_THROW(iso8608_gd0('I'), inerta::InvalidArgument);
  // G_d(n) ∝ n^-2 through G_d(n0) at n0 = 0.1 cycles/m; the white velocity PSD 4π² n0² G_d0 v.
  EXPECT_DOUBLE_EQ(inerta::mbs::iso8608_psd('C', 0.2), 256e-6 / 4);
  EXPECT_NEAR(inerta::mbs::iso8608_velocity_psd('C', 20), 4 * kPi * kPi * 0.01 * 256e-6 * 20, 1e-15);
}

// Samples of a road function at spacing dt over its whole period.
std::vector<double> samples(const TF& f, double dt, double T) {
  std::vector<double> y;
  for (double t = 0; t < T - 1e-9; t += dt) y.push_back(f.value(t));
  return y;
}

TEST(Road, VarianceIsTheIntegralOfThePsdOverTheBand) {
  inerta::mbs::RoadProfile r;
  r.road_class = 'C', r.speed = 20, r.n_min = 0.05, r.n_max = 2, r.length = 2000, r.seed = 7;
  const TF f = TF::road(r);
  const double T = r.length / r.speed;
  const std::vector<double> y = samples(f, 1 / (r.speed * 16 * r.n_max), T);
  double mean = 0, var = 0;
  for (double v : y) mean += v / static_cast<double>(y.size());
  for (double v : y) var += (v - mean) * (v - mean) / static_cast<double>(y.size());
  // Over one period the variance is Σ G_d(n_k) Δn exactly (random phases, deterministic
  // amplitudes); that sum approximates ∫ G_d dn to O(Δn / n_min) = O(1/(n_min L)) = 1 %.
  const double expected = inerta::mbs::iso8608_variance('C', r.n_min, r.n_max);
  EXPECT_NEAR(var / expected, 1.0, 0.015);
  EXPECT_NEAR(mean, 0.0, 1e-12);
}

TEST(Road, SpectrumFollowsTheClassPsd) {
  inerta::mbs::RoadProfile r;
  r.road_class = 'D', r.speed = 10, r.n_min = 0.05, r.n_max = 3, r.length = 4000, r.seed = 3;
  const TF f = TF::road(r);
  const double fs = 100;  // Hz; the band in time is v·n = 0.5–30 Hz
  const std::vector<double> y = samples(f, 1 / fs, r.length / r.speed);
  inerta::numerics::WelchOptions o;
  o.segment = 4096;  // Δf = 0.024 Hz
  const auto S = inerta::numerics::welch(y, fs, o);
  // G_z(f) = G_d(f/v)/v; compare band averages (each over many Welch bins) within ±15 %.
  for (double fc : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    const double lo = fc / 1.2, hi = fc * 1.2;
    const double measured = S.integral(lo, hi);
    const double exact = inerta::mbs::iso8608_gd0('D') * 0.01 * r.speed * (1 / lo - 1 / hi);  // ∫ G_d(f/v)/v df
    EXPECT_NEAR(measured / exact, 1.0, 0.15) << "band around " << fc << " Hz";
  }
}

TEST(Road, SeedDelayAndSmoothness) {
  inerta::mbs::RoadProfile r;
  r.road_class = 'B', r.speed = 15, r.length = 300, r.seed = 11;
  const TF a = TF::road(r), b = TF::road(r);
  r.seed = 12;
  const TF c = TF::road(r);
  r.seed = 11, r.delay = 0.25;
  const TF d = TF::road(r);
  double diff = 0;
  for (double t : {0.1, 1.3, 7.7}) {
    EXPECT_EQ(a.value(t), b.value(t));                 // reproducible
    EXPECT_NEAR(d.value(t + 0.25), a.value(t), 1e-12);  // a second axle: the same road later
    diff += std::abs(c.value(t) - a.value(t));
    expect_derivatives(a, t, 1e-6, 1e-5);
  }
  EXPECT_GT(diff, 0);
  // Periodic: the profile repeats after its length (at t = length / speed), C² across the seam.
  const double T = r.length / r.speed;
  EXPECT_NEAR(a.value(T + 0.3), a.value(0.3), 1e-12);
  EXPECT_NEAR(a.d2(T - 1e-9), a.d2(T + 1e-9), 1e-5 * (1 + std::abs(a.d2(T))));
}

}  // namespace
}  // namespace test_mbs_time_function
