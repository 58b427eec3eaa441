// Studies against the finite-element line (issue 24): limits on the contact quality as hard limits,
// physical bounds per element kind, the time method chosen for a line without a point model, the
// multi-fidelity refinement (coarse study, then a pattern search from its optimum) and the file's
// errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "inerta/error.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_fe_line {

using namespace inerta;
using inerta::testing::write_study;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
const std::string kLumped = "name: small\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                            "/models/catenary.yaml\n"
                            "speeds: {from: 100, to: 300, step: 100, unit: kmh}\n"
                            "search: {starts: 1, seed: 7, min_step: 0.1}\n"
                            "layouts: [S2-default, S2-5]\n";
// A short line (3 spans, modes below 30 Hz, a window of the whole line) at one speed.
const std::string kFe = "name: small FE\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                        "/models/catenary-fe.yaml\n"
                        "catenaries: [[line.spans=3, solver.cutoff=30]]\n"
                        "speeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                        "search: {starts: 1, seed: 7, min_step: 0.5, max_evaluations: 3}\n"
                        "layouts: [S2-5]\n";

analysis::SpeedResult result(double speed, double mean, double std, double loss = 0, std::vector<double> uplift = {}) {
  analysis::SpeedResult r;
  r.speed = speed;
  r.stats.mean = mean, r.stats.std = std, r.stats.stat_min = mean - 3 * std, r.stats.stat_max = mean + 3 * std;
  r.stats.loss_pct = loss;
  r.contacts = {r.stats};
  r.support_uplift = std::move(uplift);
  return r;
}
}  // namespace

TEST(StudyLimits, AllKeptGiveJAndEachBrokenOneRanksAfterEveryFeasibleDesign) {
  optim::Study s;
  s.catenary_labels = {"a", "b"};
  const std::vector<std::vector<analysis::SpeedResult>> ok{{result(50, 70, 10), result(70, 72, 20)},
                                                           {result(50, 71, 15), result(70, 73, 12, 0, {0.05, 0.08})}};
  optim::StudyCost c = optim::cost_of(s, ok);  // no limits
  EXPECT_TRUE(c.feasible);
  EXPECT_EQ(c.J, 20);
  EXPECT_EQ(c.penalised(), 20);
  EXPECT_EQ(c.speed, 70);
  EXPECT_EQ(c.catenary, 0);
  EXPECT_EQ(c.mean_min, 70);
  EXPECT_EQ(c.mean_max, 73);
  EXPECT_EQ(c.statistical_min, 72 - 60);
  EXPECT_EQ(c.uplift, 0.08);
  s.limits.mean_min = 60, s.limits.mean_max = 80, s.limits.loss_max = 0, s.limits.statistical_min = 0;
  s.limits.uplift_max = 0.1;
  c = optim::cost_of(s, ok);
  EXPECT_TRUE(c.feasible);
  EXPECT_EQ(c.penalised(), 20);
  // Each limit broken by a known relative excess: the penalty is 1e100 (1 + Σ excess), the words
  // name the worst one with its speed and catenary.
  s.limits.mean_max = 72.5;  // 73 N: (73 − 72.5)/72.5
  s.limits.uplift_max = 0.04;  // 0.05 and 0.08 m: 0.25 + 1
  c = optim::cost_of(s, ok);
  EXPECT_FALSE(c.feasible);
  EXPECT_EQ(c.J, 20);
  EXPECT_NEAR(c.penalised(), 1e100 * (1 + 0.5 / 72.5 + 0.25 + 1.0), 1e88);
  EXPECT_EQ(c.violation, "support uplift 0.08 m > 0.04 m at 252 km/h under b");
  s.limits = {};
  s.limits.loss_max = 0;
  c = optim::cost_of(s, {{result(50, 70, 30, 2.5)}});
  EXPECT_FALSE(c.feasible);
  EXPECT_NEAR(c.penalised(), 1e100 * (1 + 2.5), 1e88);  // percentage points beyond a 0 % limit
  EXPECT_EQ(c.violation, "contact loss 2.5 % > 0 % at 180 km/h");  // one catenary: not named
  s.limits = {};
  s.limits.statistical_min = 0;
  c = optim::cost_of(s, {{result(50, 70, 30)}});  // F_m − 3σ = −20 N
  EXPECT_NEAR(c.penalised(), 1e100 * 21, 1e88);
  // An infeasible design with a smaller excess ranks first; every feasible one before both.
  s.limits.statistical_min = -30;
  EXPECT_TRUE(optim::cost_of(s, {{result(50, 70, 30)}}).feasible);
}

