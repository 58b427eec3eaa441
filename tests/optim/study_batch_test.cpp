// Designs in batches (issue 50): evaluate_batch, design_costs and run_checks give each design what
// evaluate, design_cost and run_check give it alone, bit for bit — the time domain through lanes on a
// finite-element line (commissioned or not, a failing design among good ones, more designs than a chunk),
// the periodic fast path and the time domain on a lumped line one after another.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <tuple>
#include <string>
#include <typeinfo>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/optim/study_run.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_batch {

using namespace inerta;
using inerta::testing::write_study;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
// A short FE line (3 spans, modes below 30 Hz) at two tensions and two speeds.
const std::string kFe = "name: batch FE\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                        "/models/catenary-fe.yaml\n"
                        "catenaries: [[line.spans=3, solver.cutoff=30], [line.spans=3, solver.cutoff=30, "
                        "contact_wire.tension=24200]]\n"
                        "speeds: {from: 180, to: 220, step: 40, unit: kmh}\n"
                        "layouts: [S2-5]\n";
// The same line commissioned (issue 49): trimmed on the reference line, judged by the AC set.
const std::string kCommissioned = "name: batch commissioned\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                                  "/models/catenary-fe.yaml\n"
                                  "catenaries: [[line.spans=3, solver.cutoff=30, contact_wire.tension=18900],\n"
                                  "             [line.spans=3, solver.cutoff=30, contact_wire.tension=23100]]\n"
                                  "reference: [line.spans=3, solver.cutoff=30]\n"
                                  "speeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                                  "limits: {acceptance: en50367-ac}\n"
                                  "trim: {aerodynamic_at: {speed: 200, unit: kmh}}\n"
                                  "objective: {type: sigma_over_mean}\n"
                                  "layouts: [S2-5]\n";
const std::string kLumped = "name: batch lumped\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                            "/models/catenary.yaml\n"
                            "speeds: {from: 100, to: 300, step: 100, unit: kmh}\n"
                            "layouts: [S2-5]\n";

using Field = std::tuple<const char*, double, double>;

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(same(a[i], b[i])) << what << "[" << i << "]";
}

// Every field of two costs: doubles bit for bit, strings equal.
void expect_same(const optim::StudyCost& a, const optim::StudyCost& b, const std::string& what) {
  for (auto [name, x, y] : std::initializer_list<Field>{{"J", a.J, b.J}, {"speed", a.speed, b.speed}, {"mean", a.mean, b.mean},
                            {"unstable_speed", a.unstable_speed, b.unstable_speed}, {"floquet", a.floquet, b.floquet},
                            {"excess", a.excess, b.excess}, {"binding_margin", a.binding_margin, b.binding_margin},
                            {"mean_min", a.mean_min, b.mean_min}, {"mean_max", a.mean_max, b.mean_max},
                            {"loss_pct", a.loss_pct, b.loss_pct}, {"statistical_min", a.statistical_min, b.statistical_min},
                            {"uplift", a.uplift, b.uplift}, {"sigma", a.sigma, b.sigma}})
    EXPECT_TRUE(same(x, y)) << what << ": " << name << " " << x << " vs " << y;
  EXPECT_EQ(a.catenary, b.catenary) << what;
  EXPECT_EQ(a.feasible, b.feasible) << what;
  EXPECT_EQ(a.violation, b.violation) << what;
  EXPECT_EQ(a.binding, b.binding) << what;
  ASSERT_EQ(a.commissioning.has_value(), b.commissioning.has_value()) << what;
  if (!a.commissioning) return;
  const analysis::Commissioning &p = *a.commissioning, &q = *b.commissioning;
  for (auto [name, x, y] : std::initializer_list<Field>{{"operating_length", p.operating_length, q.operating_length},
                            {"static_stiffness", p.static_stiffness, q.static_stiffness},
                            {"static_force", p.static_force, q.static_force}, {"head_offset", p.head_offset, q.head_offset},
                            {"a", p.a, q.a}, {"mean", p.mean, q.mean}, {"mean_without", p.mean_without, q.mean_without},
                            {"target", p.target, q.target}})
    EXPECT_TRUE(same(x, y)) << what << ": commissioning " << name << " " << x << " vs " << y;
  EXPECT_EQ(p.trimmed, q.trimmed) << what;
  EXPECT_EQ(p.reached, q.reached) << what;
  EXPECT_EQ(p.runs, q.runs) << what;
  expect_same(p.range_height, q.range_height, what + " range_height");
  expect_same(p.range_force, q.range_force, what + " range_force");
  expect_same(p.range_model, q.range_model, what + " range_model");
}

