// The lumped catenary alone under a constant force against the pumping frequency (spec/06 §6.3).
#include "inerta/analysis/catenary_response.hpp"

#include <gtest/gtest.h>

#include <algorithm>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_catenary_response {

using namespace inerta;

TEST(CatenaryResponse, ResonanceWhenThePumpingFrequencyMeetsTheNaturalFrequency) {
  catenary::LumpedCatenary cat;  // default set: f_n = 1.00 Hz
  std::vector<double> fp;
  for (double f = 0.6; f <= 1.4 + 1e-9; f += 0.02) fp.push_back(f);
  auto r = analysis::catenary_response(cat, 70, fp, 40.0, 8);
  std::size_t k = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_TRUE(r[i].stable());
    if (r[i].acc_amplitude > r[k].acc_amplitude) k = i;
  }
  EXPECT_NEAR(r[k].fp, cat.natural_frequency(), 0.03);
  EXPECT_NEAR(r[k].mean_uplift, 70 / 7000.0, 0.003);  // about the static uplift F/k_c0
}

TEST(CatenaryResponse, NoHarmonicsNoAcceleration) {
  catenary::LumpedCatenary cat;
  cat.k = {7000, 0, 0, 0};
  auto r = analysis::catenary_response(cat, 70, {0.5, 1.0, 1.7}, 20.0, 4);
  for (const auto& x : r) {
    EXPECT_LT(x.acc_amplitude, 1e-6);
    EXPECT_NEAR(x.mean_uplift, 0.01, 1e-8);  // F / k_c0
  }
}

TEST(CatenaryResponse, ParametricResonanceIsFlaggedNotReportedAsSteady) {
  catenary::LumpedCatenary cat;  // ±30 % stiffness, 1.6 % damping: Mathieu-unstable at f_p ≈ 2 f_n
  auto r = analysis::catenary_response(cat, 70, {1.98}, 40.0, 8);
  EXPECT_FALSE(r[0].stable());
}
}  // namespace test_analysis_catenary_response
