// Driving joints with exact inputs (issue 13, part 1): a spline table or a ramp drives a crank at
// constant speed with the analytic torque from t = 0; a spline-table drive is followed with its
// velocity and acceleration to the integrator's tolerance; --from-equilibrium starts with the
// drive's velocity; a run whose constraints drift beyond options.max_violation fails.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "inerta/analysis/simulate.hpp"
#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_driving {

namespace {

using namespace inerta;
constexpr double kPi = std::numbers::pi;

// A crank of mass m, centre of mass at distance e from its pin at ground.O (θ = 0: horizontal),
// with a rotational damper c at the pin, its angle driven by `motion`. Outputs: the drive's
// torque on the crank, θ, and the vertical velocity of the centre of mass.
std::string crank(const std::string& motion, double m, double e, double c) {
  return fmt::format(R"(name: crank
options: {{gravity: true}}
ground:
  markers: {{O: [0, 0]}}
bodies:
  - {{name: crank, mass: {m}, inertia: 0.05, position: [{e}, 0], markers: {{a: [{me}, 0]}}}}
joints:
  - {{name: pin, type: revolute, markers: [ground.O, crank.a]}}
  - {{name: drive, type: driving, body: crank, coordinate: theta, motion: {motion}}}
forces:
  - {{name: cr, type: rotational_damper, joint: pin, c: {c}}}
outputs:
  - {{name: torque, type: reaction, joint: drive, component: moment}}
  - {{name: theta, type: coordinate, body: crank, component: theta}}
  - {{name: vy, type: velocity, marker: crank.cm, component: y}}
)",
                     fmt::arg("m", m), fmt::arg("e", e), fmt::arg("me", -e), fmt::arg("c", c),
                     fmt::arg("motion", motion));
}

void expect_constant_speed_crank(const std::string& motion) {
  const double m = 2, e = 0.3, c = 0.4, w = 2.0, g = 9.81;
  const mbs::Model model = io::parse_model(crank(motion, m, e, c), "crank.yaml");
  solve::IntegratorOptions o;
  o.rtol = 1e-9, o.atol = 1e-11;
  const auto s = inerta::testing::run(model, 3.0, 0.01, o);
  // θ̈ = 0: about the pin, τ = m g e cos θ + c ω (the pin's force has no moment about it).
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const double t = s.t[i];
    const double th = w * t;
    EXPECT_NEAR(s[1][i], th, 1e-7) << "t = " << t;
    EXPECT_NEAR(s[2][i], e * w * std::cos(th), 1e-6) << "t = " << t;
    EXPECT_NEAR(s[0][i], m * g * e * std::cos(th) + c * w, 1e-5 * (m * g * e)) << "t = " << t;
  }
}

TEST(Driving, ConstantSpeedCrankFromASplineTable) {
  expect_constant_speed_crank("{type: table, points: [[0, 0], [1, 2], [2, 4], [4, 8]]}");
}

TEST(Driving, ConstantSpeedCrankFromARamp) { expect_constant_speed_crank("{type: ramp, slope: 2}"); }

TEST(Driving, SplineTableIsFollowedWithVelocityAndAcceleration) {
  // A slider (mass on a vertical prismatic joint, spring to ground) driven by an irregular table.
  const std::string table = "[[0, 0], [0.3, 0.02], [0.7, -0.01], [1.1, 0.03], [1.6, 0.0], [2.0, 0.01]]";
  const std::string text = fmt::format(R"(name: slider
options: {{gravity: true}}
ground:
  markers: {{P: [0, -1]}}
bodies:
  - {{name: s, mass: 3, inertia: 0.1, position: [0, 0]}}
joints:
  - {{name: rail, type: prismatic, markers: [ground.P, s.cm], axis: [0, 1]}}
  - {{name: drive, type: driving, marker: s.cm, coordinate: y, motion: {{type: table, points: {0}}}}}
forces:
  - {{name: k, type: spring, markers: [ground.P, s.cm], k: 1000, free_length: 1}}
outputs:
  - {{name: y, type: position, marker: s.cm, component: y}}
  - {{name: v, type: velocity, marker: s.cm, component: y}}
  - {{name: a, type: acceleration, marker: s.cm, component: y}}
)",
                                       table);
  const mbs::Model model = io::parse_model(text, "slider.yaml");
  const mbs::TimeFunction f = model.joints[1].motion;
  ASSERT_EQ(f.kind, mbs::TimeFunction::Kind::Table);
  ASSERT_EQ(f.interpolation, mbs::TimeFunction::Interpolation::Spline);
  // The error bounds below are the integrator's (positions ~1 m): at rtol 1e-9 they sat on 1e-9 and a
  // change of rounding (an AVX2 build) crossed it; at 1e-11 they hold with a margin of ≈ 100.
  solve::IntegratorOptions o;
  o.rtol = 1e-11, o.atol = 1e-13;
  const auto s = inerta::testing::run(model, 2.5, 0.005, o);
  double ey = 0, ev = 0, ea = 0, amax = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    ey = std::max(ey, std::abs(s[0][i] - f.value(s.t[i])));
    ev = std::max(ev, std::abs(s[1][i] - f.d1(s.t[i])));
    ea = std::max(ea, std::abs(s[2][i] - f.d2(s.t[i])));
    amax = std::max(amax, std::abs(f.d2(s.t[i])));
  }
  EXPECT_LT(ey, 1e-9);
  EXPECT_LT(ev, 1e-8);
  EXPECT_LT(ea, 1e-6 * amax);
  // The table's points themselves.
  const double pts[][2] = {{0.3, 0.02}, {0.7, -0.01}, {1.1, 0.03}};
  for (const auto& p : pts) EXPECT_NEAR(f.value(p[0]), p[1], 1e-15);
  EXPECT_LT(s.stats.max_violation, 1e-9);
}