TEST(StudyLimits, BoundsPerElementKindBecomeTheSearchVariables) {
  optim::Study s = io::load_study(write_study("bounds.yaml", kLumped + "bounds: {inerter: [0.1, 1000], spring: [10, .inf]}\n"));
  ASSERT_EQ(s.bounds.size(), 2u);
  const auto v = optim::search_variables(s, "b|c|k");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].name, "b");
  EXPECT_EQ(v[0].hi, 1000);
  EXPECT_TRUE(v[0].can_open);
  EXPECT_FALSE(v[0].can_rigid);  // an inerter of at most 1000 kg cannot be rigid
  EXPECT_EQ(v[1].lo, s.lo);      // a damper: the search's range
  EXPECT_TRUE(v[1].can_rigid);
  EXPECT_EQ(v[2].lo, 10);
  EXPECT_EQ(v[2].hi, s.hi);      // no upper bound: the search's, rigid reachable
  EXPECT_TRUE(v[2].can_rigid);
  // The optimum respects them and is flagged when it ends on one.
  const optim::LayoutResult r = optim::optimise_layout(s, "S2-3");
  EXPECT_LE(r.values.at("b"), 1000);
}

TEST(StudyFidelity, ACoarseStudyIsRefinedFromItsOptimumAndNeverEndsWorse) {
  // The coarse study: three speeds, the fine one five; the refinement starts at the coarse optimum
  // (its cost here is coarse_here) and the pattern search never ends above its start.
  const std::string text = kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100, unit: kmh}}\n"
                                     "refine: {initial_step: 0.3, min_step: 0.1, max_evaluations: 12}\n";
  std::string fine = text;
  fine.replace(fine.find("step: 100, unit: kmh}\nsearch"), 9, "step: 50");
  const optim::Study s = io::load_study(write_study("fidelity.yaml", fine));
  ASSERT_TRUE(s.coarse);
  EXPECT_EQ(s.coarse->speeds.size(), 3u);
  EXPECT_EQ(s.speeds.size(), 5u);
  EXPECT_EQ(s.refine.max_evaluations, 12);
  const optim::LayoutResult r = optim::optimise_layout(s, "S2-5");
  const optim::LayoutResult c = optim::optimise_layout(*s.coarse, "S2-5");
  EXPECT_EQ(r.coarse_values, c.values);
  EXPECT_EQ(r.coarse_cost.J, c.cost.J);
  EXPECT_EQ(r.coarse_here.J, optim::evaluate(s, network::resolve("S2-5", c.values)).J);
  EXPECT_LE(r.cost.J, r.coarse_here.J);
  EXPECT_LE(r.evaluations, 12);
  // Fewer speeds first: half the budget at the start's worst speed, then every speed; never worse.
  const optim::Study w = io::load_study(write_study("fidelity_w.yaml", fine.replace(fine.find("max_evaluations: 12}"), 20,
                                                                                  "max_evaluations: 12, worst_speed_first: true}")));
  EXPECT_TRUE(w.worst_speed_first);
  const optim::LayoutResult rw = optim::optimise_layout(w, "S2-5");
  EXPECT_EQ(rw.coarse_here.J, r.coarse_here.J);
  EXPECT_LE(rw.cost.J, rw.coarse_here.J);
  EXPECT_LE(rw.evaluations, 12);
  EXPECT_GE(rw.evaluations, 2);
}

TEST(StudyFidelity, TheRefinementCanStartFromTheBestFewCoarseEndPoints) {
  // A coarse search of three starts ends at up to three points, best first. With candidates: 2 the
  // refinement starts from the two best distinct ones: its first start is the one-candidate
  // refinement step for step, so it ends no worse than it, with more evaluations, and no worse
  // than either candidate evaluated here.
  std::string text = kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100, unit: kmh}, "
                               "search: {starts: 3, seed: 3, min_step: 0.3}}\n"
                               "refine: {initial_step: 0.3, min_step: 0.15, max_evaluations: 8}\n";
  text.replace(text.find("step: 100, unit: kmh}\nsearch"), 9, "step: 50");
  const optim::Study one = io::load_study(write_study("fidelity_one.yaml", text));
  EXPECT_EQ(one.refine_candidates, 1);
  const optim::Study two = io::load_study(
      write_study("fidelity_two.yaml", text.replace(text.find("max_evaluations: 8}"), 19, "max_evaluations: 8, candidates: 2}")));
  ASSERT_EQ(two.refine_candidates, 2);
  const optim::LayoutResult c = optim::optimise_layout(*two.coarse, "S2-4");
  ASSERT_EQ(c.ends.size(), 3u);
  for (std::size_t i = 1; i < c.ends.size(); ++i) EXPECT_LE(c.ends[i - 1].second, c.ends[i].second);
  EXPECT_EQ(c.ends.front().first, c.values);
  EXPECT_EQ(c.ends.front().second, c.cost.penalised());
  std::vector<network::Params> distinct;
  for (const auto& [values, cost] : c.ends)
    if (std::isfinite(cost) && std::find(distinct.begin(), distinct.end(), values) == distinct.end()) distinct.push_back(values);
  ASSERT_GE(distinct.size(), 2u) << "the three coarse starts should not all end at one point";
  const optim::LayoutResult r1 = optim::optimise_layout(one, "S2-4");
  const optim::LayoutResult r2 = optim::optimise_layout(two, "S2-4");
  EXPECT_EQ(r1.refined_from, 1);
  EXPECT_EQ(r2.refined_from, 2);
  EXPECT_LE(r2.cost.penalised(), r1.cost.penalised());
  EXPECT_GT(r2.evaluations, r1.evaluations);
  for (int k = 0; k < 2; ++k)
    EXPECT_LE(r2.cost.penalised(), optim::evaluate(two, network::resolve("S2-4", distinct[static_cast<std::size_t>(k)])).penalised());
}

