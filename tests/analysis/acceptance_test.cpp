// The acceptance verdict (analysis/acceptance.hpp) on hand-computed force histories, and the study
// limit it becomes (optim::cost_of).
#include "inerta/analysis/acceptance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "inerta/analysis/contact_quality.hpp"
#include "inerta/error.hpp"
#include "inerta/optim/study.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_acceptance {

using namespace inerta;
using analysis::AcceptanceCriteria;
using analysis::CriterionResult;
using analysis::Statistics;

namespace {
// 1000 samples at 1 kHz: 988 at 120 N, one at 300 N, and two loss events at 0 N: 3 samples (3 ms)
// from sample 100 and 8 samples (8 ms) from sample 500. By hand:
//   F_m = (988·120 + 300)/1000 = 118.86 N;  E[F²] = (988·120² + 300²)/1000 = 14317.2 N²;
//   σ = sqrt(14317.2 − 118.86²) = sqrt(189.5004) N;  max 300 N;  loss 11 samples = 1.1 %.
std::vector<double> force() {
  std::vector<double> F(1000, 120.0);
  F[700] = 300;
  for (int i = 100; i < 103; ++i) F[static_cast<std::size_t>(i)] = 0;
  for (int i = 500; i < 508; ++i) F[static_cast<std::size_t>(i)] = 0;
  return F;
}
constexpr double kMean = 118.86, kSigma2 = 189.5004;

analysis::VerdictInput input(double v_kmh) {
  const std::vector<double> F = force();
  analysis::VerdictInput in;
  in.speed = v_kmh / 3.6;
  in.raw = analysis::statistics(F);
  in.loss_runs = analysis::loss_runs(F);
  in.has_loss_runs = true;
  in.sample_dt = 1e-3;
  return in;
}

// Raw statistics throughout, so each number above is the value a criterion reads.
AcceptanceCriteria raw_criteria() {
  AcceptanceCriteria c;
  c.name = "hand";
  c.mean.push_back({{0, 0, 110}, {0, 0, 130}, Statistics::Raw, {}});
  c.sigma.push_back({0.1, Statistics::Raw, {}});
  c.statistical_min.push_back({0, Statistics::Raw, {}});
  c.max_force.push_back({250, Statistics::Raw, {}});
  c.contact_loss.push_back({1.0, 0.005, {}});
  return c;
}

const CriterionResult& find(const std::vector<CriterionResult>& rows, const std::string& name) {
  for (const auto& r : rows)
    if (r.criterion == name) return r;
  throw std::runtime_error("no row " + name);
}
}  // namespace

TEST(Acceptance, EachCriterionAgainstAHandComputedHistory) {
  const auto rows = analysis::assess(raw_criteria(), input(200));
  const double sigma = std::sqrt(kSigma2);
  ASSERT_EQ(rows.size(), 6u);  // mean_lower, mean_upper, sigma, statistical_min, max_force, contact_loss
  EXPECT_NEAR(find(rows, "mean_lower").value, kMean, 1e-9);
  EXPECT_NEAR(find(rows, "mean_lower").margin, kMean - 110, 1e-9);
  EXPECT_TRUE(find(rows, "mean_lower").passed);
  EXPECT_NEAR(find(rows, "mean_upper").margin, 130 - kMean, 1e-9);
  EXPECT_TRUE(find(rows, "mean_upper").passed);
  // σ ≤ 0.1 F_m: 13.766 > 11.886 fails by their difference.
  EXPECT_NEAR(find(rows, "sigma").value, sigma, 1e-9);
  EXPECT_NEAR(find(rows, "sigma").limit, 0.1 * kMean, 1e-9);
  EXPECT_NEAR(find(rows, "sigma").margin, 0.1 * kMean - sigma, 1e-9);
  EXPECT_FALSE(find(rows, "sigma").passed);
  EXPECT_NEAR(find(rows, "statistical_min").value, kMean - 3 * sigma, 1e-9);
  EXPECT_TRUE(find(rows, "statistical_min").passed);
  EXPECT_EQ(find(rows, "max_force").value, 300);
  EXPECT_EQ(find(rows, "max_force").margin, -50);
  EXPECT_FALSE(find(rows, "max_force").passed);
  // Events of at least 5 ms: only the 8-sample one, 0.8 % ≤ 1 %.
  EXPECT_NEAR(find(rows, "contact_loss").value, 0.8, 1e-12);
  EXPECT_TRUE(find(rows, "contact_loss").passed);
  EXPECT_FALSE(analysis::passed(rows));
  // Every loss counted (no minimum duration): 1.1 % > 1 %, the raw statistic.
  AcceptanceCriteria all = raw_criteria();
  all.contact_loss[0].min_duration = 0;
  const auto rows0 = analysis::assess(all, input(200));
  EXPECT_NEAR(find(rows0, "contact_loss").value, 1.1, 1e-12);
  EXPECT_NEAR(find(rows0, "contact_loss").value, input(200).raw.loss_pct, 1e-12);
  EXPECT_FALSE(find(rows0, "contact_loss").passed);
}

