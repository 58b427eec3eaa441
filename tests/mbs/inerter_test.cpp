// The inerter force (eq. 3.20) against the Cartesian formula eq. 3.10, and the spinning
// constant-length inerter that must produce no force (spec/01 §1.1).
#include <gtest/gtest.h>

#include <random>

#include "inerta/mbs/struts.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_inerter {

using namespace inerta;
using namespace inerta::mbs;

namespace {
const char* kTwoBodies = R"(
options: {gravity: false, centripetal: CORR}
bodies:
  - {name: b1, mass: 2, inertia: 0.3, position: [0, 0], markers: {p: [0.4, 0.1]}}
  - {name: b2, mass: 1, inertia: 0.2, position: [1.5, 0.5], markers: {q: [-0.3, 0.2]}}
forces:
  - {name: b, type: inerter, markers: [b1.p, b2.q], b: 7}
)";

Model two_bodies(bool corr) {
  std::string t = kTwoBodies;
  t.replace(t.find("CORR"), 4, corr ? "true" : "false");
  return io::parse_model(t, "two-bodies.yaml");
}
}  // namespace

TEST(Inerter, ForceEqualsEquation3_10ForRandomStates) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (bool corr : {true, false}) {
    Model model = two_bodies(corr);
    Workspace ws(model);
    const auto& inerter = *model.forces[0];
    for (int trial = 0; trial < 50; ++trial) {
      State x{Eigen::VectorXd(6), Eigen::VectorXd(6), {}};
      x.q << u(rng), u(rng), u(rng), 3 + u(rng), u(rng), u(rng);
      for (int k = 0; k < 6; ++k) x.qd[k] = u(rng);
      Eigen::VectorXd qdd(6);
      for (int k = 0; k < 6; ++k) qdd[k] = 3 * u(rng);
      ws.set_state(x);
      ws.qdd = qdd;
      double F = inerter.force(model, 0.0, x, ws);
      // Terminal kinematics of each point: r, ṙ, r̈ from rigid-body formulas.
      auto terminal = [&](int b, Vec2 u_local, Vec2& r, Vec2& v, Vec2& a) {
        double th = x.q[3 * b + 2], w = x.qd[3 * b + 2], al = qdd[3 * b + 2];
        Vec2 Au = rotate(th, u_local), perp(-Au.y(), Au.x());
        r = x.q.segment<2>(3 * b) + Au;
        v = x.qd.segment<2>(3 * b) + w * perp;
        a = qdd.segment<2>(3 * b) + al * perp - w * w * Au;
      };
      Vec2 ri, vi, ai, rj, vj, aj;
      terminal(0, Vec2(0.4, 0.1), ri, vi, ai);
      terminal(1, Vec2(-0.3, 0.2), rj, vj, aj);
      Vec2 r = rj - ri, rd = vj - vi, rdd = aj - ai;
      const double b = 7, l2 = r.squaredNorm(), l = std::sqrt(l2);
      // eq. 3.10 (2D): F = b/l { (ẍx + ÿy) + (ẋ² + ẏ²) − (ẋx + ẏy)²/(x² + y²) }; eq. 3.8 without correction.
      double F_ref = corr ? b / l * (rdd.dot(r) + rd.squaredNorm() - std::pow(rd.dot(r), 2) / l2) : b / l * rdd.dot(r);
      EXPECT_NEAR(F, F_ref, 1e-10 * std::max(1.0, std::abs(F_ref)));
    }
  }
}

TEST(Inerter, MassTermIsRankOneAndMatchesForce) {
  // eq. 3.33: F = b l̈ must equal what the assembled M_I and Q_Iv produce for any q̈.
  Model model = two_bodies(true);
  Workspace ws(model);
  State x{Eigen::VectorXd(6), Eigen::VectorXd(6), {}};
  x.q << 0.1, -0.2, 0.3, 1.4, 0.6, -0.5;
  x.qd << 0.5, -1, 2, 0.3, 0.7, -1.5;
  evaluate_forces(model, 0, x, ws);
  Eigen::MatrixXd MI = ws.M;
  MI.diagonal() -= Eigen::VectorXd((Eigen::VectorXd(6) << 2, 2, 0.3, 1, 1, 0.2).finished());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(MI);
  EXPECT_GT(svd.singularValues()[0], 1.0);
  EXPECT_LT(svd.singularValues()[1], 1e-12);
  Eigen::VectorXd qdd = Eigen::VectorXd::LinSpaced(6, -1, 2);
  ws.qdd = qdd;
  double F = model.forces[0]->force(model, 0, x, ws);
  StrutKinematics s = static_cast<const Strut&>(*model.forces[0]).kinematics(model, x);
  // Q_I = −F Jᵀ = −M_I q̈ + Q_Iv  (eq. 3.31)
  Eigen::VectorXd QI = -MI * qdd + ws.Q;
  EXPECT_LT((QI + F * Eigen::VectorXd(s.J)).cwiseAbs().maxCoeff(), 1e-10);
}

namespace {
// A bar pinned at its centre to the pivot O spins freely; an inerter joins O to the bar's tip,
// so its length is constant (R) while its axis rotates at ω.
const char* kSpinner = R"(
options: {gravity: false}
ground: {markers: {O: [0, 0]}}
bodies:
  - {name: bar, mass: 1, inertia: 0.1, position: [0, 0], angular_velocity: 3, markers: {tip: [0.5, 0]}}
joints:
  - {name: pivot, type: revolute, markers: [ground.O, bar.cm]}
forces:
  - {name: b, type: inerter, markers: [ground.O, bar.tip], b: 20}
outputs:
  - {name: F, type: force, element: b}
  - {name: w, type: coordinate, body: bar, component: theta}
)";
}  // namespace

TEST(Inerter, SpinningAtConstantLengthProducesNoForce) {
  const double b = 20, R = 0.5, w = 3;
  for (bool corr : {true, false}) {
    Model model = io::parse_model(kSpinner, "spinner.yaml");
    model.options.centripetal = corr;
    auto s = inerta::testing::run(model, 2, 0.01);
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      // With the correction F = b l̈ = 0; the 1D form gives b r̈·ê = −b ω² R (spec/01 §1.1).
      EXPECT_NEAR(s[0][i], corr ? 0.0 : -b * w * w * R, 1e-6 * b * w * w * R) << "t = " << s.t[i];
      EXPECT_NEAR(s[1][i], w * s.t[i], 1e-6);  // the spin is undisturbed either way
    }
  }
}

TEST(Inerter, PerElementSwitchTurnsCorrectionOff) {
  std::string text = kSpinner;
  text.replace(text.find("b: 20}"), 6, "b: 20, centripetal: false}");
  Model model = io::parse_model(text, "spinner.yaml");
  auto s = inerta::testing::run(model, 0.5, 0.1);
  EXPECT_NEAR(s[0].back(), -20 * 9 * 0.5, 1e-6);
}
}  // namespace test_mbs_inerter