TEST(StudyFidelity, AFiniteElementLineIsStudiedInTheTimeDomainWithItsSupportUplift) {
  const optim::Study s = io::load_study(write_study("fe_study.yaml", kFe + "limits: {support_uplift: 1.0}\n"));
  EXPECT_EQ(s.method, optim::Study::Method::Time);
  const optim::StudyCost c = optim::evaluate(s, optim::default_suspension(s));
  // The time domain on the line: the model's own suspension relaxed at its own operating point is the
  // model itself, so J is the analysis' sweep of the unchanged pantograph; the uplift is measured.
  const auto ref = analysis::sweep(s.pantograph, *s.catenaries[0], s.contact, s.speeds, analysis::RunOptions{});
  EXPECT_NEAR(c.J, ref[0].stats.std, 1e-6 * ref[0].stats.std);
  EXPECT_GT(c.J, 1);
  EXPECT_GT(c.uplift, 0);
  EXPECT_TRUE(c.feasible);
  EXPECT_NEAR(c.mean, 71, 5);  // relaxed at the line's static state: the default's static force
}

TEST(StudyFidelity, AnAcceptanceSetIsAStudyLimitThatNamesItsBindingCriterion) {
  // A criteria file beside the study (relative path), σ ≤ 2 F_m: the default keeps it; the binding
  // criterion is the only one, its margin that of the run's own 20 Hz statistics.
  write_study("lenient.yaml", "name: lenient\nfilter: {cutoff: 20, order: 4}\nsigma: {max_ratio: 2, statistics: filtered}\n");
  const optim::Study s = io::load_study(write_study("fe_acc.yaml", kFe + "limits: {acceptance: lenient.yaml}\n"));
  ASSERT_TRUE(s.limits.acceptance);
  EXPECT_EQ(s.limits.acceptance->name, "lenient");
  const optim::StudyCost c = optim::evaluate(s, optim::default_suspension(s));
  EXPECT_TRUE(c.feasible) << c.violation;
  EXPECT_EQ(c.binding, "sigma at 200 km/h");
  const auto ref = analysis::sweep(s.pantograph, *s.catenaries[0], s.contact, s.speeds, analysis::RunOptions{});
  const double margin = 2 * ref[0].filtered[0].mean - ref[0].filtered[0].std;
  EXPECT_NEAR(c.binding_margin, margin / (2 * ref[0].filtered[0].mean), 1e-9);
  // The preset's mean-force band fails without aerodynamic uplift: infeasible, named.
  const optim::Study p = io::load_study(write_study("fe_preset.yaml", kFe + "limits: {acceptance: en50367-ac}\n"));
  const optim::StudyCost cp = optim::evaluate(p, optim::default_suspension(p));
  EXPECT_FALSE(cp.feasible);
  EXPECT_NE(cp.violation.find("(en50367-ac)"), std::string::npos) << cp.violation;
}

