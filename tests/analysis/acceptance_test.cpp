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

using C = AcceptanceCriteria;
C::MeanBand band(analysis::SpeedCurve lower, analysis::SpeedCurve upper, Statistics s, analysis::SpeedRange r = {}) {
  C::MeanBand b;
  b.lower = lower, b.upper = upper, b.statistics = s, b.speeds = r;
  return b;
}
C::SigmaRatio sigma(double ratio, Statistics s) {
  C::SigmaRatio e;
  e.ratio = ratio, e.statistics = s;
  return e;
}
C::StatisticalMin stat_min(double min, Statistics s) {
  C::StatisticalMin e;
  e.min = min, e.statistics = s;
  return e;
}
C::MaxForce max_force(double max, Statistics s, analysis::SpeedRange r = {},
                      analysis::ForceMeasure m = analysis::ForceMeasure::Largest) {
  C::MaxForce e;
  e.max = max, e.statistics = s, e.speeds = r, e.measure = m;
  return e;
}
C::ContactLoss loss(double pct, double min_duration, analysis::SpeedRange r = {}) {
  C::ContactLoss e;
  e.max_pct = pct, e.min_duration = min_duration, e.speeds = r;
  return e;
}
C::SupportUplift uplift(double factor, double limited = NAN) {
  C::SupportUplift e;
  e.clearance_factor = factor, e.limited_clearance_factor = limited;
  return e;
}

// Raw statistics throughout, so each number above is the value a criterion reads.
AcceptanceCriteria raw_criteria() {
  AcceptanceCriteria c;
  c.name = "hand";
  c.mean.push_back(band({0, 0, 110}, {0, 0, 130}, Statistics::Raw));
  c.sigma.push_back(sigma(0.1, Statistics::Raw));
  c.statistical_min.push_back(stat_min(0, Statistics::Raw));
  c.max_force.push_back(max_force(250, Statistics::Raw));
  c.contact_loss.push_back(loss(1.0, 0.005));
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
  c.contact_loss.push_back(loss(0.1, 0, {0, 250}));
  c.contact_loss.push_back(loss(2.0, 0, {250, 320}));
  // 1.1 % of loss: above 0.1 % below 250 km/h, within 2 % from 250 km/h (from ≤ v < to).
  EXPECT_FALSE(find(analysis::assess(c, input(249)), "contact_loss").passed);
  EXPECT_TRUE(find(analysis::assess(c, input(250)), "contact_loss").passed);
  const CriterionResult out = find(analysis::assess(c, input(330)), "contact_loss");
  EXPECT_FALSE(out.assessed);
  EXPECT_NE(out.note.find("from 250 to 320 km/h"), std::string::npos) << out.note;
  EXPECT_TRUE(analysis::passed(analysis::assess(c, input(330))));  // not assessed does not decide
  // The top band holds at its end ("up to 320 km/h"); a band's end where the next starts belongs to the next.
  EXPECT_TRUE(find(analysis::assess(c, input(320)), "contact_loss").assessed);
  EXPECT_EQ(find(analysis::assess(c, input(320)), "contact_loss").limit, 2.0);
}