TEST(Acceptance, LossEventsAreMaximalRunsAndTheirDurationIsSamplesTimesTheStep) {
  EXPECT_EQ(analysis::loss_runs({1, 0, 0, 1, -1, 0, 0, 2, 0}), (std::vector<long>{2, 3, 1}));
  EXPECT_TRUE(analysis::loss_runs({1, 2, 3}).empty());
  // A run of exactly the minimum duration counts; one sample shorter does not.
  EXPECT_DOUBLE_EQ(analysis::counted_loss_pct({5}, 100, 1e-3, 0.005), 5.0);
  EXPECT_DOUBLE_EQ(analysis::counted_loss_pct({4}, 100, 1e-3, 0.005), 0.0);
  EXPECT_DOUBLE_EQ(analysis::counted_loss_pct({4, 6, 1}, 200, 1e-3, 0), 5.5);
}

TEST(Acceptance, ASpeedBandPicksItsEntryAndOutsideEveryBandTheCriterionIsNotAssessed) {
  AcceptanceCriteria c;
  c.contact_loss.push_back({0.1, 0, {0, 250}});
  c.contact_loss.push_back({2.0, 0, {250, 320}});
  // 1.1 % of loss: above 0.1 % below 250 km/h, within 2 % from 250 km/h (from ≤ v < to).
  EXPECT_FALSE(find(analysis::assess(c, input(249)), "contact_loss").passed);
  EXPECT_TRUE(find(analysis::assess(c, input(250)), "contact_loss").passed);
  const CriterionResult& out = find(analysis::assess(c, input(330)), "contact_loss");
  EXPECT_FALSE(out.assessed);
  EXPECT_NE(out.note.find("250 to below 320 km/h"), std::string::npos) << out.note;
  EXPECT_TRUE(analysis::passed(analysis::assess(c, input(330))));  // not assessed does not decide
}

TEST(Acceptance, FilteredStatisticsAndSupportUpliftNeedAFiniteLineAndItsLimit) {
  AcceptanceCriteria c;
  c.sigma.push_back({0.3, Statistics::Filtered, {}});
  c.support_uplift.push_back({2.0, {}});
  analysis::VerdictInput in = input(200);  // a lumped line: no 20 Hz statistics, no registrations
  auto rows = analysis::assess(c, in);
  EXPECT_FALSE(find(rows, "sigma").assessed);
  EXPECT_FALSE(find(rows, "support_uplift").assessed);
  in.has_filtered = true, in.filtered = in.raw;
  in.uplift_max = 0.05;  // a finite line without registration.uplift_limit: reported, not assessed
  rows = analysis::assess(c, in);
  EXPECT_TRUE(find(rows, "sigma").assessed);
  EXPECT_FALSE(find(rows, "support_uplift").assessed);
  EXPECT_EQ(find(rows, "support_uplift").value, 0.05);
  EXPECT_NE(find(rows, "support_uplift").note.find("registration.uplift_limit"), std::string::npos);
  in.uplift_limit = 0.12;  // 2 · 50 mm within 120 mm: the limit on the uplift is 60 mm
  rows = analysis::assess(c, in);
  EXPECT_TRUE(find(rows, "support_uplift").passed);
  EXPECT_NEAR(find(rows, "support_uplift").limit, 0.06, 1e-15);
  EXPECT_NEAR(find(rows, "support_uplift").margin, 0.01, 1e-15);
  in.uplift_limit = 0.09;  // 2 · 50 mm > 90 mm
  EXPECT_FALSE(find(analysis::assess(c, in), "support_uplift").passed);
}

