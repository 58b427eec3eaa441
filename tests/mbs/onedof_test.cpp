// 1-DOF lumped mass with an inerter (spec/01 §1.2): linearised natural frequency and the
// nonlinear response of eq. 3.14.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/reference_models.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_onedof {

using namespace inerta;
using inerta::testing::run;

namespace {
mbs::Model onedof(double y0, bool centripetal) {
  mbs::Model m = io::load_model(inerta::testing::model_path("onedof.yaml"));
  m.bodies[0].q0.y() = y0;
  m.options.centripetal = centripetal;
  return m;
}

// Mean period from upward zero crossings of v − mean (linear interpolation between samples).
double frequency(const std::vector<double>& t, const std::vector<double>& v, double centre) {
  std::vector<double> up;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (v[i - 1] < centre && v[i] >= centre)
      up.push_back(t[i - 1] + (centre - v[i - 1]) / (v[i] - v[i - 1]) * (t[i] - t[i - 1]));
  return static_cast<double>(up.size() - 1) / (up.back() - up.front());
}
}  // namespace

TEST(OneDof, SmallAmplitudeFrequencyIsLinearisedNaturalFrequency) {
  // Linearised: m_eq = m + (Lb/L0)² b, k_eq = k (Lb/L0)² (thesis appendix A.1).
  const double m = 5, b = 100, k = 1e4, La = 1, Lb = 1, L0 = std::sqrt(La * La + Lb * Lb);
  const double f_lin = std::sqrt(k * std::pow(Lb / L0, 2) / (m + std::pow(Lb / L0, 2) * b)) / (2 * M_PI);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-13;
  for (bool corr : {true, false}) {
    auto s = run(onedof(Lb + 1e-4, corr), 20, 1e-4, opt);
    EXPECT_NEAR(frequency(s.t, s[0], Lb), f_lin, 1e-3 * f_lin) << "centripetal " << corr;
  }
}

TEST(OneDof, LargeAmplitudeMatchesEquation3_14) {
  for (bool corr : {true, false}) {
    solve::IntegratorOptions opt;
    opt.rtol = 1e-10;
    opt.atol = 1e-12;
    auto s = run(onedof(1.5, corr), 5, 0.001, opt);
    auto ref = testref::onedof_reference(corr, 1.5, 5, 0.001, 1e-5);
    ASSERT_EQ(s.t.size(), ref.size());
    double ey = 0, eF = 0, Fmax = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      ey = std::max(ey, std::abs(s[0][i] - ref[i].y));
      eF = std::max(eF, std::abs(s[1][i] - ref[i].F_inerter));
      Fmax = std::max(Fmax, std::abs(ref[i].F_inerter));
    }
    EXPECT_LT(ey, 1e-6) << "centripetal " << corr;
    EXPECT_LT(eF, 1e-5 * Fmax) << "centripetal " << corr;
  }
}

TEST(OneDof, CorrectionLowersFrequencyAndShiftsMeanDown) {
  // Expected qualitative result of spec/01 §1.2 at y0 = 1.5 m.
  const double f_lin = testref::onedof_linear_frequency_hz();
  auto on = run(onedof(1.5, true), 20, 5e-4), off = run(onedof(1.5, false), 20, 5e-4);
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  double m_on = mean(on[0]), m_off = mean(off[0]);
  EXPECT_LT(frequency(on.t, on[0], m_on), f_lin);
  EXPECT_GT(frequency(off.t, off[0], m_off), f_lin);
  EXPECT_LT(m_on - 1.0, 0.0);
  EXPECT_GT(m_off - 1.0, m_on - 1.0);
}
}  // namespace test_mbs_onedof
