// models/hsx.yaml — the Brecknell Willis HSX pantograph (spec/04 §4.1, docs/models/hsx.md):
// Table 6.2 mass preserved by the upper-arm split, small assembly corrections, and the static
// contact force of 70 N with the head held by the driving joint `contact`.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/output.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_pantograph_hsx_model {

using namespace inerta;

namespace {

const std::string kPath = std::string(INERTA_SOURCE_DIR) + "/models/hsx.yaml";

int output_index(const mbs::Model& model, const std::string& name) {
  for (std::size_t k = 0; k < model.outputs.size(); ++k)
    if (model.outputs[k].name == name) return static_cast<int>(k);
  return -1;
}

double contact_force(const mbs::Model& model, const mbs::State& x) {
  const int k = output_index(model, "F_contact");
  EXPECT_GE(k, 0);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  return mbs::evaluate_output(model.outputs[static_cast<std::size_t>(k)], model, 0.0, x, ws);
}

}  // namespace

TEST(HsxModel, TotalMassIsTable62) {
  mbs::Model model = io::load_model(kPath);
  // Table 6.2: base, lower arm, upper arm (split into lever + main span), lower link, upper link,
  // stability arm, head.
  const double table = 41.93 + 17.18 + 11.33 + 3.75 + 2.09 + 5.57 + 5.41;
  double total = 0;
  for (const auto& b : model.bodies) total += b.mass;
  EXPECT_NEAR(total, table, 1e-9);
  const int lever = model.find_body("upper_lever"), span = model.find_body("upper_arm");
  ASSERT_GE(lever, 0);
  ASSERT_GE(span, 0);
  EXPECT_NEAR(model.bodies[lever].mass + model.bodies[span].mass, 11.33, 1e-9);
  // frame + flexible upper arm; the head is held by `contact`
  EXPECT_EQ(model.dof(), 2);
}

TEST(HsxModel, AssemblyCorrectionBelow5mm) {
  mbs::Model model = io::load_model(kPath);
  mbs::AssemblyReport rep;
  mbs::State x = mbs::assemble(model, 0.0, &rep);
  EXPECT_LT(rep.residual, 1e-12);
  EXPECT_GT(rep.initial_residual, 1e-3);  // the tables do not close exactly (gaps at E and F)
  // Every body's centre of mass and every marker (all joint and force points) moves < 5 mm.
  double max_move = 0;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    max_move = std::max(max_move, std::hypot(rep.dq[3 * b], rep.dq[3 * b + 1]));
  const Eigen::VectorXd q0 = model.q0();
  for (const auto& m : model.markers) {
    if (m.body < 0) continue;
    auto at = [&](const Eigen::VectorXd& q) {
      const double th = q[3 * m.body + 2];
      return mbs::Vec2(q[3 * m.body] + std::cos(th) * m.u.x() - std::sin(th) * m.u.y(),
                       q[3 * m.body + 1] + std::sin(th) * m.u.x() + std::cos(th) * m.u.y());
    };
    max_move = std::max(max_move, (at(x.q) - at(q0)).norm());
  }
  EXPECT_LT(max_move, 5e-3);
}

TEST(HsxModel, StaticContactForceIs70N) {
  mbs::Model model = io::load_model(kPath);
  mbs::State x = mbs::assemble(model, 0.0);
  // In the assembled configuration the head is held at its tabulated height with the suspension
  // preloaded for 70 N.
  EXPECT_NEAR(contact_force(model, x), 70.0, 0.7);

  mbs::EquilibriumReport rep;
  mbs::static_equilibrium(model, 0.0, x, &rep);
  EXPECT_LT(rep.force_residual, 1e-6);
  EXPECT_LT(rep.max_move, 0.02);  // the flexible arm sags by a few mm, no more
  const double F = contact_force(model, x);
  EXPECT_NEAR(F, 70.0, 0.7);

  // At the equilibrium nothing accelerates.
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  EXPECT_LT(ws.qdd.cwiseAbs().maxCoeff(), 1e-6);
}
}  // namespace test_pantograph_hsx_model
