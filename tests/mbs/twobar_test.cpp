// Two-bar mechanism (spec/01 §1.6): the Cartesian engine against an independent minimal-coordinate
// Lagrangian model, tolerance convergence, and the two integrators against each other.
#include <gtest/gtest.h>

#include <cmath>

#include "inerta/error.hpp"
#include "support/reference_models.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_twobar {

using namespace inerta;
using inerta::testing::run;
using inerta::testing::window;

namespace {
mbs::Model twobar(bool centripetal) {
  mbs::Model m = io::load_model(inerta::testing::model_path("twobar.yaml"));
  m.options.centripetal = centripetal;
  return m;
}
}  // namespace

class TwoBarVsLagrange : public ::testing::TestWithParam<bool> {};

TEST_P(TwoBarVsLagrange, CyHistoryAgrees) {
  const bool corr = GetParam();
  const double t_end = 20, dt = 0.01;
  solve::IntegratorOptions opt;
  opt.rtol = 1e-9;
  opt.atol = 1e-11;
  auto s = run(twobar(corr), t_end, dt, opt);
  auto ref = testref::twobar_reference(corr, t_end, dt, 1e-4);
  ASSERT_EQ(s.t.size(), ref.size());
  double err = 0, amp = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    err = std::max({err, std::abs(s[1][i] - ref[i].Cy), std::abs(s[0][i] - ref[i].Cx)});
    amp = std::max(amp, std::abs(ref[i].Cy - ref[0].Cy));
  }
  EXPECT_GT(amp, 0.05);  // the mechanism really moves
  EXPECT_LT(err, 2e-6) << "max |C_engine − C_Lagrange| over 20 s, centripetal " << corr;
}

TEST_P(TwoBarVsLagrange, SteadyStatePeakToPeakAndOffset) {
  const bool corr = GetParam();
  auto s = run(twobar(corr), 60, 0.001);
  auto ref = testref::twobar_reference(corr, 60, 0.001, 1e-4);
  std::vector<double> rt, ry;
  for (const auto& r : ref) rt.push_back(r.t), ry.push_back(r.Cy);
  auto a = window(s.t, s[1], 50), b = window(rt, ry, 50);
  EXPECT_NEAR(a.ptp, b.ptp, 1e-5);
  EXPECT_NEAR(a.mean, b.mean, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Correction, TwoBarVsLagrange, ::testing::Values(true, false));

TEST(TwoBar, CorrectionChangesResponse) {
  // The thesis's point: the correction visibly changes peak-to-peak and mean offset (spec/01 §1.6).
  auto on = run(twobar(true), 60, 0.001), off = run(twobar(false), 60, 0.001);
  auto a = window(on.t, on[1], 50), b = window(off.t, off[1], 50);
  EXPECT_GT(std::abs(a.ptp - b.ptp), 0.005);
  EXPECT_GT(std::abs(a.mean - b.mean), 0.01);
}

TEST(TwoBar, DefaultTolerancesConvergeWithinTenthOfMillimetre) {
  for (auto method : {solve::Method::Rk, solve::Method::Bdf}) {
    solve::IntegratorOptions def, tight;
    def.method = tight.method = method;
    tight.rtol = 1e-10;
    tight.atol = 1e-12;
    auto a = run(twobar(true), 60, 0.001, def), b = run(twobar(true), 60, 0.001, tight);
    auto wa = window(a.t, a[1], 50), wb = window(b.t, b[1], 50);
    EXPECT_LT(std::abs(wa.ptp - wb.ptp), 1e-4) << solve::method_name(method);
    EXPECT_LT(std::abs(wa.mean - wb.mean), 1e-4) << solve::method_name(method);
  }
}

TEST(TwoBar, IntegratorsAgree) {
  solve::IntegratorOptions rk, bdf;
  rk.rtol = bdf.rtol = 1e-9;
  rk.atol = bdf.atol = 1e-11;
  bdf.method = solve::Method::Bdf;
  auto a = run(twobar(true), 10, 0.01, rk), b = run(twobar(true), 10, 0.01, bdf);
  double err = 0;
  for (std::size_t i = 0; i < a.t.size(); ++i) err = std::max(err, std::abs(a[1][i] - b[1][i]));
  EXPECT_LT(err, 1e-6);
}

TEST(TwoBar, ConstraintDriftStaysSmall) {
  auto s = run(twobar(true), 60, 0.01);
  EXPECT_LT(s.stats.max_violation, 1e-6);
  EXPECT_GT(s.stats.steps, 100);
}

TEST(Integrator, FailureStopsWithSimulatedTime) {
  for (auto method : {solve::Method::Rk, solve::Method::Bdf}) {
    solve::IntegratorOptions opt;
    opt.method = method;
    opt.max_steps = 20;  // far too few for one 1 s sample interval
    mbs::Model m = twobar(true);
    mbs::State x = mbs::assemble(m, 0.0);
    try {
      solve::integrate(m, x, 0.0, 10.0, 1.0, opt);
      FAIL() << "expected NumericalError";
    } catch (const NumericalError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find("failed at t = "), std::string::npos) << msg;
    }
  }
}
}  // namespace test_mbs_twobar
