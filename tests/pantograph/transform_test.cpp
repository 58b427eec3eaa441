// Model transformations cannot leave stale state offsets (issue 11): the compile step places every
// element's internal states, so an element placed after the actuator survives suspension
// replacement and coupling.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include "inerta/analysis/simulate.hpp"
#include "inerta/error.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/model_study.hpp"
#include "inerta/pantograph/suspension.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_pantograph_transform {

using namespace inerta;

namespace {
// A head lifted by an actuator (network ACT), with a stateful network strut (a Maxwell k–c in
// series, one internal state) placed *after* the actuator in the file.
std::string model(const std::string& act) {
  return fmt::format(R"(
ground: {{markers: {{G: [0, 0], B: [0, 6]}}}}
bodies:
  - {{name: head, mass: 10, inertia: 0.1, position: [0, 5]}}
joints:
  - {{name: slide, type: prismatic, markers: [ground.G, head.cm], axis: [0, 1]}}
  - {{name: rig, type: driving, body: head, coordinate: y, motion: 0}}
forces:
  - {{name: act, type: actuator, markers: [ground.G, head.cm], constant_force: -168.1, {}}}
  - {{name: k, type: spring, markers: [ground.B, head.cm], k: 2000}}
  - {{name: tail, type: network, markers: [ground.B, head.cm], network: "k-c", params: {{k: 3000, c: 40}}}}
outputs:
  - {{name: y_head, type: coordinate, body: head, component: y}}
  - {{name: F_tail, type: force, element: tail}}
pantograph: {{contact: head.cm, rig_joint: rig}}
)",
                     act);
}
}  // namespace

TEST(Transform, StatefulElementAfterTheActuatorSurvivesSuspensionReplacementAndCoupling) {
  // From a Maxwell actuator network (1 state, tail's state at z[1]) to a spring–damper (0 states):
  // the tail's state must move to z[0]. The replaced model must equal the model written that way.
  pantograph::Pantograph from = io::parse_pantograph(model("network: S2-default"), "from.yaml");
  const pantograph::Pantograph written =
      io::parse_pantograph(model("network: \"k|c\", params: {k: 5000, c: 300}"), "written.yaml");
  const auto tail = static_cast<std::size_t>(from.model.find_force("tail")),
             act = static_cast<std::size_t>(from.model.find_force("act"));
  ASSERT_LT(act, tail);
  ASSERT_EQ(from.model.n_states(), 2);
  ASSERT_EQ(from.model.forces[tail]->state_offset(), 1);
  from.model = pantograph::with_suspension(from.model, network::resolve("k|c", {{"k", 5000}, {"c", 300}}));
  ASSERT_EQ(from.model.n_states(), 1);
  EXPECT_EQ(from.model.forces[tail]->state_offset(), 0);
  EXPECT_EQ(from.model.state_adr(static_cast<int>(tail)), 0);
  // Coupled to a lumped catenary, run both: every output agrees.
  const catenary::Lumped cat{catenary::LumpedCatenary{}};
  analysis::CoupledOptions o;
  o.spans = 3;
  const auto a = analysis::simulate_coupled({{from, 0.0, {}}}, cat, 40.0, o);
  const auto b = analysis::simulate_coupled({{written, 0.0, {}}}, cat, 40.0, o);
  ASSERT_EQ(a.histories[0].names, b.histories[0].names);
  const auto& Fa = a.histories[0].columns[1];
  const auto& Fb = b.histories[0].columns[1];
  ASSERT_EQ(Fa.size(), Fb.size());
  double spread = 0;
  for (double f : Fa) spread = std::max(spread, std::abs(f - Fa.front()));
  EXPECT_GT(spread, 1e-3);  // the tail strut works
  for (std::size_t i = 0; i < Fa.size(); ++i) ASSERT_NEAR(Fa[i], Fb[i], 1e-9 * (1 + std::abs(Fb[i]))) << i;
  // The other way round (more states before the tail) as well.
  pantograph::Pantograph back = written;
  back.model = pantograph::with_suspension(back.model, network::resolve("b-(k|c)", {{"b", 5}, {"k", 5000}, {"c", 300}}));
  EXPECT_EQ(back.model.forces[tail]->state_offset(), 2);  // after b-(k|c)'s two states
}

TEST(Transform, FinalizeRelocatesElementsWhoseOffsetsWentStale) {
  mbs::Model m = io::parse_model(model("network: S2-default"), "m.yaml");
  const auto a = static_cast<std::size_t>(m.find_force("act")), t = static_cast<std::size_t>(m.find_force("tail"));
  const auto tail = m.forces[t];
  std::swap(m.forces[a], m.forces[t]);  // the tail first, the actuator after it
  m.finalize();
  EXPECT_EQ(m.forces[a]->name(), "tail");
  EXPECT_EQ(m.forces[a]->state_offset(), 0);
  EXPECT_EQ(m.forces[t]->state_offset(), 1);
  EXPECT_EQ(tail->state_offset(), 1);  // the original element is untouched (shared by other models)
}

TEST(Transform, TheSuspensionIsTheLoadersActuatorHandle) {
  // The loader records the actuator's index (mbs::Model::actuators); the suspension is found by it,
  // a model with two actuators is ambiguous, and a strut removed before it moves the handle along.
  const mbs::Model m = io::parse_model(model("network: S2-default"), "m.yaml");
  ASSERT_EQ(m.actuators, std::vector<int>{m.find_force("act")});
  EXPECT_EQ(pantograph::suspension_index(m), m.find_force("act"));
  const mbs::Model s = pantograph::with_suspension(m, network::resolve("k|c", {{"k", 5000}, {"c", 300}}), 0.75);
  EXPECT_EQ(s.actuators, m.actuators);
  const auto& act = s.forces[static_cast<std::size_t>(pantograph::suspension_index(s))];
  EXPECT_EQ(act->name(), "act");
  EXPECT_EQ(network::to_string(*act->strut_network(), false), "k|c");
  // An open tail strut before the actuator: removed, the actuator's index follows.
  std::string two = model("network: S2-default");
  const std::string line = "  - {name: act,";
  const auto at = two.find(line);
  ASSERT_NE(at, std::string::npos);
  two.insert(at, "  - {name: pre, type: network, markers: [ground.B, head.cm], network: \"c\", params: {c: 0}}\n");
  const mbs::Model pre = io::parse_model(two, "pre.yaml");
  const int p = pre.find_force("pre"), a = pre.find_force("act");
  ASSERT_EQ(a, p + 1);
  ASSERT_EQ(pre.actuators, std::vector<int>{a});
  const mbs::Model cut = optim::with_strut_network(pre, p, network::resolve("c", {{"c", 0}}));
  EXPECT_EQ(cut.forces.size(), pre.forces.size() - 1);
  EXPECT_EQ(cut.actuators, std::vector<int>{p});
  EXPECT_EQ(cut.forces[static_cast<std::size_t>(p)]->name(), "act");
  // Two actuators: the suspension is ambiguous.
  std::string both = model("network: S2-default");
  both.insert(both.find(line), "  - {name: act2, type: actuator, markers: [ground.B, head.cm], network: \"k\", params: {k: 1}}\n");
  const mbs::Model ambiguous = io::parse_model(both, "two.yaml");
  EXPECT_EQ(ambiguous.actuators.size(), 2u);
  try {
    (void)pantograph::with_suspension(ambiguous, network::resolve("k", {{"k", 1}}));
    ADD_FAILURE() << "two actuators accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("more than one actuator"), std::string::npos) << e.what();
  }
}
}  // namespace test_pantograph_transform
