// Identification round trips (spec/06 §6.4, spec/03 §3.3) on synthetic measurements: a model with
// known parameters, seeded noise, and the parameters recovered within stated tolerances.
#include "inerta/analysis/identification.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"
#include "support/synthetic.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_identification {

using namespace inerta;
using inerta::testing::cd;

namespace {

std::vector<double> grid(double a, double step, double b) {
  std::vector<double> f;
  for (long k = 0; a + static_cast<double>(k) * step <= b + 1e-9; ++k) f.push_back(a + static_cast<double>(k) * step);
  return f;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

// ---- head suspension (eqs. 4.19, 4.20) ----

TEST(HeadSuspension, ExactFrfsGiveK2AndC2AtEveryFrequency) {
  const inerta::testing::HeadArm p;
  const std::vector<double> f = grid(0.5, 0.25, 20);
  std::vector<cd> H, E;
  for (double x : f) {
    auto [h, e] = inerta::testing::head_arm_frf(p, x);
    H.push_back(h), E.push_back(e);
  }
  const auto r = analysis::fit_head_suspension(p.m_H, f, H, E, 4, 20);
  EXPECT_NEAR(r.k2 / p.k2, 1.0, 1e-8);
  EXPECT_NEAR(r.c2 / p.c2, 1.0, 1e-8);
  EXPECT_EQ(r.points, 65);  // 4, 4.25, …, 20
  EXPECT_LT(r.rms_residual, 1e-10);
  ASSERT_EQ(r.per_frequency.size(), f.size());
  for (const auto& q : r.per_frequency) {  // eq. 4.19 alone, even below 4 Hz
    EXPECT_NEAR(q.k2 / p.k2, 1.0, 1e-10) << q.f;
    EXPECT_NEAR(q.c2 / p.c2, 1.0, 1e-10) << q.f;
  }
}

TEST(HeadSuspension, TwoPercentNoiseRecoversK2AndC2WithinAFewPercent) {
  // 2 % complex noise on both FRFs, 0.5–20 Hz in 0.1 Hz steps, band 4–20 Hz (161 frequencies).
  const inerta::testing::HeadArm p;
  const std::vector<double> f = grid(0.5, 0.1, 20);
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    std::vector<cd> H, E;
    for (double x : f) {
      auto [h, e] = inerta::testing::head_arm_frf(p, x);
      H.push_back(inerta::testing::noisy(h, 0.02, rng)), E.push_back(inerta::testing::noisy(e, 0.02, rng));
    }
    const auto r = analysis::fit_head_suspension(p.m_H, f, H, E, 4, 20);
    EXPECT_NEAR(r.k2 / p.k2, 1.0, 0.01) << "seed " << seed;  // measured ≤ 0.4 %
    EXPECT_NEAR(r.c2 / p.c2, 1.0, 0.03) << "seed " << seed;  // measured ≤ 0.9 %
    // A wrong head mass must show: +10 % moves k2 by far more than the noise does.
    const auto wrong = analysis::fit_head_suspension(1.1 * p.m_H, f, H, E, 4, 20);
    EXPECT_GT(std::abs(wrong.k2 / p.k2 - 1), 0.05);
  }
}

TEST(HeadSuspension, BandWithoutDataIsAnInputError) {
  const inerta::testing::HeadArm p;
  auto [h, e] = inerta::testing::head_arm_frf(p, 5.0);
  try {
    analysis::fit_head_suspension(p.m_H, {5.0}, {h}, {e}, 10, 20);
    FAIL() << "no error";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find("no frequency in the band 10–20 Hz"), std::string::npos) << err.what();
  }
  EXPECT_THROW(analysis::head_suspension_at(p.m_H, 0.0, h, e), ModelError);
}

// ---- multi-parameter FRF fit (eq. 6.47) on the HSX ----

