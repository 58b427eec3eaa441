#pragma once
// Acceptance criteria of the pantograph–catenary interaction (EN 50367 / TSI Energy practice) as
// data, and the verdict of one pantograph at one speed against them (docs/contact-quality.md
// "Acceptance"). The criteria are read from YAML by io/acceptance_file.hpp; this header holds only
// the data and the arithmetic.
//
// Conventions
// - Speeds in the criteria are km/h (as the standards write them); the input's speed is m/s.
// - Every criterion has a kind of limit: an upper limit passes when value ≤ limit (margin = limit −
//   value), a lower limit when value ≥ limit (margin = value − limit); margins are in the value's
//   unit, positive when the criterion passes.
// - A criterion applies over its speed range [from, to] km/h; outside it, or without the data it
//   needs (the line's registration.uplift_limit, the 20 Hz statistics of a finite line), it is
//   "not assessed" (assessed = false, passed = false) and does not decide the verdict.
// - Contact loss (the proxy for arcing): the share, in %, of the analysis section's samples whose
//   raw force is ≤ 0 and that belong to a loss event (a maximal run of consecutive such samples)
//   lasting at least min_duration; a run of n samples lasts n·Δt. With min_duration 0 it is the
//   EN 50317 statistic loss_pct. It stands in for the measured percentage of arcing of the standards
//   (arcing_text() says so, for a verdict's output).
// - Every entry carries where its number comes from (`source`: the document and the public address it
//   was read at) and whether it stays unverified (`assumed`); each row copies both, with the statistic
//   it judged (issue 53), so that a report shows them beside the verdict.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "inerta/analysis/contact_statistics.hpp"

namespace inerta::analysis {

struct CoupledSimulation;  // simulate.hpp

/// F(v) = v2·v² + v1·v + v0 (N, v in km/h): a mean-force band edge or the target curve.
struct SpeedCurve {
  double v2 = 0, v1 = 0, v0 = 0;
  double at(double v_kmh) const { return (v2 * v_kmh + v1) * v_kmh + v0; }
};

/// Which statistics a criterion reads: the raw section force or the 20 Hz low-passed one.
enum class Statistics { Raw, Filtered };

/// A speed range in km/h, from ≤ v < to (so [0, 250] and [250, ∞] meet without overlapping); a criterion's
/// top band also holds at its `to` (no band starts there: "up to 320 km/h" includes 320 km/h).
struct SpeedRange {
  double from = 0, to = std::numeric_limits<double>::infinity();
  bool contains(double v_kmh) const { return v_kmh >= from && v_kmh < to; }
};

/// "from 0 to 200 km/h", "from 200 km/h" (the whole range: "at every speed").
std::string range_text(const SpeedRange& r);

/// What the largest force is judged on: the largest sample of the section, or the statistical maximum
/// F_m + 3σ (EN 50367 / TSI practice for the maximum contact force of a simulation).
enum class ForceMeasure { Largest, StatisticalMax };

/// The mean-force target curve over the speeds its source gives it for (issue 53): at() refuses
/// (InvalidArgument naming the range) a speed outside them, so that no caller fits to an extrapolation.
struct TargetCurve : SpeedCurve {
  SpeedRange speeds;
  std::string source;   ///< the document and public address the curve was read at
  bool assumed = true;  ///< not verified against a public source
  /// from ≤ v ≤ to: the curve holds at the end of its range ("up to 320 km/h").
  bool covers(double v_kmh) const { return speeds.contains(v_kmh) || v_kmh == speeds.to; }
  /// F(v), N; InvalidArgument outside `speeds`.
  double at(double v_kmh) const;
};

struct AcceptanceCriteria {
  std::string name;    ///< the set's name (its file's `name:`)
  std::string source;  ///< the file it was read from
  double filter_cutoff = 20;  ///< Hz: the low-pass of the filtered statistics
  int filter_order = 4;       ///< of each pass (zero-phase, contact_quality.hpp)

