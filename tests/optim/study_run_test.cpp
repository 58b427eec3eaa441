// The study engine (optim/study_run.hpp): one call runs a whole study, with events, through an executor.
#include "inerta/optim/study_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "inerta/io/model_study_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_run {

using namespace inerta;

namespace {
using inerta::testing::write_study;
std::string study_text(const std::string& layouts, const std::string& extra) {
  return std::string("name: engine\nmodel: ") + INERTA_SOURCE_DIR + "/models/hsx.yaml\ncatenary: " + INERTA_SOURCE_DIR +
         "/models/catenary.yaml\nspeeds: {from: 150, to: 250, step: 50, unit: kmh}\nlayouts: " + layouts + "\n" + extra;
}

// Records the events in order.
struct Recorder : optim::StudyEvents {
  using optim::StudyEvents::searched;
  std::vector<std::string> seen;
  void searched(std::size_t i, const optim::LayoutResult&) override { seen.push_back("searched " + std::to_string(i)); }
  void searched(std::size_t i, const optim::ModelLayoutResult&) override { seen.push_back("searched " + std::to_string(i)); }
  void network(const optim::StructureProgress&) override { seen.push_back("network"); }
  void searches_done(const optim::StudyOutcome&) override { seen.push_back("searches_done"); }
  void bound(const optim::AdmittanceBound&) override { seen.push_back("bound"); }
};

// Runs every search of a batch in reverse order and reports them so (as a cluster might): the engine
// must not depend on the order in which an executor finishes. Either kind of study.
struct ReverseExecutor : optim::StudyExecutor {
  int searches = 0, checks = 0;
  template <class S, class Result>
  std::vector<Result> reversed(const S& s, const std::vector<optim::SearchTask>& tasks, const Done<Result>& done) {
    std::vector<Result> out(tasks.size());
    for (std::size_t k = tasks.size(); k-- > 0;) {
      out[k] = optim::run_search(s, tasks[k]);
      ++searches;
      done(k, out[k]);
    }
    return out;
  }
  template <class S>
  auto checked(const S& s, const std::vector<optim::CheckTask>& tasks) {
    std::vector<decltype(optim::run_check(s, tasks.front()))> out;
    for (const auto& t : tasks) out.push_back(optim::run_check(s, t)), ++checks;
    return out;
  }
  std::vector<optim::LayoutResult> search(const optim::Study& s, const std::vector<optim::SearchTask>& tasks,
                                          const Done<optim::LayoutResult>& done, const Searching&) override {
    return reversed(s, tasks, done);
  }
  std::vector<optim::ModelLayoutResult> search(const optim::ModelStudy& s, const std::vector<optim::SearchTask>& tasks,
                                               const Done<optim::ModelLayoutResult>& done, const Searching&) override {
    return reversed(s, tasks, done);
  }
  std::vector<optim::CheckResult> check(const optim::Study& s, const std::vector<optim::CheckTask>& tasks) override {
    return checked(s, tasks);
  }
  std::vector<optim::ModelCheckResult> check(const optim::ModelStudy& s, const std::vector<optim::CheckTask>& tasks) override {
    return checked(s, tasks);
  }
};

// A model study of the tuned mass damper (models/tmd.yaml, H∞ over 3–8 Hz) with these layouts.
std::string model_study_text(const std::string& layouts, const std::string& extra) {
  return std::string("name: engine model\nmodel: ") + INERTA_SOURCE_DIR +
         "/models/tmd.yaml\nstrut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, "
         "points: 200}}\nlayouts: " + layouts + "\n" + extra;
}
}  // namespace