TEST(StudyFidelity, TwoPantographsTakeJ2AndTheLimitsOverBothContacts) {
  // Two copies on the 3-span line, the leading one 40 m ahead: J2 is the larger σ of the two contacts.
  const optim::Study s = io::load_study(write_study("fe_two.yaml", kFe + "pantographs: [0, 40]\n"));
  ASSERT_EQ(s.positions, (std::vector<double>{0, 40}));
  const optim::StudyCost c = optim::evaluate(s, optim::default_suspension(s));
  const std::vector<catenary::PantographOnLine> train{{s.pantograph, 0, s.contact}, {s.pantograph, 40, s.contact}};
  const auto ref = analysis::sweep(train, *s.catenaries[0], s.speeds, analysis::RunOptions{});
  ASSERT_EQ(ref[0].contacts.size(), 2u);
  const double worst = std::max(ref[0].contacts[0].std, ref[0].contacts[1].std);
  EXPECT_NEAR(c.J, worst, 1e-6 * worst);
  EXPECT_TRUE(c.feasible);
  // The trailing pantograph runs in the leading one's waves: J differs from a lone pantograph's.
  const optim::Study one = io::load_study(write_study("fe_one.yaml", kFe));
  const double alone = optim::evaluate(one, optim::default_suspension(one)).J;
  EXPECT_GT(std::abs(c.J - alone), 1e-3 * alone) << c.J << " " << alone;
  EXPECT_GT(optim::estimated_evaluation_seconds(s), optim::estimated_evaluation_seconds(one));
}

TEST(StudyFidelity, FileErrorsOfTheNewKeys) {
  auto fails = [&](const std::string& text, const std::string& words) {
    try {
      io::load_study(write_study("bad_fe.yaml", text));
      ADD_FAILURE() << "accepted: " << words;
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad_fe.yaml:"), std::string::npos) << e.what();
    }
  };
  fails(kFe + "method: periodic\n", "the periodic fast path needs a lumped catenary");
  fails(kLumped + "method: fast\n", "expected periodic or time");
  fails(kLumped + "pantographs: [0, 200]\n", "several pantographs need the time domain");
  fails(kFe + "pantographs: [40, 0]\n", "expected increasing positions");
  fails(kFe + "pantographs: 200\n", "expected 1 to 8 positions");
  fails(kLumped + "limits: {support_uplift: 0.1}\n", "a support uplift needs a finite line");
  fails(kLumped + "limits: {acceptance: en50367-ac}\n", "acceptance criteria need a finite line");
  fails(kFe + "limits: {acceptance: nope}\n", "unknown preset 'nope'");
  fails(kFe + "limits: {acceptance: missing.yaml}\n", "missing.yaml");
  fails(kLumped + "limits: {mean: [90, 60]}\n", "expected 0 < lo < hi (N)");
  fails(kLumped + "limits: {contact_loss: 120}\n", "a percentage from 0 to 100");
  fails(kLumped + "limits: {noise: 1}\n", "unknown key in limits");
  fails(kLumped + "bounds: {mass: [1, 2]}\n", "unknown element kind in bounds");
  fails(kLumped + "bounds: {inerter: [0, 1000]}\n", "expected 0 < lo < hi");
  fails(kLumped + "refine: {max_evaluations: 3}\n", "expected coarse: too");
  fails(kLumped + "coarse: {layouts: [k]}\n", "unknown key in coarse");
  fails(kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100}}\nrefine: {initial_step: 0.01, min_step: 0.1}\n",
        "expected min_step <= initial_step");
  fails(kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100}}\nrefine: {starts: 3}\n", "unknown key in refine");
  fails(kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100}}\nrefine: {worst_speed_first: maybe}\n",
        "expected true or false");
  fails(kLumped + "coarse: {speeds: {from: 100, to: 300, step: 100}}\nrefine: {candidates: 0}\n", "candidates");
}

TEST(StudyFidelity, AnUndampedInternalBranchIsFlaggedAsSlowToSettle) {
  // Issue 24 item 4: the fast path and the time domain disagree for notch networks because a spring–
  // inerter branch without a damper (k2–b: ω = sqrt(k2/b)) is a free vibration the pantograph hardly
  // damps; a time-domain run of a few spans measures its beating. The periodic path's largest Floquet
  // multiplier gives the decay per span: spans to 1 % = ln 0.01 / ln |μ|.
  optim::StudyCost c;
  c.floquet = 0.5;
  EXPECT_NEAR(c.settling_spans(), std::log(0.01) / std::log(0.5), 1e-12);
  c.floquet = 0;
  EXPECT_EQ(c.settling_spans(), 0);
  const optim::Study s = io::load_study(write_study("settle.yaml", kLumped));
  const double spring = optim::evaluate(s, network::resolve("k", {{"k", 9.3e4}})).settling_spans();
  const double notch =
      optim::evaluate(s, network::resolve("k1|(k2-b)", {{"k1", 1e5}, {"k2", 3162.28}, {"b", 29.4}})).settling_spans();
  EXPECT_GT(spring, 1);
  EXPECT_LT(spring, 40);        // settles within a time-domain run
  EXPECT_GT(notch, 10 * spring);  // the undamped branch outlasts it
  EXPECT_GT(notch, 40);
}
}  // namespace test_optim_study_fe_line
