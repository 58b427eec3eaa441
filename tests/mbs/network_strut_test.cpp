// Network struts in the multibody engine (spec/03 §3.1): time domain against the admittance,
// explicit point-body networks converging to the strut, 0/∞ limits, the spinning strut, energy,
// and the two-bar with its parallel elements written as one network.
#include "inerta/mbs/network_strut.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_network_strut {

using namespace inerta;
using inerta::testing::run;

namespace {

// Test rig: the strut joins the fixed point A to a slider driven along the strut axis,
// x = 1 + U sin(2π f t) (spec/03: "one terminal fixed, the other driven sinusoidally").
std::string rig(const std::string& network, const std::string& params, double U, double f,
                const std::string& extra = "") {
  return fmt::format(R"(
options: {{gravity: false}}
ground: {{markers: {{A: [0, 0]}}}}
bodies:
  - {{name: slider, mass: 1, inertia: 0.1, position: [1, 0]}}
joints:
  - {{name: rail, type: prismatic, markers: [ground.A, slider.cm], axis: [1, 0]}}
  - {{name: drive, type: driving, body: slider, coordinate: x, motion: {{type: sine, amplitude: {}, frequency: {}}}}}
forces:
  - {{name: s, type: network, markers: [ground.A, slider.cm], network: "{}", params: {{{}}}}}
{}outputs:
  - {{name: F, type: force, element: s}}
  - {{name: l, type: length, element: s}}
)",
                     U, f, network, params, extra);
}

// Fourier coefficient of v at frequency f over the samples with t >= t0 (whole periods):
// v ≈ a sin(ωt) + b cos(ωt); returns amplitude and phase (rad) of a sin(ωt + φ).
std::pair<double, double> harmonic(const std::vector<double>& t, const std::vector<double>& v, double f, double t0) {
  const double w = 2 * M_PI * f;
  double a = 0, b = 0, T = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i - 1] < t0 - 1e-12) continue;
    double h = t[i] - t[i - 1];
    a += 0.5 * h * (v[i] * std::sin(w * t[i]) + v[i - 1] * std::sin(w * t[i - 1]));
    b += 0.5 * h * (v[i] * std::cos(w * t[i]) + v[i - 1] * std::cos(w * t[i - 1]));
    T += h;
  }
  a *= 2 / T, b *= 2 / T;
  return {std::hypot(a, b), std::atan2(b, a)};
}

struct LayoutCase {
  std::string network, params;
  network::Params values;
};
const std::vector<LayoutCase>& layout_cases() {
  static const std::vector<LayoutCase> c = {
      {"S2-default", "", {}},
      {"b-(k|c)", "b: 10, k: 100, c: 100", {{"b", 10}, {"k", 100}, {"c", 100}}},
      {"k-(b|c)", "k: 2000, b: 5, c: 60", {{"k", 2000}, {"b", 5}, {"c", 60}}},
      {"b-c", "b: 20, c: 300", {{"b", 20}, {"c", 300}}},
      {"b|c|k", "b: 3, c: 40, k: 900", {{"b", 3}, {"c", 40}, {"k", 900}}},
      {"(k1-c1)|(b-(k2|c2))",
       "k1: 500, c1: 50, b: 2, k2: 800, c2: 30",
       {{"k1", 500}, {"c1", 50}, {"b", 2}, {"k2", 800}, {"c2", 30}}},
  };
  return c;
}

}  // namespace

TEST(NetworkStrut, SteadyStateForceMatchesAdmittance) {
  const double U = 0.01;
  for (const auto& lc : layout_cases()) {
    for (double f : {0.5, 2.0, 6.0}) {
      SCOPED_TRACE(fmt::format("{} at {} Hz", lc.network, f));
      mbs::Model m = io::parse_model(rig(lc.network, lc.params, U, f), "rig.yaml");
      solve::IntegratorOptions opt;
      opt.method = solve::Method::Bdf;
      opt.rtol = 1e-10;
      opt.atol = 1e-12;
      const double settle = 12.0, T = 1.0 / f;
      auto s = run(m, settle + 4 * T, T / 400, opt);
      // F/v = Y with v = U ω cos ωt = U ω sin(ωt + π/2).
      std::complex<double> Y = network::admittance(network::resolve(lc.network, lc.values), {0, 2 * M_PI * f});
      auto [amp, phase] = harmonic(s.t, s[0], f, settle);
      EXPECT_NEAR(amp, std::abs(Y) * U * 2 * M_PI * f, 2e-3 * std::abs(Y) * U * 2 * M_PI * f);
      double dphi = std::remainder(phase - (M_PI / 2 + std::arg(Y)), 2 * M_PI);
      EXPECT_LT(std::abs(dphi) * 180 / M_PI, 0.1);
    }
  }
}