TEST(StudyRun, TheDefaultDesignCanWinAndIsVerifiedWithItsOwnNetwork) {
  // A spring of at most 2 N/m (or open, or rigid) cannot carry the head: S2-default (k–c, c fixed at
  // 10440 N·s/m) wins. Its closing time-domain check uses the layout's network, not the listed values
  // (resolving S2-default with c given would refuse it).
  const optim::Study s =
      io::load_study(write_study("engine_default_wins.yaml", study_text("[S2-default, k]", "search: {starts: 1, seed: 1, lo: 1, hi: 2, min_step: 0.1}\n")));
  const optim::StudyOutcome o = optim::run_study(s);
  ASSERT_EQ(o.results.size(), 2u);
  ASSERT_LT(o.results[0].cost.penalised(), o.results[1].cost.penalised());  // the premise: k is worse
  EXPECT_EQ(o.best.layout, "S2-default");
  EXPECT_EQ(o.best.index, 0u);
  EXPECT_EQ(network::to_string(o.best.net, true), network::to_string(optim::default_suspension(s), true));
  const optim::StudyCost t = optim::evaluate_time(s, optim::default_suspension(s));
  EXPECT_DOUBLE_EQ(o.time_check.J, t.J);
  EXPECT_DOUBLE_EQ(o.best.J, t.J);  // the verified J2 of a periodic study is the time domain's
  EXPECT_DOUBLE_EQ(o.default_cost.J, optim::evaluate(s, optim::default_suspension(s)).J);
}

TEST(StudyRun, NamedLayoutsGiveOptimiseLayoutsResultsAndEventsInOrder) {
  const optim::Study s =
      io::load_study(write_study("engine_named.yaml", study_text("[k, S2-5]", "search: {starts: 1, seed: 2, min_step: 0.2}\n")));
  Recorder events;
  const optim::StudyOutcome o = optim::run_study(s, {}, &events);
  ASSERT_EQ(o.results.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const optim::LayoutResult r = optim::optimise_layout(s, s.layouts[i]);
    EXPECT_EQ(o.results[i].values, r.values);
    EXPECT_DOUBLE_EQ(o.results[i].cost.J, r.cost.J);
  }
  EXPECT_EQ(events.seen, (std::vector<std::string>{"searched 0", "searched 1", "searches_done"}));
  const std::size_t best = o.results[0].cost.penalised() <= o.results[1].cost.penalised() ? 0 : 1;
  EXPECT_EQ(o.best.index, best);
  EXPECT_FALSE(o.best.verified);
  EXPECT_FALSE(o.report.has_value());
}

TEST(StudyRun, AnExecutorThatFinishesInAnotherOrderGivesTheSameOutcome) {
  const optim::Study s = io::load_study(write_study(
      "engine_all.yaml", study_text("all", "networks: {max_elements: 2}\nadmittance: [2]\nsearch: {starts: 1, seed: 1, min_step: 0.2}\n")));
  Recorder events;
  const optim::StudyOutcome here = optim::run_study(s, {}, &events);
  ReverseExecutor reverse;
  optim::StudyOptions full;  // and without the early stops: every re-check in full
  full.early_stops = false;
  const optim::StudyOutcome there = optim::run_study(s, full, nullptr, &reverse);
  EXPECT_EQ(reverse.searches, static_cast<int>(s.layouts.size()));  // every network went through the executor
  EXPECT_GE(reverse.checks, 2);  // the default and the re-checks
  ASSERT_EQ(here.entries.size(), there.entries.size());
  for (std::size_t i = 0; i < here.entries.size(); ++i) {
    EXPECT_EQ(here.entries[i].values, there.entries[i].values) << here.entries[i].expression;
    EXPECT_EQ(here.entries[i].J, there.entries[i].J);
    EXPECT_EQ(here.entries[i].warm_from, there.entries[i].warm_from);
  }
  EXPECT_EQ(here.best.expression, there.best.expression);
  EXPECT_EQ(here.best.J, there.best.J);
  // The early stops (issue 50): the same designs re-checked, the same winner; a design evaluated in full has the
  // same cost, in the same order; a stopped one (its J2 a lower bound) is worse in full than the winner.
  ASSERT_EQ(here.rechecks.size(), there.rechecks.size());
  std::vector<std::size_t> finished_here, finished_there;
  int stopped = 0;
  for (const optim::Recheck& c : here.rechecks) {
    const auto f = std::find_if(there.rechecks.begin(), there.rechecks.end(), [&](const auto& x) { return x.entry == c.entry; });
    ASSERT_NE(f, there.rechecks.end());
    EXPECT_FALSE(f->stopped);
    if (c.stopped) {
      ++stopped;
      EXPECT_LE(c.time.J, f->time.J);
      EXPECT_GT(f->time.penalised(), there.rechecks.front().time.penalised());
    } else {
      EXPECT_EQ(c.time.J, f->time.J);
      finished_here.push_back(c.entry);
    }
  }
  for (const optim::Recheck& c : there.rechecks)
    if (std::find(finished_here.begin(), finished_here.end(), c.entry) != finished_here.end()) finished_there.push_back(c.entry);
  EXPECT_EQ(finished_here, finished_there);
  EXPECT_GT(stopped, 0);
  // The stops are a design's own (CheckTask::stop): one check a task (as on Dask) stops as the batch here does.
  ReverseExecutor alone;
  EXPECT_EQ(optim::run_study(s, {}, nullptr, &alone).recheck_csv(), here.recheck_csv());
  // The best design is the re-checks' best, with its time-domain J2.
  ASSERT_FALSE(here.rechecks.empty());
  EXPECT_TRUE(here.best.verified);
  EXPECT_EQ(here.best.expression, here.entries[here.rechecks.front().entry].expression);
  EXPECT_DOUBLE_EQ(here.best.J, here.rechecks.front().time.J);
  for (std::size_t k = 1; k < there.rechecks.size(); ++k) EXPECT_LE(there.rechecks[k - 1].time.J, there.rechecks[k].time.J);
  ASSERT_EQ(here.admittance.size(), 1u);
  // Events: a network event each, then the searches' end, then the bound.
  EXPECT_EQ(std::count(events.seen.begin(), events.seen.end(), "network"), static_cast<long>(s.layouts.size()));
  EXPECT_EQ(events.seen[s.layouts.size()], "searches_done");
  EXPECT_EQ(events.seen.back(), "bound");
}

