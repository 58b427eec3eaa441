// Assembly (Newton on C(q) = 0 with held coordinates), static equilibrium against analytic
// solutions, and the singular-system errors (spec/02 §2.4).
#include <gtest/gtest.h>

#include <cmath>

#include "inerta/error.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_assembly {

using namespace inerta;

TEST(Assembly, CorrectsGapsAndHonoursHeldCoordinates) {
  mbs::Model m = io::load_model(inerta::testing::model_path("twobar.yaml"));
  m.bodies[1].q0 += mbs::Vec3(0.01, -0.02, 0.03);  // open gaps at B
  m.held = {2};                                    // hold bar1.theta
  mbs::AssemblyReport rep;
  mbs::State x = mbs::assemble(m, 0.0, &rep);
  mbs::Workspace ws(m);
  mbs::evaluate_constraints(m, 0.0, x, ws);
  EXPECT_GT(rep.initial_residual, 0.01);
  EXPECT_LT(ws.C.cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(x.q[2], m.bodies[0].q0.z());  // held exactly
  EXPECT_GT(rep.dq.cwiseAbs().maxCoeff(), 0.005);
  EXPECT_LT(rep.iterations, 10);
  // Velocities are projected onto C_q q̇ + C_t = 0.
  EXPECT_LT((ws.Cq * x.qd + ws.Ct).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Equilibrium, HangingMassOnSpring) {
  // Mass m on a vertical slider hanging from a spring: y_eq = y_top − L0 − m g / k.
  const char* text = R"(
ground: {markers: {top: [0, 2]}}
bodies:
  - {name: m, mass: 3, inertia: 0.1, position: [0, 1]}
joints:
  - {name: slide, type: prismatic, markers: [ground.top, m.cm], axis: [0, 1]}
forces:
  - {name: k, type: spring, markers: [ground.top, m.cm], k: 500, free_length: 0.9}
)";
  mbs::Model model = io::parse_model(text, "hanging.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  EXPECT_NEAR(x.q[1], 2 - 0.9 - 3 * 9.81 / 500, 1e-9);
  // And it stays there.
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0, x, ws);
  EXPECT_LT(ws.qdd.cwiseAbs().maxCoeff(), 1e-8);
}

TEST(Equilibrium, PendulumWithRotationalSpring) {
  // Uniform bar (m, L) pinned at one end, rotational spring k (undeformed horizontal):
  // k θ + m g (L/2) cos θ = 0. Solve by bisection here and compare.
  const double m = 2, L = 1, k = 40, g = 9.81;
  const char* text = R"(
ground: {markers: {O: [0, 0]}}
bodies:
  - {name: bar, mass: 2, inertia: 0.1667, position: [0.5, 0], markers: {a: [-0.5, 0]}}
joints:
  - {name: O, type: revolute, markers: [ground.O, bar.a]}
forces:
  - {name: k, type: rotational_spring, joint: O, k: 40, angle0: 0}
)";
  mbs::Model model = io::parse_model(text, "pendulum.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::EquilibriumReport rep;
  mbs::static_equilibrium(model, 0.0, x, &rep);
  double lo = -M_PI / 2, hi = 0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (k * mid + m * g * L / 2 * std::cos(mid) > 0 ? hi : lo) = mid;
  }
  EXPECT_NEAR(x.q[2], lo, 1e-9);
  EXPECT_NEAR(x.q[0], 0.5 * std::cos(lo), 1e-9);
  EXPECT_GT(rep.iterations, 0);
}

TEST(Equilibrium, UnbalancedLoadIsReported) {
  // A slider pushed along its free axis has no equilibrium: a clear error, not a guess.
  const char* text = R"(
ground: {markers: {O: [0, 0]}}
bodies:
  - {name: slider, mass: 2, inertia: 0.2, position: [0, 0]}
joints:
  - {name: rail, type: prismatic, markers: [ground.O, slider.cm], axis: [1, 0]}
forces:
  - {name: push, type: point_force, marker: slider.cm, direction: [1, 0], value: 10}
)";
  mbs::Model model = io::parse_model(text, "pushed.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  try {
    mbs::static_equilibrium(model, 0.0, x);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("static equilibrium"), std::string::npos) << e.what();
  }
}

TEST(Singular, RedundantJointsStopWithTimeAndReason) {
  const char* text = R"(
ground: {markers: {O: [0, 0]}}
bodies:
  - {name: bar, mass: 2, inertia: 0.2, position: [0.5, 0], markers: {a: [-0.5, 0]}}
joints:
  - {name: O1, type: revolute, markers: [ground.O, bar.a]}
  - {name: O2, type: revolute, markers: [ground.O, bar.a]}
)";
  mbs::Model model = io::parse_model(text, "redundant.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  try {
    mbs::accelerations(model, 0.25, x, ws);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("t = 0.25 s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

TEST(Singular, MasslessUnconstrainedBodyIsReported) {
  const char* text = R"(
options: {gravity: false}
bodies:
  - {name: ghost, mass: 0, inertia: 0, position: [0, 0]}
)";
  mbs::Model model = io::parse_model(text, "ghost.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  EXPECT_THROW(mbs::accelerations(model, 0.0, x, ws), NumericalError);
}

TEST(Singular, ZeroInertiaBodyWithLockedRotationUsesTheFullSystem) {
  // M is singular (no inertia) but eq. 4.12 is not: the LU fallback must give the right answer.
  const char* text = R"(
ground: {markers: {G: [0, 0]}}
bodies:
  - {name: head, mass: 4, inertia: 0, position: [0, 1]}
joints:
  - {name: slide, type: prismatic, markers: [ground.G, head.cm], axis: [0, 1]}
forces:
  - {name: k, type: spring, markers: [ground.G, head.cm], k: 100, free_length: 1.5}
)";
  mbs::Model model = io::parse_model(text, "head.yaml");
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  EXPECT_NEAR(ws.qdd[1], (100 * 0.5 - 4 * 9.81) / 4, 1e-10);
  EXPECT_NEAR(ws.qdd[0], 0, 1e-10);
  EXPECT_NEAR(ws.qdd[2], 0, 1e-10);
}
}  // namespace test_mbs_assembly
