// The positive-real test (docs/synthesis.md) on functions whose positive-realness is known by
// construction: single elements, admittances of random series–parallel networks (passive, hence
// PR), minimum functions; and on functions that violate one condition each. The general test is
// checked against the closed-form biquadratic condition on random coefficient sets.
#include "inerta/network/positive_real.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "inerta/error.hpp"
#include "network_random.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_network_positive_real {

using namespace inerta::network;
using cd = std::complex<double>;

TEST(PositiveReal, SingleElements) {
  for (double v : {1e-3, 1.0, 7.5e4}) {
    EXPECT_TRUE(positive_real({{v}, {0.0, 1.0}}).positive_real) << "spring k/s, k = " << v;
    EXPECT_TRUE(positive_real({{v}, {1.0}}).positive_real) << "damper c = " << v;
    EXPECT_TRUE(positive_real({{0.0, v}, {1.0}}).positive_real) << "inerter b s, b = " << v;
  }
  const PrTest c = positive_real({{3.0}, {1.0}});
  EXPECT_NEAR(c.re_min, 3.0, 1e-12);
  const PrTest k = positive_real({{2.0}, {0.0, 1.0}});  // lossless: Re Y(jω) = 0 everywhere
  EXPECT_NEAR(k.re_min, 0.0, 1e-12);
}

TEST(PositiveReal, RandomNetworkAdmittancesArePositiveReal) {
  std::mt19937 rng(11);
  int tested = 0;
  for (int i = 0; i < 600; ++i) {
    const RandomNetwork r = random_network(rng, 1 + i % 6);
    const Rational y = rational_admittance(r.net);
    const PrTest t = positive_real(y);
    EXPECT_TRUE(t.positive_real) << r.text << ": " << t.reason;
    // re_min is the minimum of Re Y(jω): no sampled frequency goes below it.
    for (double w : log_grid(1e-3, 1e3, 61)) EXPECT_GE(y(cd(0, w)).real(), t.re_min - 1e-9 * std::abs(y(cd(0, w))));
    ++tested;
  }
  EXPECT_EQ(tested, 600);
}

TEST(PositiveReal, MinimumFunctionsArePositiveReal) {
  // (s² + s + 1)/(s² + s + 4): E(x) = (x − 2)², Re Y(jω) touches 0 at ω = √2.
  const PrTest t = positive_real({{1.0, 1.0, 1.0}, {4.0, 1.0, 1.0}});
  EXPECT_TRUE(t.positive_real) << t.reason;
  EXPECT_NEAR(t.re_min, 0.0, 1e-12);
  EXPECT_NEAR(t.omega_min, std::sqrt(2.0), 1e-6);
  // A random network's Y minus its min Re is a minimum function, PR; minus a little more it is not.
  std::mt19937 rng(5);
  int minimum = 0;
  for (int i = 0; i < 200; ++i) {
    const RandomNetwork r = random_network(rng, 3 + i % 4);
    const Rational y = rational_admittance(r.net);
    const PrTest t0 = positive_real(y);
    ASSERT_TRUE(t0.positive_real);
    if (!(t0.re_min > 1e-3 * std::abs(y(cd(0, 1.0))))) continue;
    Rational m = y;
    for (std::size_t j = 0; j < m.num.size() || j < m.den.size(); ++j) {
      if (j >= m.num.size()) m.num.push_back(0.0);
      if (j < m.den.size()) m.num[j] -= t0.re_min * m.den[j];
    }
    // The zero the subtraction makes at ω = 0 or ∞ is exact: set it so (rounding would move it).
    if (t0.omega_min == 0 && y.den[0] != 0.0) m.num[0] = 0.0;
    if (std::isinf(t0.omega_min) && m.num.size() == m.den.size()) m.num.back() = 0.0;
    double big = 0, left = 0;
    for (double v : y.num) big = std::max(big, std::abs(v));
    for (double& v : m.num)
      if (std::abs(v) <= 1e-13 * big) v = 0.0;  // cancelled exactly in exact arithmetic (Re Y constant)
    for (double v : m.num) left = std::max(left, std::abs(v));
    if (left <= 1e-12 * big) continue;  // Y was a constant (num and den with a common factor)
    const PrTest t1 = positive_real(m);
    EXPECT_TRUE(t1.positive_real) << r.text << " minus " << t0.re_min << ": " << t1.reason;
    Rational below = m;
    for (std::size_t j = 0; j < below.den.size(); ++j) below.num[j] -= 1e-6 * t0.re_min * below.den[j];
    EXPECT_FALSE(positive_real(below).positive_real) << r.text;
    ++minimum;
  }
  EXPECT_GT(minimum, 50);
}