TEST(Acceptance, FilteredStatisticsAndSupportUpliftNeedAFiniteLineAndItsLimit) {
  AcceptanceCriteria c;
  c.sigma.push_back(sigma(0.3, Statistics::Filtered));
  c.support_uplift.push_back(uplift(2.0));
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

// Issue 53: the maximum force on the statistical maximum F_m + 3σ, banded in speed.
TEST(Acceptance, TheMaximumForceOnFmPlus3SigmaPicksItsSpeedBand) {
  AcceptanceCriteria c;
  c.max_force.push_back(max_force(300, Statistics::Filtered, {0, 200}, analysis::ForceMeasure::StatisticalMax));
  c.max_force.push_back(max_force(350, Statistics::Filtered, {200, INFINITY}, analysis::ForceMeasure::StatisticalMax));
  c.max_force[0].source = "below", c.max_force[1].source = "above", c.max_force[1].assumed = false;
  analysis::VerdictInput in = input(200);
  // Known filtered statistics: F_m = 150 N, σ = 50 N, so F_m + 3σ = 300 N by hand (the largest sample, 900 N,
  // is not what this measure reads).
  in.has_filtered = true;
  in.filtered.mean = 150, in.filtered.std = 50, in.filtered.max = 900;
  for (const double v : {199.999, 200.001}) {
    in.speed = v / 3.6;
    const CriterionResult r = find(analysis::assess(c, in), "max_force");
    ASSERT_TRUE(r.assessed) << v;
    EXPECT_DOUBLE_EQ(r.value, 150 + 3 * 50) << v;
    EXPECT_EQ(r.limit, v < 200 ? 300 : 350) << v;
    EXPECT_DOUBLE_EQ(r.margin, (v < 200 ? 300 : 350) - 300.0) << v;
    EXPECT_TRUE(r.passed) << v;  // 300 N against 300 N passes (margin 0)
    EXPECT_EQ(r.statistic, "filtered, F_m + 3σ");
    EXPECT_EQ(r.source, v < 200 ? "below" : "above");
    EXPECT_EQ(r.assumed, v < 200);
  }
  in.filtered.std = 50.001;  // just above 300 N: fails below 200 km/h, passes above
  in.speed = 199.999 / 3.6;
  EXPECT_FALSE(find(analysis::assess(c, in), "max_force").passed);
  in.speed = 200.001 / 3.6;
  EXPECT_TRUE(find(analysis::assess(c, in), "max_force").passed);
  // The largest sample, as before: 900 N.
  c.max_force[1].measure = analysis::ForceMeasure::Largest;
  const CriterionResult largest = find(analysis::assess(c, in), "max_force");
  EXPECT_EQ(largest.value, 900);
  EXPECT_EQ(largest.statistic, "filtered, largest sample");
}

// Issue 53: a bounded target curve refuses a speed outside its range; every row carries its source.
TEST(Acceptance, ATargetOutsideItsSpeedsIsNotAssessedAndRowsCarryTheirSource) {
  analysis::TargetCurve t;
  t.v2 = 0.00047, t.v0 = 90, t.speeds = {200, 320};
  EXPECT_NEAR(t.at(300), 132.3, 1e-9);
  EXPECT_NEAR(t.at(320), 0.00047 * 320 * 320 + 90, 1e-9);  // the end of the range holds
  EXPECT_FALSE(t.covers(199.9));
  try {
    t.at(150);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("not assessed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("from 200 to 320 km/h"), std::string::npos) << e.what();
  }
  EXPECT_THROW(t.at(320.1), InvalidArgument);
  // A bounded mean band: outside it both rows are not assessed, with a note naming its speeds.
  AcceptanceCriteria c = raw_criteria();
  c.mean[0].speeds = {200, 320};
  c.mean[0].source = "a document, https://example.org/x";
  auto rows = analysis::assess(c, input(150));
  EXPECT_FALSE(find(rows, "mean_lower").assessed);
  EXPECT_NE(find(rows, "mean_upper").note.find("from 200 to 320 km/h"), std::string::npos) << find(rows, "mean_upper").note;
  EXPECT_TRUE(find(rows, "mean_upper").statistic.empty());  // no entry judged it
  rows = analysis::assess(c, input(250));
  EXPECT_EQ(find(rows, "mean_lower").source, "a document, https://example.org/x");
  EXPECT_EQ(find(rows, "mean_lower").statistic, "raw, F_m");
  EXPECT_TRUE(find(rows, "mean_lower").assumed);  // the default: not verified
  EXPECT_EQ(find(rows, "contact_loss").statistic, "raw, F <= 0 for >= 5 ms (stands in for arcing)");
  // The verdict's line on arcing.
  EXPECT_NE(analysis::arcing_text(c).find("stands in for the measured percentage of arcing"), std::string::npos);
  EXPECT_NE(analysis::arcing_text(c).find("5 ms"), std::string::npos) << analysis::arcing_text(c);
  EXPECT_EQ(analysis::arcing_text(AcceptanceCriteria{}), "");
}

// Issue 53: where a stop limits the registration's uplift, the clearance is 1.5 S₀, else 2 S₀.
TEST(Acceptance, ALimitedSupportUpliftTakesTheLimitedClearanceFactor) {
  AcceptanceCriteria c;
  c.support_uplift.push_back(uplift(2.0, 1.5));
  analysis::VerdictInput in = input(200);
  in.has_filtered = true, in.filtered = in.raw;
  in.uplift_max = 0.05, in.uplift_limit = 0.09;
  CriterionResult r = find(analysis::assess(c, in), "support_uplift");
  EXPECT_NEAR(r.limit, 0.045, 1e-15);  // 2 · 50 mm > 90 mm
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.statistic, "largest registration uplift × 2");
  in.uplift_limited = true;  // 1.5 · 50 mm = 75 mm ≤ 90 mm
  r = find(analysis::assess(c, in), "support_uplift");
  EXPECT_NEAR(r.limit, 0.06, 1e-15);
  EXPECT_NEAR(r.margin, 0.01, 1e-15);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.statistic, "largest registration uplift × 1.5 (uplift limited by a stop)");
  // Without a limited factor the set's clearance factor holds on a limited line too.
  c.support_uplift[0].limited_clearance_factor = NAN;
  EXPECT_NEAR(find(analysis::assess(c, in), "support_uplift").limit, 0.045, 1e-15);
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
  c->sigma.push_back(sigma(0.3, Statistics::Filtered));
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