TEST(NetworkStrut, ExplicitPointBodiesConvergeToTheStrut) {
  // b-(k|c) built from a point body (mass m_n) at the internal node: as m_n → 0 its force → the strut's.
  const double U = 0.01, f = 1.5;
  solve::IntegratorOptions opt;
  opt.method = solve::Method::Bdf;
  opt.rtol = 1e-9;
  opt.atol = 1e-12;
  auto strut = run(io::parse_model(rig("b-(k|c)", "b: 10, k: 100, c: 100", U, f), "rig.yaml"), 3, 0.01, opt);
  double Fmax = 0;
  for (double v : strut[0]) Fmax = std::max(Fmax, std::abs(v));
  std::vector<double> errors;
  for (double mn : {1e-1, 1e-3, 1e-5}) {
    std::string text = fmt::format(R"(
options: {{gravity: false}}
ground: {{markers: {{A: [0, 0]}}}}
bodies:
  - {{name: slider, mass: 1, inertia: 0.1, position: [1, 0]}}
  - {{name: node, mass: {}, inertia: 0, position: [0.5, 0]}}
joints:
  - {{name: rail, type: prismatic, markers: [ground.A, slider.cm], axis: [1, 0]}}
  - {{name: rail_n, type: prismatic, markers: [ground.A, node.cm], axis: [1, 0]}}
  - {{name: drive, type: driving, body: slider, coordinate: x, motion: {{type: sine, amplitude: {}, frequency: {}}}}}
forces:
  - {{name: b, type: inerter, markers: [ground.A, node.cm], b: 10}}
  - {{name: k, type: spring, markers: [node.cm, slider.cm], k: 100}}
  - {{name: c, type: damper, markers: [node.cm, slider.cm], c: 100}}
outputs:
  - {{name: Fk, type: force, element: k}}
  - {{name: Fc, type: force, element: c}}
)",
                                   mn, U, f);
    auto ex = run(io::parse_model(text, "explicit.yaml"), 3, 0.01, opt);
    double e = 0;
    for (std::size_t i = 0; i < ex.t.size(); ++i) e = std::max(e, std::abs(ex[0][i] + ex[1][i] - strut[0][i]));
    errors.push_back(e / Fmax);
  }
  EXPECT_LT(errors[1], 0.1 * errors[0]);
  EXPECT_LT(errors[2], 0.1 * errors[1]);
  EXPECT_LT(errors[2], 1e-4);
}

TEST(NetworkStrut, LimitsBehaveAsTheSimplerNetwork) {
  const double U = 0.01, f = 1.0;
  solve::IntegratorOptions opt;
  opt.method = solve::Method::Bdf;
  opt.rtol = 1e-10;
  opt.atol = 1e-12;
  auto base = run(io::parse_model(rig("b-(k|c)", "b: 10, k: 100, c: 100", U, f), "a.yaml"), 4, 0.01, opt);
  // A series damper of 1e12 is (nearly) rigid: the same force.
  auto stiff = run(io::parse_model(rig("b-(k|c)-c2", "b: 10, k: 100, c: 100, c2: 1e12", U, f), "b.yaml"), 4, 0.01, opt);
  // A parallel damper of 0 is absent (simplified away); an infinite series damper too.
  auto open = run(io::parse_model(rig("(b-(k|c))|c0", "b: 10, k: 100, c: 100, c0: 0", U, f), "c.yaml"), 4, 0.01, opt);
  auto rigid = run(io::parse_model(rig("b-(k|c)-c2", "b: 10, k: 100, c: 100, c2: inf", U, f), "d.yaml"), 4, 0.01, opt);
  double Fmax = 0, e_stiff = 0, e_open = 0, e_rigid = 0;
  for (std::size_t i = 0; i < base.t.size(); ++i) {
    Fmax = std::max(Fmax, std::abs(base[0][i]));
    e_stiff = std::max(e_stiff, std::abs(stiff[0][i] - base[0][i]));
    e_open = std::max(e_open, std::abs(open[0][i] - base[0][i]));
    e_rigid = std::max(e_rigid, std::abs(rigid[0][i] - base[0][i]));
  }
  EXPECT_GT(Fmax, 0.1);
  EXPECT_LT(e_stiff, 1e-6 * Fmax);
  EXPECT_EQ(e_open, 0.0);
  EXPECT_EQ(e_rigid, 0.0);
}