std::string driven_mass(const std::string& motion, const std::string& options = "") {
  return fmt::format(R"(name: driven
options: {{gravity: true{1}}}
ground:
  markers: {{P: [0, 0]}}
bodies:
  - {{name: base, mass: 1, inertia: 0.1, position: [0, 0]}}
  - {{name: top, mass: 2, inertia: 0.1, position: [0, 1]}}
joints:
  - {{name: rail, type: prismatic, markers: [ground.P, base.cm], axis: [0, 1]}}
  - {{name: rail2, type: prismatic, markers: [ground.P, top.cm], axis: [0, 1]}}
  - {{name: drive, type: driving, body: base, coordinate: y, motion: {0}}}
forces:
  - {{name: k, type: spring, markers: [base.cm, top.cm], k: 2000, free_length: 1}}
  - {{name: c, type: damper, markers: [base.cm, top.cm], c: 5}}
outputs:
  - {{name: v_base, type: velocity, marker: base.cm, component: y}}
  - {{name: v_top, type: velocity, marker: top.cm, component: y}}
)",
                     motion, options);
}

TEST(Driving, FromEquilibriumStartsWithTheDrivesVelocity) {
  const double slope = 0.2;
  const mbs::Model model = io::parse_model(driven_mass(fmt::format("{{type: ramp, slope: {}}}", slope)), "d.yaml");
  analysis::SimulateOptions so;
  so.t_end = 0.1, so.sample = 0.01, so.from_equilibrium = true;
  const analysis::Simulation r = analysis::simulate(model, so);
  EXPECT_NEAR(r.history.columns[0].front(), slope, 1e-12);  // the driven base moves at f′(0)
  EXPECT_NEAR(r.history.columns[1].front(), 0.0, 1e-12);    // the free mass starts at rest
  EXPECT_LT(r.stats.max_velocity_violation, 1e-8);
  // static_equilibrium alone keeps q̇ = 0; consistent_velocities adds the drive's.
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  EXPECT_EQ(x.qd.norm(), 0.0);
  mbs::consistent_velocities(model, 0.0, x);
  EXPECT_NEAR(x.qd[1], slope, 1e-12);
  EXPECT_NEAR(x.qd[4], 0.0, 1e-12);
}

TEST(Driving, DriftBeyondTheBoundFailsWithTimeAndJoint) {
  // A linear table with a velocity jump of 0.1/0.1 = 1 m/s at t = 0.5 s: the driven coordinate
  // follows only through the Baumgarte terms and lags by ≈ 0.1 m.
  const std::string lin =
      "{type: table, interpolation: linear, accept_linear: true, points: [[0, 0], [0.5, 0], [0.6, 0.1], [2, 0.1]]}";
  const mbs::Model model = io::parse_model(driven_mass(lin), "d.yaml");
  try {
    inerta::testing::run(model, 2.0, 0.01);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("joint 'drive' (equation 1)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("exceeds the bound 0.0001 (options.max_violation)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at t = 0.5"), std::string::npos) << msg;
  }
  // The bound is an option; .inf switches it off.
  const mbs::Model loose = io::parse_model(driven_mass(lin, ", max_violation: .inf"), "d.yaml");
  const auto s = inerta::testing::run(loose, 2.0, 0.01);
  EXPECT_GT(s.stats.max_violation, 0.01);
  // The same step as a smooth (spline) table stays on the constraint.
  const mbs::Model smooth = io::parse_model(
      driven_mass("{type: table, points: [[0, 0], [0.5, 0], [0.6, 0.1], [2, 0.1]]}"), "d.yaml");
  EXPECT_LT(inerta::testing::run(smooth, 2.0, 0.01).stats.max_violation, 1e-5);
}

}  // namespace
}  // namespace test_mbs_driving