TEST(FrfFit, HsxRecoversFourPerturbedParametersFromNoisyFrfs) {
  // Truth: c2, k_u, k_f, c_f perturbed by −20 … +25 % from models/hsx.yaml; "measured" FRFs by
  // frf_linear at 0.5–11 Hz every 0.5 Hz (issue 52: the suite's budget) plus 1 % complex noise; fit from
  // the file's values (box ÷10 … ×10).
  const std::string path = inerta::testing::model_path("hsx.yaml"), text = read_text(path);
  const std::vector<std::string> keys = {"c2.c", "k_u.k", "kf_cf.k", "kf_cf.c"};
  const std::vector<double> truth = {95.0, 24e3, 800.0, 105.0};
  std::vector<std::string> set;
  for (std::size_t i = 0; i < keys.size(); ++i) set.push_back(keys[i] + "=" + fmt::format("{:.17g}", truth[i]));
  const std::vector<std::string> outs = {"P_ay", "E_ay", "B_ay"};
  analysis::Frf meas = analysis::frf_linear(io::parse_model_file(text, path, set), outs, grid(0.5, 0.5, 11));
  std::mt19937 rng(7);
  for (auto& row : meas.H)
    for (auto& h : row) h = inerta::testing::noisy(h, 0.01, rng);
  std::vector<numerics::Variable> vars;
  for (const auto& k : keys) {
    const double v = *io::model_value(text, path, k);
    vars.push_back({k, v / 10, v * 10, false, false});
  }
  numerics::Options o;
  o.starts = 1;
  o.min_step = 1e-4;
  auto model_of = [&](const std::vector<double>& v) {
    std::vector<std::string> s;
    for (std::size_t i = 0; i < v.size(); ++i) s.push_back(keys[i] + "=" + fmt::format("{:.17g}", v[i]));
    return io::parse_model_file(text, path, s);
  };
  const analysis::FrfFit r = analysis::fit_frf(model_of, vars, meas, o);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    EXPECT_NEAR(r.values[i] / truth[i], 1.0, 0.02) << keys[i] << " = " << r.values[i];  // measured ≤ 0.47 %
  }
  EXPECT_LT(r.cost, 0.05 * r.initial_cost);
  // The cost at the truth is the noise floor; the fit must be at least as good.
  EXPECT_LE(r.cost, analysis::frf_misfit(analysis::frf_linear(model_of(truth), outs, meas.f), meas) * (1 + 1e-6));
}

TEST(FrfFit, BandWithoutDataIsAnInputError) {
  analysis::Frf m;
  m.f = {1, 2};
  m.outputs = {"P_ay"};
  m.H = {{1.0, 2.0}};
  EXPECT_EQ(analysis::frf_band(m, 1.5, 3).f.size(), 1u);
  EXPECT_THROW(analysis::frf_band(m, 5, 6), ModelError);
}

// ---- model overrides (the --set of frf-fit) ----

TEST(ModelOverrides, OverrideEqualsEditedFile) {
  const std::string path = inerta::testing::model_path("hsx.yaml"), text = read_text(path);
  std::string edited = text;
  const std::string from = "c: 78}", to = "c: 60}";
  ASSERT_NE(edited.find(from), std::string::npos);
  edited.replace(edited.find(from), from.size(), to);
  const std::vector<double> f = {3.0, 6.0, 9.0};
  const auto a = analysis::frf_linear(io::parse_model_file(text, path, {"c2.c=60"}), {"P_ay"}, f);
  const auto b = analysis::frf_linear(io::parse_model_file(edited, path), {"P_ay"}, f);
  const auto c = analysis::frf_linear(io::parse_model_file(text, path), {"P_ay"}, f);
  for (std::size_t k = 0; k < f.size(); ++k) {
    EXPECT_EQ(a.H[0][k], b.H[0][k]);
    EXPECT_GT(std::abs(a.H[0][k] - c.H[0][k]), 1e-3 * std::abs(c.H[0][k]));  // the override acts
  }
  EXPECT_EQ(*io::model_value(text, path, "c2.c"), 78.0);
  EXPECT_EQ(*io::model_value(text, path, "kf_cf.k"), 658.0);
  EXPECT_FALSE(io::model_value(text, path, "actuator.params.k").has_value());  // the layout's default
}