TEST(NetworkStrut, OpenAndRigidNetworksAreReported) {
  mbs::Model open = io::parse_model(rig("k-c", "k: 0, c: 5", 0.01, 1), "open.yaml");
  ASSERT_EQ(open.notes.size(), 1u);
  EXPECT_NE(open.notes[0].find("open"), std::string::npos);
  auto s = run(open, 1, 0.1);  // the strut stays (its outputs work) and exerts no force
  for (double F : s[0]) EXPECT_EQ(F, 0.0);
  EXPECT_NEAR(s[1].back(), 1.0, 1e-6);  // the driven length, x(1 s) = 1 m
  // A rigid network becomes a distance joint: the driven slider then over-constrains the rig.
  try {
    io::parse_model(rig("k|c", "k: inf, c: 5", 0.01, 1), "rigid.yaml");
    FAIL() << "the rig's output of the strut's force must be refused";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("rigid network"), std::string::npos) << e.what();
  }
  std::string text = rig("k|c", "k: inf, c: 5", 0.01, 1);
  text = text.substr(0, text.find("outputs:"));
  mbs::Model rigid = io::parse_model(text, "rigid.yaml");
  ASSERT_EQ(rigid.notes.size(), 1u);
  EXPECT_NE(rigid.notes[0].find("distance joint"), std::string::npos);
  EXPECT_EQ(rigid.joints.back().type, mbs::JointType::Distance);
}

TEST(NetworkStrut, SpinningAtConstantLengthProducesNoForceForEveryLayout) {
  const double w = 3, R = 0.5;
  for (const auto& layout : network::layouts()) {
    network::Params p;
    for (const auto& name : network::parameter_names(network::parse(layout.expression)))
      if (!layout.fixed.count(name)) p[name] = name[0] == 'b' ? 20.0 : name[0] == 'c' ? 300.0 : 5000.0;
    std::string params;
    for (const auto& [k, v] : p) params += fmt::format("{}{}: {}", params.empty() ? "" : ", ", k, v);
    for (bool corr : {true, false}) {
      SCOPED_TRACE(layout.name + (corr ? " with correction" : " without correction"));
      std::string text = fmt::format(R"(
options: {{gravity: false, centripetal: {}}}
ground: {{markers: {{O: [0, 0]}}}}
bodies:
  - {{name: bar, mass: 1, inertia: 0.1, position: [0, 0], angular_velocity: {}, markers: {{tip: [{}, 0]}}}}
joints:
  - {{name: pivot, type: revolute, markers: [ground.O, bar.cm]}}
forces:
  - {{name: s, type: network, markers: [ground.O, bar.tip], network: "{}", params: {{{}}}}}
outputs:
  - {{name: F, type: force, element: s}}
)",
                                     corr, w, R, layout.name, params);
      mbs::Model m = io::parse_model(text, "spin.yaml");
      auto s = run(m, 1, 0.05);
      // Without the correction the 1D form gives −b_direct ω² R, with b_direct = lim Y(s)/s (the inerter
      // directly across the terminals), taken from the tree admittance, not from the realisation.
      const std::complex<double> s_big(0, 1e9);
      const double b_direct = (network::admittance(network::resolve(layout.name, p), s_big) / s_big).real();
      const double expected = corr ? 0.0 : -b_direct * w * w * R;
      // Tolerance: the constraint drift (~1e-13 m) times the stiffest element.
      for (double F : s[0]) EXPECT_NEAR(F, expected, 1e-6 * (1 + std::abs(expected)));
    }
  }
}