// What evaluating a design alone gives: its cost, or its exception's type and message.
struct Alone {
  optim::StudyCost cost;
  std::string type, message;
};
template <class F>
Alone alone(F&& evaluate) {
  Alone a;
  try {
    a.cost = evaluate();
  } catch (const std::exception& e) {
    a.type = typeid(e).name(), a.message = e.what();
  }
  return a;
}

void expect_same(const optim::BatchEvaluation& got, const Alone& want, const std::string& what) {
  if (!want.message.empty()) {
    ASSERT_TRUE(got.error) << what << " should fail: " << want.message;
    try {
      got.get();
    } catch (const std::exception& e) {
      EXPECT_EQ(typeid(e).name(), want.type) << what;
      EXPECT_EQ(e.what(), want.message) << what;
    }
    return;
  }
  ASSERT_FALSE(got.error) << what << " failed in the batch";
  expect_same(got.cost, want.cost, what);
}

network::Network net(const std::string& layout, const network::Params& values) { return network::resolve(layout, values); }

// Good designs of several structures, a rigid one (refused by design_pantographs) and one whose run fails
// (an almost rigid link in series with a vanishing damper: a singular constraint Jacobian).
std::vector<network::Network> designs(const optim::Study& s, bool many) {
  std::vector<network::Network> d{optim::default_suspension(s),
                                  net("k", {{"k", 1e4}}),
                                  net("k", {{"k", INFINITY}}),
                                  net("c", {{"c", 1e3}}),
                                  net("k-c", {{"k", 1e9}, {"c", 1e-3}}),
                                  net("b|c", {{"b", 10}, {"c", 100}})};
  if (many)  // more than a chunk: the second chunk has a good and a failing design too
    for (const network::Network& n : {net("k-(b|c)", {{"k", 5e4}, {"b", 5}, {"c", 500}}), net("c|k", {{"c", 2e3}, {"k", 3e3}}),
                                      net("b", {{"b", 20}}), net("k-c", {{"k", 1e9}, {"c", 1e-3}}),
                                      net("k-c", {{"k", 8e4}, {"c", 6e3}})})
      d.push_back(n);
  return d;
}
}  // namespace

TEST(StudyBatch, ATimeDomainBatchOnTheFeLineEqualsEvaluateOneByOneBitForBit) {
  const optim::Study s = io::load_study(write_study("batch_fe.yaml", kFe));
  ASSERT_EQ(s.method, optim::Study::Method::Time);
  const std::vector<network::Network> d = designs(s, true);
  ASSERT_GT(d.size(), optim::lane_chunk);
  const std::vector<optim::BatchEvaluation> got = optim::evaluate_batch(s, d);
  ASSERT_EQ(got.size(), d.size());
  int failed = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    const Alone want = alone([&] { return optim::evaluate(s, d[k]); });
    failed += !want.message.empty();
    expect_same(got[k], want, "design " + std::to_string(k) + " " + network::to_string(d[k], true));
  }
  EXPECT_EQ(failed, 3);  // the rigid one and the two singular ones
  EXPECT_TRUE(optim::evaluate_batch(s, {}).empty());
}