TEST(StudyRun, AModelStudyThroughAnExecutorThatFinishesInAnotherOrderGivesTheSameOutcome) {
  const optim::ModelStudy s = io::load_model_study(write_study(
      "engine_model_all.yaml", model_study_text("all", "networks: {max_elements: 2}\nadmittance: [2]\n"
                                                       "search: {starts: 1, seed: 1, lo: 0.01, hi: 1.0e7, min_step: 0.05}\n")));
  Recorder events;
  const optim::StudyOutcome here = optim::run_study(s, {}, &events);
  ReverseExecutor reverse;
  optim::StudyOptions full;  // and without the early stops: every re-check in full
  full.early_stops = false;
  const optim::StudyOutcome there = optim::run_study(s, full, nullptr, &reverse);
  EXPECT_EQ(reverse.searches, static_cast<int>(s.layouts.size()));  // every network went through the executor
  EXPECT_EQ(reverse.checks, 1);                                       // the default
  ASSERT_TRUE(here.model && there.model);
  const optim::ModelStudyResult &a = *here.model, &b = *there.model;
  ASSERT_EQ(a.entries.size(), b.entries.size());
  for (std::size_t i = 0; i < a.entries.size(); ++i) {
    EXPECT_EQ(a.entries[i].values, b.entries[i].values) << a.entries[i].expression;
    EXPECT_EQ(a.entries[i].J, b.entries[i].J);
    EXPECT_EQ(a.entries[i].warm_from, b.entries[i].warm_from);
  }
  ASSERT_EQ(a.results.size(), b.results.size());
  for (std::size_t i = 0; i < a.results.size(); ++i) {
    EXPECT_EQ(a.results[i].expression, b.results[i].expression);
    EXPECT_EQ(a.results[i].values, b.results[i].values);
    EXPECT_EQ(a.results[i].cost.J, b.results[i].cost.J);
    EXPECT_EQ(a.results[i].at_bounds, b.results[i].at_bounds);
  }
  EXPECT_EQ(a.baseline_cost.J, b.baseline_cost.J);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(here.best.expression, there.best.expression);
  EXPECT_EQ(here.best.J, there.best.J);
  ASSERT_EQ(a.admittance.size(), 1u);
  ASSERT_EQ(b.admittance.size(), 1u);
  EXPECT_EQ(a.admittance[0].result.J, b.admittance[0].result.J);
  // layouts: all is ranked: the best is the first result, and a network of optimise_all's.
  EXPECT_EQ(a.best, 0u);
  std::vector<optim::ModelLayoutResult> all;
  const auto entries = optim::optimise_all(s, all);
  EXPECT_EQ(entries[here.order.front()].values, a.results.front().values);
  EXPECT_EQ(std::count(events.seen.begin(), events.seen.end(), "network"), static_cast<long>(s.layouts.size()));
  EXPECT_EQ(events.seen[s.layouts.size()], "searches_done");
  EXPECT_EQ(events.seen.back(), "bound");
}

