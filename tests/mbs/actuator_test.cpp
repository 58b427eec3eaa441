// The HSX pneumatic actuator element (spec/03 §3.3): constant force, piston mass at the rod end,
// Maxwell network, regularised Coulomb friction.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "inerta/mbs/network_strut.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_actuator {

using namespace inerta;

namespace {
// A slider (mass 20 kg) on a vertical rail, pushed up by an actuator from the ground point below.
std::string lift(const std::string& actuator) {
  return fmt::format(R"(
ground: {{markers: {{base: [0, 0]}}}}
bodies:
  - {{name: slider, mass: 20, inertia: 0.5, position: [0, 1]}}
joints:
  - {{name: rail, type: prismatic, markers: [ground.base, slider.cm], axis: [0, 1]}}
forces:
  - {{name: act, type: actuator, markers: [ground.base, slider.cm], {}}}
outputs:
  - {{name: y, type: coordinate, body: slider, component: y}}
  - {{name: F, type: force, element: act}}
)",
                     actuator);
}
}  // namespace

TEST(Actuator, ConstantForceBalancesWeightIncludingPistonMass) {
  const double g = 9.81, m = 20, mp = 3.45;
  mbs::Model model = io::parse_model(lift(fmt::format("constant_force: {}, piston_mass: {}", -(m + mp) * g, mp)), "a.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  EXPECT_NEAR(ws.qdd[1], 0.0, 1e-12);
  EXPECT_EQ(model.n_states(), 1);  // default dynamic network S2-default (Maxwell)
}

TEST(Actuator, PistonMassMovesWithTheRodEnd) {
  // Push with 100 N more than the weights: ÿ = 100 / (m + m_p); the Maxwell element is relaxed at t = 0.
  const double g = 9.81, m = 20, mp = 3.45;
  mbs::Model model =
      io::parse_model(lift(fmt::format("constant_force: {}, piston_mass: {}", -(m + mp) * g - 100, mp)), "a.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  EXPECT_NEAR(ws.qdd[1], 100 / (m + mp), 1e-12);
}

TEST(Actuator, MaxwellNetworkGivesItsAdmittance) {
  // At constant extension rate v the Maxwell element k1—c1 settles to F = c1 v (final-value theorem,
  // spec/03 §3.3): drive the slider at v and read the actuator force minus F_c.
  const double v = 0.005, c1 = 10.44e3, Fc = -1000;
  std::string text = lift(fmt::format("constant_force: {}", Fc));
  text.replace(text.find("forces:"), 7,
               "  - {name: drive, type: driving, body: slider, coordinate: y, motion: {type: table, points: [[0, 0], "
               "[10, 0.05]]}}\nforces:");
  mbs::Model model = io::parse_model(text, "a.yaml");
  solve::IntegratorOptions opt;
  opt.method = solve::Method::Bdf;
  opt.rtol = 1e-9;
  opt.atol = 1e-12;
  auto s = inerta::testing::run(model, 5, 0.01, opt);
  EXPECT_NEAR(s[1].back() - Fc, c1 * v, 1e-4 * c1 * v);
}

TEST(Actuator, FrictionIsRegularisedCoulomb) {
  const double Fr = 53, vr = 1e-3;
  std::string text = lift(fmt::format("friction: {}, friction_velocity: {}, network: c, params: {{c: 0}}", Fr, vr));
  text.replace(text.find("position: [0, 1]}"), 17, "position: [0, 1], velocity: [0, 0.002]}");
  mbs::Model model = io::parse_model(text, "a.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  EXPECT_NEAR(mbs::evaluate_output(model.outputs[1], model, 0.0, x, ws), Fr * std::tanh(0.002 / vr), 1e-9);
  // It only dissipates.
  EXPECT_LT(model.forces[1]->power(model, 0.0, x), 0.0);
}
}  // namespace test_mbs_actuator