TEST(StudyBatch, DesignCostsAndChecksOfABatchEqualThoseOneByOne) {
  const optim::Study s = io::load_study(write_study("batch_fe_costs.yaml", kFe));
  // design_costs: the search's cost (rigid and no design: ∞), as design_cost.
  const std::vector<network::Params> params{{{"k", 1e4}, {"c", 2e3}}, {{"k", INFINITY}, {"c", 1}}, {{"k", 1e9}, {"c", 1e-3}},
                                            {{"k", 5e4}, {"c", 8e3}}};
  const std::vector<optim::DesignCost> costs = optim::design_costs(s, "k-c", params);
  ASSERT_EQ(costs.size(), params.size());
  for (std::size_t k = 0; k < params.size(); ++k) {
    const optim::DesignCost one = optim::design_cost(s, "k-c", params[k]);
    EXPECT_TRUE(same(costs[k].cost, one.cost)) << k;
    EXPECT_TRUE(same(costs[k].J, one.J)) << k;
    EXPECT_TRUE(same(costs[k].excess, one.excess)) << k;
    EXPECT_EQ(costs[k].unstable, one.unstable) << k;
  }
  EXPECT_TRUE(std::isinf(costs[2].cost));
  EXPECT_TRUE(std::isfinite(costs[3].cost));
  // run_checks: the default, a design, and one whose run fails (a failure, J = ∞), as run_check.
  const std::vector<optim::CheckTask> tasks{{}, {"k-c", params[0], false}, {"k-c", params[2], true}, {"S2-5", {{"k", 2e4}}, true}};
  const std::vector<optim::CheckResult> checks = optim::run_checks(s, tasks);
  ASSERT_EQ(checks.size(), tasks.size());
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    const optim::CheckResult one = optim::run_check(s, tasks[k]);
    EXPECT_EQ(checks[k].failure, one.failure) << k;
    expect_same(checks[k].cost, one.cost, "check " + std::to_string(k));
  }
  EXPECT_FALSE(checks[2].failure.empty());
}

TEST(StudyBatch, ACommissionedBatchEqualsEvaluateOneByOne) {
  // Each design commissioned on its own (its trim runs on the reference line), then its lanes; a design
  // whose commissioning fails has that exception.
  const optim::Study s = io::load_study(write_study("batch_commissioned.yaml", kCommissioned));
  ASSERT_TRUE(s.commissioned());
  const std::vector<network::Network> d = designs(s, false);
  const std::vector<optim::BatchEvaluation> got = optim::evaluate_batch(s, d);
  ASSERT_EQ(got.size(), d.size());
  for (std::size_t k = 0; k < d.size(); ++k)
    expect_same(got[k], alone([&] { return optim::evaluate(s, d[k]); }), "design " + std::to_string(k));
  ASSERT_FALSE(got[0].error);
  EXPECT_TRUE(got[0].cost.commissioning && got[0].cost.commissioning->trimmed);
  EXPECT_TRUE(got[2].error);  // rigid
  EXPECT_TRUE(got[4].error);  // singular: its commissioning fails
}

TEST(StudyBatch, ThePeriodicPathAndTheTimeDomainOnALumpedLineGiveEachDesignItsOwnCost) {
  const optim::Study s = io::load_study(write_study("batch_lumped.yaml", kLumped));
  ASSERT_EQ(s.method, optim::Study::Method::Periodic);
  const std::vector<network::Network> d = designs(s, false);
  const std::vector<optim::BatchEvaluation> got = optim::evaluate_batch(s, d);
  for (std::size_t k = 0; k < d.size(); ++k)
    expect_same(got[k], alone([&] { return optim::evaluate(s, d[k]); }), "periodic design " + std::to_string(k));
  // The time-domain reference on the lumped (periodic) line: no lanes, each design's sweeps.
  const std::vector<network::Network> few{d[0], d[1], d[2], d[3]};
  const std::vector<optim::BatchEvaluation> time = optim::evaluate_time_batch(s, few);
  for (std::size_t k = 0; k < few.size(); ++k)
    expect_same(time[k], alone([&] { return optim::evaluate_time(s, few[k]); }), "time design " + std::to_string(k));
  EXPECT_TRUE(time[2].error);  // rigid
}

