#include "inerta/numerics/cubic_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "inerta/error.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_cubic_spline {

using inerta::numerics::CubicSpline;
using std::numbers::pi;

namespace {
CubicSpline sine_table(int n, CubicSpline::Ends ends) {
  std::vector<double> x, y;
  for (int i = 0; i <= n; ++i) x.push_back(2 * pi * i / n), y.push_back(i == n ? 0.0 : std::sin(2 * pi * i / n));
  return CubicSpline(x, y, ends);
}
}  // namespace

TEST(CubicSpline, InterpolatesAndIsC2AcrossKnots) {
  const CubicSpline s({0, 1, 2.5, 3, 5}, {1, -1, 2, 0.5, 0});
  const std::vector<double> x = {0, 1, 2.5, 3, 5}, y = {1, -1, 2, 0.5, 0};
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s.value(x[i]), y[i], 1e-12);
  for (double k : {1.0, 2.5, 3.0}) {
    const double e = 1e-7;
    EXPECT_NEAR(s.slope(k - e), s.slope(k + e), 1e-5);
    EXPECT_NEAR(s.curvature(k - e), s.curvature(k + e), 1e-5);
  }
  EXPECT_NEAR(s.curvature(0), 0, 1e-12);  // natural ends
  EXPECT_NEAR(s.curvature(5), 0, 1e-12);
  // Derivatives against central differences of the spline itself.
  for (double t : {0.3, 1.7, 2.8, 4.1}) {
    const double h = 1e-5;
    EXPECT_NEAR(s.slope(t), (s.value(t + h) - s.value(t - h)) / (2 * h), 1e-7);
    EXPECT_NEAR(s.curvature(t), (s.slope(t + h) - s.slope(t - h)) / (2 * h), 1e-6);
  }
}

TEST(CubicSpline, ReproducesStraightLinesAndExtrapolatesThemLinearly) {
  const CubicSpline s({0, 1, 3}, {2, 3, 5});
  EXPECT_NEAR(s.value(2), 4, 1e-12);
  EXPECT_NEAR(s.value(-1), 1, 1e-12);
  EXPECT_NEAR(s.value(4), 6, 1e-12);
  EXPECT_NEAR(s.mean(), 3.5, 1e-12);
}

TEST(CubicSpline, PeriodicSineConvergesAtFourthOrderAndWraps) {
  double previous = 0;
  for (int n : {16, 32, 64}) {
    const CubicSpline s = sine_table(n, CubicSpline::Ends::Periodic);
    double err = 0;
    for (int k = 0; k < 1000; ++k) {
      const double t = 2 * pi * (k + 0.37) / 1000;
      err = std::max(err, std::abs(s.value(t) - std::sin(t)));
    }
    if (previous > 0) {
      EXPECT_NEAR(std::log2(previous / err), 4.0, 0.3) << "n = " << n;
    }
    previous = err;
    EXPECT_NEAR(s.value(1.0 + 6 * pi), s.value(1.0), 1e-12);  // wraps
    EXPECT_NEAR(s.value(1.0 - 2 * pi), s.value(1.0), 1e-12);
    EXPECT_NEAR(s.slope(0), s.slope(2 * pi), 1e-12);          // periodic ends
    EXPECT_NEAR(s.mean(), 0.0, 1e-12);
  }
}

TEST(CubicSpline, RejectsBadTables) {
  EXPECT_THROW(CubicSpline({0}, {1}), inerta::InvalidArgument);
  EXPECT_THROW(CubicSpline({0, 1, 1}, {1, 2, 3}), inerta::InvalidArgument);
  EXPECT_THROW(CubicSpline({0, 1}, {1, NAN}), inerta::InvalidArgument);
  EXPECT_THROW(CubicSpline({0, 1, 2}, {0, 1, 2}, CubicSpline::Ends::Periodic), inerta::InvalidArgument);
}
}  // namespace test_numerics_cubic_spline