TEST(NetworkStrut, NetworksOnlyDissipate) {
  // Passivity: starting relaxed, the work done on the network W(t) = ∫ F l̇ dt never goes negative,
  // and over a steady cycle it equals the dissipation ½ (Uω)² Re Y(iω) > 0.
  const double U = 0.01;
  for (const auto& lc : layout_cases()) {
    SCOPED_TRACE(lc.network);
    for (double f : {0.7, 3.0}) {
      mbs::Model m = io::parse_model(rig(lc.network, lc.params, U, f), "rig.yaml");
      solve::IntegratorOptions opt;
      opt.method = solve::Method::Bdf;
      opt.rtol = 1e-10;
      opt.atol = 1e-12;
      const double T = 1 / f, settle = 12.0;
      auto s = run(m, settle + 2 * T, T / 400, opt);
      double W = 0, Wmin = 0, Wcycle = 0;
      for (std::size_t i = 1; i < s.t.size(); ++i) {
        double dW = 0.5 * (s[0][i] + s[0][i - 1]) * (s[1][i] - s[1][i - 1]);  // F dl
        W += dW;
        Wmin = std::min(Wmin, W);
        if (s.t[i - 1] >= settle - 1e-12) Wcycle += dW;
      }
      const double w = 2 * M_PI * f;
      std::complex<double> Y = network::admittance(network::resolve(lc.network, lc.values), {0, w});
      const double expected = 0.5 * std::pow(U * w, 2) * Y.real() * 2 * T;  // two periods
      EXPECT_GE(Wmin, -1e-9 * std::abs(W));
      EXPECT_GT(expected, 0.0);
      EXPECT_NEAR(Wcycle, expected, 5e-3 * expected);
    }
  }
}

TEST(NetworkStrut, EnergyBalanceOfTheWholeSystem) {
  // Two-bar with a TID strut b-(k|c) and a direct inerter b2|(...): d/dt(T + Σ energy) = Σ power.
  mbs::Model m = io::load_model(inerta::testing::model_path("twobar_network.yaml"));
  // Replace the strut by one with internal states and a direct inerter.
  auto& old = static_cast<const mbs::NetworkStrut&>(*m.forces[1]);
  network::Network net = network::simplify(
      network::assign(network::parse("b2|(b-(k|c))"), {{"b2", 4}, {"b", 10}, {"k", 100}, {"c", 100}}));
  m.forces[1] = std::make_shared<mbs::NetworkStrut>("strut", 0, mbs::Vec2(0.25, 0), 1, mbs::Vec2(0.25, 0), net,
                                                    old.reference_length());
  m.finalize();
  ASSERT_EQ(m.n_states(), 2);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-11;
  opt.atol = 1e-13;
  mbs::State x = mbs::assemble(m, 0.0);
  double E0 = 0, W = 0, tp = 0, Pp = 0, err = 0, scale = 0;
  bool first = true;
  solve::integrate(m, x, 0, 5, 1e-4, opt, [&](double t, const mbs::State& s, const mbs::Workspace&) {
    double E = mbs::kinetic_energy(m, s) + mbs::stored_energy(m, t, s), P = mbs::element_power(m, t, s);
    if (first)
      E0 = E, first = false;
    else
      W += 0.5 * (P + Pp) * (t - tp);
    err = std::max(err, std::abs(E - E0 - W));
    scale = std::max(scale, std::abs(W));
    tp = t, Pp = P;
  });
  EXPECT_GT(scale, 0.1);
  EXPECT_LT(err, 1e-5 * scale);
}

TEST(NetworkStrut, TwoBarWithNetworkStrutEqualsPlainTwoBar) {
  // k|c|b as one strut is the same force law as the three elements: equal to integrator accuracy.
  for (double rtol : {1e-6, 1e-10}) {
    solve::IntegratorOptions opt;
    opt.rtol = rtol;
    opt.atol = rtol * 1e-2;
    auto plain = run(io::load_model(inerta::testing::model_path("twobar.yaml")), 60, 0.001, opt);
    auto net = run(io::load_model(inerta::testing::model_path("twobar_network.yaml")), 60, 0.001, opt);
    ASSERT_EQ(plain.t.size(), net.t.size());
    double e = 0;
    for (std::size_t i = 0; i < plain.t.size(); ++i) e = std::max(e, std::abs(plain[1][i] - net[1][i]));
    EXPECT_LT(e, 10 * rtol) << "max |C_y(plain) − C_y(network)| at rtol " << rtol;
  }
}
}  // namespace test_mbs_network_strut