TEST(StudyBatch, EarlyStopsSkipOnlyDesignsThatCannotBeatTheIncumbentAndLeaveTheOthersBitForBit) {
  // Early stops (issue 50 item 2): behind an incumbent (its J, its worst run first, then that speed's other
  // catenary, then the other speed) a design is stopped once its J over the runs done exceeds the incumbent's.
  // A stopped design is worse than the incumbent in full, its J a lower bound from the incumbent's worst speed;
  // every other design's result is evaluate's bit for bit (a failing design's exception too).
  const optim::Study s = io::load_study(write_study("batch_stops.yaml", kFe));
  ASSERT_EQ(s.speeds.size(), 2u);
  const std::vector<network::Network> d = designs(s, false);
  std::vector<Alone> full;
  std::vector<std::size_t> feasible;
  for (const network::Network& n : d) {
    full.push_back(alone([&] { return optim::evaluate(s, n); }));
    if (full.back().message.empty() && full.back().cost.feasible) feasible.push_back(full.size() - 1);
  }
  ASSERT_GE(feasible.size(), 3u);
  std::sort(feasible.begin(), feasible.end(), [&](std::size_t a, std::size_t b) { return full[a].cost.J < full[b].cost.J; });
  // The incumbent: the median design (designs on both sides of it).
  const optim::EarlyStop stop = optim::EarlyStop::behind(full[feasible[feasible.size() / 2]].cost);
  const double bound = stop.above;
  ASSERT_TRUE(std::isfinite(bound));
  ASSERT_GE(stop.catenary, 0);
  const std::vector<optim::BatchEvaluation> got = optim::evaluate_time_batch(s, d, std::vector<optim::EarlyStop>(d.size(), stop));
  ASSERT_EQ(got.size(), d.size());
  int stopped = 0, kept = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    const std::string what = "design " + std::to_string(k) + " " + network::to_string(d[k], true);
    if (!got[k].stopped) {
      ++kept;
      expect_same(got[k], full[k], what);
      continue;
    }
    ++stopped;
    ASSERT_TRUE(full[k].message.empty()) << what << ": a failing design runs to the end";
    EXPECT_TRUE(full[k].cost.J > bound || !full[k].cost.feasible) << what << " could have won";
    EXPECT_LE(got[k].cost.J, full[k].cost.J) << what;  // a lower bound
    EXPECT_EQ(got[k].cost.speed, stop.speed) << what << ": only the incumbent's worst speed ran";
    // The same stop for the design alone (a Dask task's run_check of a CheckTask with the bound).
    const std::vector<optim::CheckTask> as_task{{"", {}},           {"k", {{"k", 1e4}}},  {"k", {{"k", INFINITY}}},
                                                {"c", {{"c", 1e3}}}, {"k-c", {{"k", 1e9}, {"c", 1e-3}}},
                                                {"b|c", {{"b", 10}, {"c", 100}}}};  // designs(s, false) as check tasks
    optim::CheckTask task = as_task.at(k);
    task.time = true, task.stop = stop;
    const optim::CheckResult one = optim::run_check(s, task);
    EXPECT_TRUE(one.stopped) << what;
    EXPECT_EQ(one.cost.J, got[k].cost.J) << what;
    if (stopped == 1) {  // without the worst run: the fastest speed first
      task.stop = {bound, -1, NAN};
      const optim::CheckResult fastest = optim::run_check(s, task);
      if (fastest.stopped) {
        EXPECT_EQ(fastest.cost.speed, std::max(s.speeds[0], s.speeds[1])) << what;
      }
      EXPECT_LE(fastest.cost.J, full[k].cost.J) << what;
    }
  }
  EXPECT_GT(stopped, 0);
  EXPECT_GT(kept, 3);  // the failing ones, the bound's own design and the better
  // No bound (+∞) is evaluate_time_batch without bounds; a bound per design or none.
  const std::vector<optim::BatchEvaluation> none = optim::evaluate_time_batch(s, {d[0], d[1]}, {{}, {}});
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_FALSE(none[k].stopped);
    expect_same(none[k], full[k], "no bound " + std::to_string(k));
  }
  EXPECT_THROW(optim::evaluate_time_batch(s, d, {{bound, -1, NAN}}), InvalidArgument);
}

}  // namespace test_optim_study_batch