TEST(PositiveReal, RejectsEachViolation) {
  auto reason = [](const Rational& y) {
    const PrTest t = positive_real(y);
    EXPECT_FALSE(t.positive_real);
    return t.reason;
  };
  EXPECT_NE(reason({{1.0}, {-1.0, 1.0}}).find("denominator has a root at s = 1 in the right half-plane"), std::string::npos);
  EXPECT_NE(reason({{-1.0, 1.0}, {2.0, 1.0}}).find("numerator has a root at s = 1 in the right half-plane"), std::string::npos);
  // Y = (s+1)/s²: a double pole at 0; (s⁴ + s³ + 1)/(s² + 1)²: a double pair at ±j.
  EXPECT_NE(reason({{1.0, 1.0}, {0.0, 0.0, 1.0}}).find("multiplicity 2"), std::string::npos);
  EXPECT_NE(reason({{1.0, 0.0, 0.0, 1.0, 1.0}, {1.0, 0.0, 2.0, 0.0, 1.0}}).find("multiplicity 2"), std::string::npos);
  // Negative residues with every root in the closed left half-plane: −(PR function with the pole).
  EXPECT_NE(reason({{-1.0, -1.0}, {0.0, 2.0, 1.0}}).find("pole of Y at s = 0"), std::string::npos);
  EXPECT_NE(reason({{-1.0, -1.0, -1.0}, {1.0, 0.0, 1.0}}).find("pole of Y at s = 0+1j"), std::string::npos);
  EXPECT_NE(reason({{-1.0, -1.0, -1.0}, {1.0, 1.0}}).find("pole of Y at s = ∞"), std::string::npos);
  EXPECT_NE(reason({{1.0, 1.0, 1.0}, {1.0}}).find("degree difference 2"), std::string::npos);
  EXPECT_NE(reason({{1.0}, {1.0, 1.0, 1.0}}).find("degree difference -2"), std::string::npos);
  EXPECT_NE(reason({{-2.0}, {1.0}}).find("Re Y(jω) = -2"), std::string::npos);
}

TEST(PositiveReal, NarrowDipBetweenGridPointsIsFound) {
  // Y0(s) = (σ² + σ + 1)/(σ² + σ + 4), σ = s·√2/ω0, has Re Y0(jω) = (x' − 2)²/|den|² ≥ 0 touching 0
  // at ω0; Y = Y0 − ε dips below 0 only for |ω/ω0 − 1| ≲ 6e-4. ω0 is put halfway (in log) between
  // two points of a 200-point grid over 1e-2 … 1e2, whose spacing is 4.7 %.
  const std::vector<double> grid = log_grid(1e-2, 1e2, 200);
  const double w0 = std::sqrt(grid[120] * grid[121]);
  const double a = std::sqrt(2.0) / w0, eps = 1e-6;
  const Poly den{4.0, a, a * a};
  const Rational y{{1.0 - 4 * eps, a * (1 - eps), a * a * (1 - eps)}, den};
  double grid_min = INFINITY;
  for (double w : grid) grid_min = std::min(grid_min, y(cd(0, w)).real());
  EXPECT_GT(grid_min, 0.0) << "the grid check passes";
  const PrTest t = positive_real(y);
  EXPECT_FALSE(t.positive_real);
  EXPECT_NEAR(t.re_min, -eps, 1e-12);
  EXPECT_NEAR(t.omega_min / w0, 1.0, 1e-6);
  EXPECT_NE(t.reason.find("< 0 at ω"), std::string::npos) << t.reason;
}

TEST(PositiveReal, AgreesWithTheBiquadraticCondition) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> e(-2, 2), u(0, 1);
  int pr = 0, not_pr = 0, skipped = 0;
  for (int i = 0; i < 6000; ++i) {
    double c[6];
    for (double& v : c) v = u(rng) < 0.1 ? 0.0 : std::pow(10.0, e(rng));
    if ((c[0] == 0 && c[1] == 0 && c[2] == 0) || (c[3] == 0 && c[4] == 0 && c[5] == 0)) continue;
    // Skip the boundary, where the tolerance decides: |a1 d1 − (√(a2 d0) − √(a0 d2))²| small.
    const double t = std::sqrt(c[2] * c[3]) - std::sqrt(c[0] * c[5]);
    const double margin = c[1] * c[4] - t * t, size = c[1] * c[4] + c[2] * c[3] + c[0] * c[5];
    if (std::abs(margin) < 1e-6 * size) {
      ++skipped;
      continue;
    }
    const bool closed = biquadratic_positive_real(c[0], c[1], c[2], c[3], c[4], c[5]);
    const PrTest g = positive_real({{c[0], c[1], c[2]}, {c[3], c[4], c[5]}});
    EXPECT_EQ(g.positive_real, closed) << "a = " << c[0] << ", " << c[1] << ", " << c[2] << "; d = " << c[3] << ", "
                                       << c[4] << ", " << c[5] << ": " << g.reason;
    (closed ? pr : not_pr)++;
  }
  EXPECT_GT(pr, 1000);
  EXPECT_GT(not_pr, 1000);
  std::cout << "biquadratic sets: " << pr << " PR, " << not_pr << " not PR, " << skipped << " on the boundary\n";
}

TEST(PositiveReal, BadArgumentsThrow) {
  EXPECT_THROW(positive_real({{}, {1.0}}), inerta::InvalidArgument);
  EXPECT_THROW(positive_real({{1.0}, {0.0, 0.0}}), inerta::InvalidArgument);
  EXPECT_THROW(positive_real({{NAN}, {1.0}}), inerta::InvalidArgument);
  EXPECT_THROW(positive_real({{1.0}, {INFINITY}}), inerta::InvalidArgument);
  EXPECT_THROW(positive_real({{1.0}, {1.0}}, -1), inerta::InvalidArgument);
  EXPECT_THROW(biquadratic_positive_real(-1, 1, 1, 1, 1, 1), inerta::InvalidArgument);
  EXPECT_THROW(biquadratic_positive_real(0, 0, 0, 1, 1, 1), inerta::InvalidArgument);
}
}  // namespace test_network_positive_real