TEST(Acceptance, ContactQualityGivesTheLossEventsOfItsSection) {
  // The same history through contact_quality over the whole of it: its runs are the history's.
  const std::vector<double> F = force();
  std::vector<double> t(F.size()), x(F.size());
  for (std::size_t i = 0; i < F.size(); ++i) t[i] = 1e-3 * static_cast<double>(i), x[i] = 0.1 * static_cast<double>(i);
  const auto q = analysis::contact_quality(t, x, F, 0.0, 1e9);
  EXPECT_EQ(q.loss_runs, (std::vector<long>{3, 8}));
  // Cut to the section from sample 200: only the 8-sample event is in it.
  const auto q2 = analysis::contact_quality(t, x, F, 20.0, 1e9);
  EXPECT_EQ(q2.loss_runs, (std::vector<long>{8}));
}

TEST(Acceptance, TheBindingCriterionHasTheLeastMarginRelativeToItsLimit) {
  std::vector<CriterionResult> rows(2);
  rows[0].assessed = rows[1].assessed = true;
  rows[0].limit = 100, rows[0].margin = 10;   // 10 %
  rows[1].limit = 0.2, rows[1].margin = 0.01;  // 5 %
  EXPECT_EQ(analysis::binding(rows), 1u);
  rows[1].assessed = false;
  EXPECT_EQ(analysis::binding(rows), 0u);
}

TEST(Acceptance, BadInputIsRefused) {
  analysis::VerdictInput in = input(200);
  in.sample_dt = 0;
  EXPECT_THROW(analysis::assess(raw_criteria(), in), InvalidArgument);
  in = input(200);
  in.speed = NAN;
  EXPECT_THROW(analysis::assess(raw_criteria(), in), InvalidArgument);
}

// The study limit is the criterion: a design whose σ is just within 0.3 F_m keeps the limits, one
// just beyond breaks them, and the message names the criterion.
TEST(Acceptance, AsAStudyLimitADesignAtTheEdgePassesOnOneSideAndFailsOnTheOther) {
  auto c = std::make_shared<AcceptanceCriteria>();
  c->name = "edge";
  c->sigma.push_back({0.3, Statistics::Filtered, {}});
  optim::Study study;
  study.limits.acceptance = c;
  auto sweep = [](double sigma) {
    analysis::SpeedResult r;
    r.speed = 250 / 3.6;
    r.stats.mean = 100, r.stats.std = sigma;
    r.contacts = {r.stats};
    r.filtered = {r.stats};
    return std::vector<std::vector<analysis::SpeedResult>>{{r}};
  };
  const optim::StudyCost in = optim::cost_of(study, sweep(30 * (1 - 1e-9)));
  const optim::StudyCost out = optim::cost_of(study, sweep(30 * (1 + 1e-9)));
  EXPECT_TRUE(in.feasible);
  EXPECT_FALSE(out.feasible);
  EXPECT_NE(out.violation.find("sigma"), std::string::npos) << out.violation;
  EXPECT_NE(out.violation.find("edge"), std::string::npos) << out.violation;
  EXPECT_EQ(in.binding, "sigma at 250 km/h");
  EXPECT_NEAR(in.binding_margin, 1e-9, 1e-12);
}

TEST(Acceptance, LossDifferencesAreTheRunsWhereOnlyOneSolveLosesContact) {
  analysis::SpeedResult a, b;
  a.t = b.t = {0, 1, 2, 3, 4, 5, 6, 7};
  a.F = {5, 0, 0, 5, 5, 5, -1, 5};
  b.F = {5, 0, 5, 5, -1, -1, 5, 5};
  const auto d = analysis::loss_differences(a, b);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].t_from, 2);  // the reference only
  EXPECT_EQ(d[0].t_to, 2);
  EXPECT_FALSE(d[0].candidate);
  EXPECT_EQ(d[1].t_from, 4);  // the candidate only, two samples
  EXPECT_EQ(d[1].t_to, 5);
  EXPECT_TRUE(d[1].candidate);
  EXPECT_EQ(d[2].t_from, 6);
  EXPECT_EQ(d[2].t_to, 6);
  EXPECT_FALSE(d[2].candidate);
  EXPECT_TRUE(analysis::loss_differences(a, a).empty());
}

}  // namespace test_analysis_acceptance
