// Test-rig FRF of the HSX (spec/04 §4.2): the linear (frequency-domain) FRF against the stepped-sine
// FRF of the nonlinear model at small amplitude — two independent formulations.
#include "inerta/analysis/frf.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_frf {

using namespace inerta;

TEST(Frf, LinearEqualsSteppedSineAtSmallAmplitude) {
  const pantograph::Pantograph hsx = io::load_pantograph(inerta::testing::model_path("hsx.yaml"));
  const std::vector<std::string> outs = {"P_ay", "E_ay", "B_ay"};
  const std::vector<double> f = {0.8, 3.0, 6.5, 8.7, 12.0};
  analysis::Frf lin = analysis::frf_linear(hsx, outs, f);
  analysis::SteppedSine o;
  o.vc = 0.006;
  o.cycles = 40;
  o.analysed = 20;
  analysis::Frf ss = analysis::frf_stepped_sine(hsx, outs, f, o);
  for (std::size_t i = 0; i < outs.size(); ++i)
    for (std::size_t k = 0; k < f.size(); ++k) {
      SCOPED_TRACE(outs[i] + " at " + std::to_string(f[k]) + " Hz");
      EXPECT_GT(std::abs(lin.H[i][k]), 1e-3);
      EXPECT_NEAR(std::abs(ss.H[i][k]) / std::abs(lin.H[i][k]), 1.0, 0.02);
      EXPECT_LT(std::abs(std::remainder(std::arg(ss.H[i][k]) - std::arg(lin.H[i][k]), 2 * M_PI)) * 180 / M_PI, 2.0);
    }
}

TEST(Frf, HeadPeakNearTheHeadModeAndFlexiblePeakNearTenHz) {
  // The identified model reproduces the thesis's peaks: head ≈ 6 Hz, upper-arm flexibility ≈ 10 Hz.
  const pantograph::Pantograph hsx = io::load_pantograph(inerta::testing::model_path("hsx.yaml"));
  std::vector<double> f;
  for (double x = 2.0; x <= 15.0; x += 0.05) f.push_back(x);
  analysis::Frf lin = analysis::frf_linear(hsx, {"P_ay", "E_ay"}, f);
  auto peak = [&](int i) {
    std::size_t k = 0;
    for (std::size_t j = 0; j < f.size(); ++j)
      if (std::abs(lin.H[i][j]) > std::abs(lin.H[i][k])) k = j;
    return f[k];
  };
  EXPECT_GT(peak(0), 4.0);
  EXPECT_LT(peak(0), 9.0);
  EXPECT_GT(peak(1), 8.0);
  EXPECT_LT(peak(1), 14.0);
}
}  // namespace test_analysis_frf