  // Each criterion is a list of entries with disjoint speed ranges (a limit that changes with the
  // speed band, e.g. contact loss 0.1 % below 250 km/h and 0.2 % above); empty: not checked. At a
  // speed no entry covers, the criterion is not assessed.
  struct MeanBand {  ///< lower(v) ≤ F_m ≤ upper(v)
    SpeedCurve lower, upper;
    Statistics statistics = Statistics::Filtered;
    SpeedRange speeds;
    std::string source;   ///< the document and public address the number was read at
    bool assumed = true;  ///< not verified against a public source: the verdict marks it [assumed]
  };
  std::vector<MeanBand> mean;
  struct SigmaRatio {  ///< σ ≤ ratio · F_m
    double ratio = 0.3;
    Statistics statistics = Statistics::Filtered;
    SpeedRange speeds;
    std::string source;
    bool assumed = true;
  };
  std::vector<SigmaRatio> sigma;
  struct StatisticalMin {  ///< F_m − 3σ ≥ min
    double min = 0;  ///< N
    Statistics statistics = Statistics::Filtered;
    SpeedRange speeds;
    std::string source;
    bool assumed = true;
  };
  std::vector<StatisticalMin> statistical_min;
  struct MaxForce {  ///< the largest section force (the largest sample, or F_m + 3σ) ≤ max
    double max = 0;  ///< N
    Statistics statistics = Statistics::Filtered;
    SpeedRange speeds;
    std::string source;
    bool assumed = true;
    ForceMeasure measure = ForceMeasure::Largest;  ///< `measure: largest | statistical_max`
  };
  std::vector<MaxForce> max_force;
  struct ContactLoss {  ///< counted loss (see above) ≤ max_pct
    double max_pct = 0;       ///< %
    double min_duration = 0;  ///< s
    SpeedRange speeds;
    std::string source;
    bool assumed = true;
  };
  std::vector<ContactLoss> contact_loss;
  /// factor · max registration uplift ≤ the line's uplift_limit; the factor is limited_clearance_factor
  /// on a line whose registrations' uplift is physically limited (a stop: `registration.uplift_limited`),
  /// else clearance_factor (EN 50119 practice: 2 S₀ for a simulated uplift, 1.5 S₀ where it is limited).
  struct SupportUplift {
    double clearance_factor = 1;
    SpeedRange speeds;
    std::string source;
    bool assumed = true;
    double limited_clearance_factor = NAN;  ///< NaN: clearance_factor also where the uplift is limited
    /// The factor on a line whose uplift is (or is not) physically limited.
    double factor(bool uplift_limited) const {
      return uplift_limited && !std::isnan(limited_clearance_factor) ? limited_clearance_factor : clearance_factor;
    }
  };
  std::vector<SupportUplift> support_uplift;

  bool has_target = false;  ///< the mean-force target curve (aero-fit), F(v) with v in km/h
  TargetCurve target;       ///< at() refuses a speed outside target.speeds