TEST(StudyRun, AModelStudysNamedLayoutsAreSearchedInTurnFromTheDefaultAndTheEarlierOptima) {
  const optim::ModelStudy s = io::load_model_study(write_study(
      "engine_model_named.yaml",
      model_study_text("[\"k|c\", \"k|c|b\"]", "search: {starts: 1, seed: 2, lo: 0.01, hi: 1.0e7, min_step: 0.05}\n")));
  Recorder events;
  ReverseExecutor reverse;
  const optim::StudyOutcome o = optim::run_study(s, {}, &events, &reverse);
  EXPECT_EQ(reverse.searches, 2);
  ASSERT_TRUE(o.model);
  network::Params def;  // the default's values, then each earlier optimum
  std::function<void(const network::Network&)> leaves = [&](const network::Network& n) {
    if (n.is_element()) def[n.name] = n.value;
    for (const auto& c : n.children) leaves(c);
  };
  leaves(optim::default_network(s));
  std::vector<network::Params> warm{def};
  for (std::size_t l = 0; l < s.layouts.size(); ++l) {
    const optim::ModelLayoutResult r = optim::optimise_layout(s, s.layouts[l], {}, warm);
    EXPECT_EQ(o.model->results[l].values, r.values) << s.layouts[l];
    EXPECT_EQ(o.model->results[l].cost.J, r.cost.J);
    warm.push_back(r.values);
  }
  EXPECT_LE(o.model->results[1].cost.J, o.model->results[0].cost.J);  // k|c|b contains k|c
  EXPECT_EQ(events.seen, (std::vector<std::string>{"searched 0", "searched 1", "searches_done"}));
  EXPECT_FALSE(o.model_figures.has_value());
}

TEST(StudyRun, TheBestDesignIsOneRuleForBothKinds) {
  // Within the limits first (J), then the least excess (1e100 (1 + excess)); the first of equals.
  EXPECT_EQ(optim::best_design({1e100 * 1.5, 3.0, 2.0, 2.0, 1e100 * 1.1}), 2u);
  EXPECT_EQ(optim::best_design({1e100 * 1.5, 1e100 * 1.1, INFINITY}), 1u);
  EXPECT_EQ(optim::best_design({INFINITY, INFINITY}), 0u);
  // A J2 study and a model study: the outcome's best is the rule's.
  const optim::Study j2 =
      io::load_study(write_study("engine_rule.yaml", study_text("[k, S2-5]", "search: {starts: 1, seed: 2, min_step: 0.2}\n")));
  const optim::StudyOutcome oj = optim::run_study(j2);
  std::vector<double> cj;
  for (const auto& r : oj.results) cj.push_back(r.cost.penalised());
  EXPECT_EQ(oj.best.index, optim::best_design(cj));
  // No design of this model study keeps its limit (a tyre load of 1 N rms): the best is the least excess,
  // as the search ranks them.
  const optim::ModelStudy m = io::load_model_study(write_study(
      "engine_rule_model.yaml",
      std::string("name: rule\nmodel: ") + INERTA_SOURCE_DIR +
          "/models/quarter_car.yaml\nstrut: suspension\nobjective: {type: rms, road: {class: C, speed: 25, inputs: [road]}, "
          "outputs: {a_body: 1}, limits: {tyre_force: 1}}\nlayouts: [c, \"k1-c\"]\n"
          "search: {starts: 1, seed: 1, lo: 1, hi: 1.0e7, min_step: 0.1}\n"));
  const optim::StudyOutcome om = optim::run_study(m);
  for (const auto& r : om.model->results) EXPECT_FALSE(r.cost.feasible);
  std::vector<double> cm;
  for (const auto& r : om.model->results) cm.push_back(r.cost.penalised);
  EXPECT_EQ(om.best.index, optim::best_design(cm));
  EXPECT_EQ(om.model->best, om.best.index);
}

}  // namespace test_optim_study_run
