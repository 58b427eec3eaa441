// Lanes (issue 50 item 1): several designs' trains stepped together on one finite-element line give
// each train's lone run bit for bit — every sample's contact force, state, wire uplift (each wire's
// on a line of sections) and the supports' uplift — on the simple, stitched, irregular, overlap and
// direct-solve lines, for the 3-mass and the HSX; a lane that fails stops alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_catenary_fe_lanes {

using namespace inerta;
using catenary::PantographOnLine;

// What a run gives, every sample of every contact in order, as raw numbers.
struct Trace {
  std::vector<double> v;
  void add(const catenary::Sample& s, const catenary::Coupled& sys) {
    v.push_back(s.t), v.push_back(s.x_contact), v.push_back(s.force), v.push_back(s.wire_uplift);
    for (int w = 0; w < 2; ++w) v.push_back(s.force_wire[static_cast<std::size_t>(w)]), v.push_back(s.uplift_wire[static_cast<std::size_t>(w)]);
    for (Eigen::Index i = 0; i < s.state.q.size(); ++i) v.push_back(s.state.q[i]), v.push_back(s.state.qd[i]);
    for (Eigen::Index i = 0; i < s.state.z.size(); ++i) v.push_back(s.state.z[i]);
    if (s.contact.index == 0)
      for (double u : sys.support_uplift()) v.push_back(u);
  }
};

// Byte for byte (NaN where the lone run has NaN).
bool same(const Trace& a, const Trace& b) {
  return a.v.size() == b.v.size() && std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(double)) == 0;
}

const solve::IntegratorOptions kOptions{};

Trace lone(const catenary::Catenary& cat, const std::vector<PantographOnLine>& train, double speed, double t_end, double dt) {
  auto sys = cat.couple(train, speed);
  sys->equilibrate();
  Trace tr;
  sys->advance(t_end, dt, kOptions, [&](const catenary::Sample& s) { tr.add(s, *sys); });
  return tr;
}

// The trains as lanes; `fail_lane` >= 0: that lane's observer throws from time `fail_at` on.
std::vector<Trace> lanes(const catenary::Catenary& cat, const std::vector<std::vector<PantographOnLine>>& trains, double speed,
                         double t_end, double dt, int fail_lane = -1, double fail_at = 0) {
  auto L = cat.couple_lanes(trains, speed);
  EXPECT_EQ(L->lanes(), static_cast<int>(trains.size()));
  for (int i = 0; i < L->lanes(); ++i) L->lane(i).equilibrate();
  std::vector<Trace> tr(trains.size());
  L->advance(t_end, dt, kOptions, [&](int i, const catenary::Sample& s) {
    if (i == fail_lane && s.t >= fail_at) throw std::runtime_error("this lane's observer gives up");
    tr[static_cast<std::size_t>(i)].add(s, L->lane(i));
  });
  for (int i = 0; i < L->lanes(); ++i) EXPECT_EQ(static_cast<bool>(L->error(i)), i == fail_lane) << "lane " << i;
  return tr;
}

const catenary::Contact kPenalty{catenary::Contact::Kind::Penalty, 50e3, 0.0};

// A design of the pantograph: its head's constant uplift raised by dF (N); with `net`, its suspension too.
pantograph::Pantograph design(pantograph::Pantograph p, double dF, const std::string& net = {}) {
  if (!p.aero.active()) p.aero.body = p.contact().body;
  p.aero.c += dF;
  if (!net.empty()) p.model = pantograph::with_suspension(p.model, network::resolve(net, {{"k", 5e3}, {"k2", 1e5}, {"c", 3e3}}));
  return p;
}

// Three designs (the model, +15 N, −10 N and with `net` when given) at positions xs, as lanes and alone.
void expect_lanes_are_lone_runs(const catenary::Catenary& cat, const std::string& model, const std::vector<double>& xs,
                                double speed, double t_end, const std::string& net = {}) {
  const auto panto = io::load_pantograph(std::string(INERTA_SOURCE_DIR "/models/") + model);
  std::vector<std::vector<PantographOnLine>> trains;
  for (const auto& [dF, n] : std::vector<std::pair<double, std::string>>{{0.0, ""}, {15.0, net}, {-10.0, ""}}) {
    std::vector<PantographOnLine> t;
    for (double x : xs) t.push_back({design(panto, dF, n), x, kPenalty});
    trains.push_back(t);
  }
  const double dt = 1e-3;
  const std::vector<Trace> together = lanes(cat, trains, speed, t_end, dt);
  for (std::size_t i = 0; i < trains.size(); ++i) {
    const Trace alone = lone(cat, trains[i], speed, t_end, dt);
    EXPECT_GT(alone.v.size(), 1000u);
    EXPECT_TRUE(same(together[i], alone)) << model << ", lane " << i << ": " << together[i].v.size() << " numbers, alone "
                                          << alone.v.size();
  }
  // The designs differ (the comparison above is not of three equal runs).
  EXPECT_FALSE(same(together[0], together[1]));
  // A lane that fails stops alone: the others as before.
  const std::vector<Trace> failed = lanes(cat, trains, speed, t_end, dt, 1, 0.3 * t_end);
  EXPECT_TRUE(same(failed[0], together[0]));
  EXPECT_TRUE(same(failed[2], together[2]));
}