  /// The static contact force at standstill over the working range (issue 49; EN 50206-1, TSI
  /// LOC&PAS): every height's force F(h) within [lower, upper] and within ± tolerance_pct % of the force
  /// at the reference height F₀ (the commissioned static force). NaN: that edge not checked.
  struct StaticForce {
    double lower = NAN, upper = NAN;  ///< N
    double tolerance_pct = NAN;       ///< %
    std::string source;
    bool assumed = true;
  };
  bool has_static_force = false;
  StaticForce static_force;
};


/// What the verdict of one pantograph at one speed reads.
struct VerdictInput {
  double speed = 0;  ///< m/s
  ContactStatistics raw;
  ContactStatistics filtered;
  bool has_filtered = false;  ///< a finite line gives the 20 Hz statistics; a lumped one does not
  /// The raw section force's loss events: the length (samples) of each maximal run of samples ≤ 0.
  std::vector<long> loss_runs;
  bool has_loss_runs = false;  ///< loss_runs given (a finite line); else the loss is raw.loss_pct
  double sample_dt = 0;  ///< s, the sampling step (loss-event durations)
  double uplift_max = NAN;    ///< m: the largest registration uplift in the section (NaN: no finite line)
  double uplift_limit = NAN;  ///< m: the line's registration.uplift_limit (NaN: not given)
  bool uplift_limited = false;  ///< the line's registration.uplift_limited: a stop limits the uplift physically
};

/// One row of the verdict.
struct CriterionResult {
  std::string criterion;  ///< mean_lower, mean_upper, sigma, statistical_min, max_force, contact_loss, support_uplift
  std::string unit;       ///< N, %, m
  double value = NAN, limit = NAN, margin = NAN;
  bool upper = true;  ///< the limit is an upper one
  bool assessed = false, passed = false;
  std::string note;  ///< why a row is not assessed
  /// What the value is: "filtered, F_m", "filtered, largest sample", "filtered, F_m + 3σ", "raw, F ≤ 0 for
  /// ≥ 5 ms", "largest registration uplift × 2", …
  std::string statistic;
  std::string source;   ///< of the entry that judged the row (empty: no entry covers its speed)
  bool assumed = true;  ///< the entry's number is not verified against a public source
};

/// The line a verdict's output gives about contact loss: that it stands in for the measured percentage of
/// arcing (force ≤ 0 for at least the set's min_duration). Empty for a set without contact_loss.
std::string arcing_text(const AcceptanceCriteria& criteria);

/// The criteria in their fixed order, each one row (the mean band gives two: mean_lower, mean_upper).
/// InvalidArgument for a negative or non-finite speed or a sample step that is not > 0 with loss runs.
std::vector<CriterionResult> assess(const AcceptanceCriteria& criteria, const VerdictInput& input);

/// Counted contact loss, %: 100 · Σ n_i over the runs with n_i·dt ≥ min_duration, over `samples`.
double counted_loss_pct(const std::vector<long>& loss_runs, long samples, double dt, double min_duration);

/// The lengths of the maximal runs of F_i ≤ 0 in F, in order.
std::vector<long> loss_runs(const std::vector<double>& F);

struct Commissioning;  // commission.hpp

/// The static contact force rows (static_force_lower, static_force_upper) of a commissioned design: the
/// smallest and largest force over its working range against the band's edges (the tighter of
/// [lower, upper] and F₀ (1 ∓ tolerance)). Not assessed without the forces (a pantograph without a rig
/// joint). Empty if the set has no static force criterion.
std::vector<CriterionResult> assess_static(const AcceptanceCriteria& criteria, const Commissioning& commissioning);

/// true if every assessed row passed (rows not assessed do not count).
bool passed(const std::vector<CriterionResult>& rows);

/// Verdict inputs of a speed run (SpeedResult) per contact, with the line's uplift limit it carries.
std::vector<VerdictInput> verdict_inputs(const SpeedResult& result);
/// Verdict inputs of a coupled simulation per contact (a finite line: its section statistics; else the
/// statistics over the simulation's window, raw only).
std::vector<VerdictInput> verdict_inputs(const CoupledSimulation& result);

/// One row of a verdict table: a criterion at one speed for one pantograph (1 = the leading one).
struct VerdictRow {
  double speed = 0;  ///< m/s
  int pantograph = 1;
  CriterionResult result;
};
/// The verdict of every speed of a sweep, every pantograph, every criterion (in that order).
std::vector<VerdictRow> verdict(const AcceptanceCriteria& criteria, const std::vector<SpeedResult>& sweep);
/// The verdict of a coupled simulation, every pantograph.
std::vector<VerdictRow> verdict(const AcceptanceCriteria& criteria, const CoupledSimulation& simulation);
/// true if every assessed row passed.
bool passed(const std::vector<VerdictRow>& rows);

/// The verdict of a set of rows (issue 52): FAIL if an assessed row failed; NOT ASSESSED if no row was
/// assessed (nothing was judged: never a PASS); else PASS. A PASS or FAIL with rows not assessed names
/// their criteria, so a partial verdict is never read as a whole one.
struct Verdict {
  enum class Status { kPass, kFail, kNotAssessed };
  Status status = Status::kNotAssessed;
  std::vector<std::string> failed;        ///< criteria with a failing row, in the rows' order
  std::vector<std::string> not_assessed;  ///< criteria with a row not assessed, in the rows' order
  /// "PASS", "FAIL" or "NOT ASSESSED".
  const char* text() const;
  /// PASS only.
  bool pass() const { return status == Status::kPass; }
};
Verdict judge(const std::vector<VerdictRow>& rows);

/// A row's margin relative to its limit: margin / |limit|, or margin / max(|value|, 1) for a limit of 0
/// (the statistical minimum F_m − 3σ ≥ 0). Negative: the criterion fails.
double relative_margin(const CriterionResult& row);

/// The criterion whose relative margin is the smallest among the assessed rows (index into rows;
/// rows.size() if none is assessed).
std::size_t binding(const std::vector<CriterionResult>& rows);

}  // namespace inerta::analysis