TEST(ModelOverrides, ErrorsNameTheOverride) {
  const std::string path = inerta::testing::model_path("hsx.yaml"), text = read_text(path);
  auto message = [&](const std::string& o) {
    try {
      io::parse_model(text, path, {o});
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("nothing.k=1").find("no force element, body or joint named 'nothing'"), std::string::npos);
  EXPECT_NE(message("c2.q=1").find("'c2' has no value 'q'; its values: c"), std::string::npos) << message("c2.q=1");
  EXPECT_NE(message("c2.c=abc").find("'abc' is not a number"), std::string::npos);
  EXPECT_NE(message("c2.name=3").find("'name' is not a number"), std::string::npos);
  EXPECT_NE(message("c2.c").find("expected NAME.KEY=VALUE"), std::string::npos);
  EXPECT_NE(message("c2.c=1").find("no error"), std::string::npos);
}

// ---- actuator (spec/03 §3.3) ----

TEST(ActuatorStatic, RecoversConstantForceFrictionAndDamping) {
  // 11 velocities 0.5–10 mm/s per direction, σ = 2 N force noise.
  const inerta::testing::ActuatorTruth a;
  for (unsigned seed : {1u, 2u, 3u}) {
    auto [v, F] = inerta::testing::actuator_static_data(a, 2.0, seed);
    const auto r = analysis::fit_actuator_static(v, F);
    EXPECT_NEAR(r.F_c, a.F_c, 2.0) << seed;
    EXPECT_NEAR(r.F_r, a.F_r, 2.0) << seed;
    EXPECT_NEAR(r.c1 / a.c1, 1.0, 0.04) << seed;  // measured ≤ 1.8 % (F_c, F_r ≤ 1.4 N)
    EXPECT_EQ(r.forward.points, 11);
    EXPECT_EQ(r.backward.points, 11);
  }
  // Noise-free: exact.
  auto [v, F] = inerta::testing::actuator_static_data(a, 0.0, 1);
  const auto r = analysis::fit_actuator_static(v, F);
  EXPECT_NEAR(r.F_c, a.F_c, 1e-8);
  EXPECT_NEAR(r.F_r, a.F_r, 1e-8);
  EXPECT_NEAR(r.c1, a.c1, 1e-6);
}

TEST(ActuatorStatic, OneDirectionOnlyIsTooFewPoints) {
  try {
    analysis::fit_actuator_static({0.001, 0.002, 0.003}, {1, 2, 3});
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("backward (v < 0) stroke has 0 distinct velocities"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(analysis::fit_line({1.0}, {2.0}), ModelError);
  EXPECT_THROW(analysis::fit_line({1.0, 1.0}, {2.0, 3.0}), ModelError);
}

TEST(ActuatorDynamic, MaxwellAdmittanceEqualsTheS2DefaultNetwork) {
  const network::Network net = network::resolve("k-c", {{"k", 141e3}, {"c", 10440}});  // S2-default's form
  for (double f : {0.5, 2.0, 6.0})
    EXPECT_LT(std::abs(analysis::maxwell_admittance(141e3, 10440, f) -
                       network::admittance(net, {0.0, 2 * std::numbers::pi * f})),
              1e-9 * 10440);
}

TEST(ActuatorDynamic, CorrelationMethodIsExactForASampledSinusoid) {
  std::vector<double> t, y;
  const double f = 1.7;
  for (int k = 0; k < 137; ++k) {  // 2.3 periods, not whole: least squares still exact
    t.push_back(k * 0.01);
    y.push_back(5.0 + 2.0 * std::cos(2 * std::numbers::pi * f * t.back() + 0.4));
  }
  const cd Y = analysis::harmonic_amplitude(t, y, f);
  EXPECT_NEAR(std::abs(Y), 2.0, 1e-12);
  EXPECT_NEAR(std::arg(Y), 0.4, 1e-12);
}

TEST(ActuatorDynamic, RecoversK1FromNoisySinusoidalTests) {
  // 1 mm amplitude at 0.5, 1.0, …, 6.0 Hz (as the thesis), 6 cycles each after a 1.5 s run-in;
  // force noise σ = 2 N, displacement noise σ = 2 µm; F_c, F_r, m_p as the thesis.
  const inerta::testing::ActuatorTruth a;
  const std::vector<double> freqs = grid(0.5, 0.5, 6.0);
  for (unsigned seed : {1u, 2u}) {
    const auto tests = inerta::testing::actuator_dynamic_data(a, 1e-3, freqs, 2.0, 2e-6, seed);
    const auto r = analysis::fit_actuator_dynamic(tests, a.c1, a.m_p, a.F_r);
    EXPECT_NEAR(r.k1 / a.k1, 1.0, 0.005) << seed;  // measured ≤ 0.03 %
    EXPECT_EQ(r.c1, a.c1);
    ASSERT_EQ(r.points.size(), freqs.size());
    for (const auto& p : r.points) {
      EXPECT_NEAR(p.amplitude, 1e-3, 1e-5);
      EXPECT_NEAR(std::abs(p.Y_E / analysis::maxwell_admittance(a.k1, a.c1, p.f)), 1.0, 0.02) << p.f;  // ≤ 0.7 %
    }
    // Both k1 and c1 free.
    const auto r2 = analysis::fit_actuator_dynamic(tests, 0, a.m_p, a.F_r, true);
    EXPECT_NEAR(r2.k1 / a.k1, 1.0, 0.005) << seed;  // measured ≤ 0.05 %
    EXPECT_NEAR(r2.c1 / a.c1, 1.0, 0.005) << seed;  // measured ≤ 0.07 %
  }
  // Noise-free: k1 to the resolution of the search and the RK4 data.
  const auto exact = analysis::fit_actuator_dynamic(inerta::testing::actuator_dynamic_data(a, 1e-3, freqs, 0, 0, 1),
                                                    a.c1, a.m_p, a.F_r);
  EXPECT_NEAR(exact.k1 / a.k1, 1.0, 1e-6);  // measured 1e-7
  EXPECT_LT(exact.cost, 1e-3);
}

TEST(ActuatorDynamic, ShortOrSparseTestsAreInputErrors) {
  analysis::DynamicTest T;
  T.f = 1.0;
  for (int k = 0; k < 5; ++k) T.t.push_back(0.1 * k), T.x.push_back(std::sin(0.6 * k)), T.F.push_back(0);
  EXPECT_THROW(analysis::fit_actuator_dynamic({T}, 1e4, 0, 0), ModelError);  // 5 samples
  for (int k = 5; k < 9; ++k) T.t.push_back(0.1 * k), T.x.push_back(std::sin(0.6 * k)), T.F.push_back(0);
  try {
    analysis::fit_actuator_dynamic({T}, 1e4, 0, 0);  // 0.8 s < one period
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("less than one period"), std::string::npos) << e.what();
  }
}
}  // namespace test_analysis_identification