const std::string kModels = INERTA_SOURCE_DIR "/models/";

TEST(FeLanes, OnTheSimpleLineEachLaneIsItsLoneRunBitForBit) {
  const auto c = io::load_catenary(kModels + "catenary-fe.yaml", {"line.spans=8", "solver.cutoff=60"});
  expect_lanes_are_lone_runs(*c.catenary, "pantograph-3mass.yaml", {0.0}, 250 / 3.6, 2.0);
}

TEST(FeLanes, OnTheStitchedAndIrregularLinesTooWithTheHsxAndAnotherSuspension) {
  // Fewer modes and a shorter window than the file's: the decompositions of a test (the property does
  // not depend on them).
  const std::vector<std::string> small = {"line.spans=8", "solver.cutoff=60", "solver.window_ahead=3"};
  const auto c = io::load_catenary(kModels + "catenary-fe-stitched.yaml", small);
  expect_lanes_are_lone_runs(*c.catenary, "hsx.yaml", {0.0}, 300 / 3.6, 2.5, "k|(k2-c)");
  std::vector<std::string> irregular = small;
  irregular.insert(irregular.end(), {"irregularity.dropper_length_std=0.01", "irregularity.seed=2"});
  const auto irr = io::load_catenary(kModels + "catenary-fe-stitched.yaml", irregular);
  expect_lanes_are_lone_runs(*irr.catenary, "pantograph-3mass.yaml", {0.0}, 250 / 3.6, 2.0);
}

TEST(FeLanes, TwoPantographsThroughAnOverlapEachLaneIsItsLoneRun) {
  catenary::FeCatenaryData d = io::read_fe_catenary_data(kModels + "catenary-fe-overlap.yaml", {});
  d.tension_sections.resize(2);
  for (catenary::FeCatenaryData& s : d.tension_sections) s.spans = 6;
  d.modal_cutoff = 60, d.window_ahead = 3;  // the decompositions of a test
  d.join_sections();
  const catenary::FeCatenary cat(d);
  // The leading pantograph through the overlap's middle span (masts 4–5 of 9): both wires, both sections.
  expect_lanes_are_lone_runs(cat, "pantograph-3mass.yaml", {60.0, 200.0}, 250 / 3.6, (5 * d.span - 200) / (250 / 3.6));
}

TEST(FeLanes, OnADirectSolveLineEachLaneIsItsLoneRun) {
  const auto c = io::load_catenary(kModels + "catenary-fe.yaml", {"line.spans=4", "solver.type=direct"});
  expect_lanes_are_lone_runs(*c.catenary, "pantograph-3mass.yaml", {0.0}, 250 / 3.6, 1.0);
}

TEST(FeLanes, TrainsAtOtherPlacesAreRefusedAndALaneAloneCannotAdvance) {
  const auto c = io::load_catenary(kModels + "catenary-fe.yaml", {"line.spans=6"});
  const auto panto = io::load_pantograph(kModels + "pantograph-3mass.yaml");
  EXPECT_THROW((void)c.catenary->couple_lanes({{{panto, 0.0, kPenalty}}, {{panto, 10.0, kPenalty}}}, 70.0), InvalidArgument);
  EXPECT_THROW((void)c.catenary->couple_lanes({}, 70.0), InvalidArgument);
  try {  // a NaN position is named as couple names it, not as a mismatch between trains
    (void)c.catenary->couple_lanes({{{panto, NAN, kPenalty}}, {{panto, NAN, kPenalty}}}, 70.0);
    ADD_FAILURE() << "a NaN x0 was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("position x0 = nan"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)c.catenary->couple_lanes({{{panto, 0.0, kPenalty}}}, -70.0), InvalidArgument);
  auto L = c.catenary->couple_lanes({{{panto, 0.0, kPenalty}}, {{panto, 0.0, kPenalty}}}, 70.0);
  L->lane(0).equilibrate();
  EXPECT_THROW(L->lane(0).advance(0.1, 1e-3, kOptions, {}), std::logic_error);
}

}  // namespace test_catenary_fe_lanes
