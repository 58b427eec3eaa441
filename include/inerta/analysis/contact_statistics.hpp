#pragma once
// Contact-quality statistics (spec/06 §6.1) and the speed run that produces them.
#include <cmath>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::analysis {

/// Statistics of the contact force F (compression positive) over a window.
struct ContactStatistics {
  double mean = 0, std = 0, max = 0, min = 0;
  double stat_max = 0, stat_min = 0;  ///< F_m ± 3σ
  double loss_pct = 0;                ///< % of samples with F <= 0 (penalty contact)
  long samples = 0;
};
ContactStatistics statistics(const std::vector<double>& F);

struct RunOptions {
  int min_spans = 6;         ///< at least this many spans (a doubled window then misses the start)
  int max_spans = 40;        ///< give up converging after this many
  double tolerance = 0.005;  ///< span-to-span relative change of σ that ends the run
  int settled_spans = 3;     ///< the change must stay below tolerance over this many consecutive spans
  int window_spans = 2;      ///< statistics over the last window_spans spans
  int samples_per_span = 400;
  solve::IntegratorOptions integrator;
  bool fixed_spans = false;  ///< run exactly min_spans spans (no convergence test)
  double filter_cutoff = 20;  ///< Hz: a finite line's filtered statistics (contact_quality.hpp)
  int filter_order = 4;
  bool allow_supercritical = false;  ///< run above the catenary's wave speed (check_run_speed)
};
/// Each speed of a sweep (the CLI's --speeds, in its unit; Python's speeds, m/s): "speeds: 0 is out of
/// range; expected > 0".
inline constexpr NumberRule speed_rule{1e-300, 1e300, "> 0"};

/// The fastest run accepted, m/s (3600 km/h: beyond any train; a faster run's statistics are of a
/// line that barely moves, σ → 0).
inline constexpr double max_run_speed = 1000;
/// The speed of a run on `catenary` (m/s), whatever calls it (simulate_coupled, run_speed, sweep, a
/// study): at most max_run_speed; a run of `spans` spans (a finite line: its length; 0: a run whose
/// t_end is given, not checked) within 1e7 s
/// (t_end_rule's limit, so that no speed makes a run without end); and, unless
/// `allow_supercritical`, not above the catenary's wave speed. ModelError naming the speed and the
/// limit (the CLI's exit 2).
void check_run_speed(const catenary::Catenary& catenary, double speed, int spans, bool allow_supercritical);
/// From 70 % of the catenary's wave speed (the usual design rule) up to it or beyond: the warning
/// the CLI prints on standard error ("warning: 600 km/h is 130 % of the contact wire's wave speed
/// …"); else "".
std::string speed_warning(const catenary::Catenary& catenary, double speed);

/// Before a finite line's run (issue 52): InvalidArgument unless the filtered statistics' cutoff (Hz) is
/// below the Nyquist frequency of the sampling step `dt` (s), naming both and what to change — not a
/// failure after the run.
void check_filter_sampling(double cutoff, double dt, double speed);

/// The rules of RunOptions: spans 1 … 10000 (max_spans ≥ min_spans), settled_spans 1 … 1000,
/// tolerance 0 … 1, samples_per_span 10 … 1e6. InvalidArgument "max_spans: 0 is out of range; …".
void check(const RunOptions& options);

struct SpeedResult {
  double speed = 0;
  ContactStatistics stats;                  ///< of the first contact (the leading pantograph)
  std::vector<ContactStatistics> contacts;  ///< of every contact, in the order of the pantographs
  int spans = 0;                            ///< spans simulated
  double sigma_change = 0;                  ///< last span-to-span relative change of σ (largest over the contacts)
  /// Time method: σ settled (sigma_change < tolerance) before the span limit; a finite line is always
  /// converged (one pass). Periodic method: always true.
  bool converged = true;
  /// Periodic method: the largest Floquet multiplier |μ| of the linearised time-periodic system
  /// (numerics/floquet.hpp); ≥ 1 means the periodic solution is unstable and `stats` are NaN. 0: not computed.
  double floquet = 0;
  bool stable() const { return floquet < 1.0; }
  std::vector<double> t, F;                 ///< contact-force history of the first contact (all spans)
  /// A finite line: its supports in the analysis section (m along the line) and the largest uplift
  /// of each over the run, m.
  std::vector<double> support_x, support_uplift;
  /// A finite line: each contact's statistics after the 20 Hz low-pass (EN 50317, contact_quality.hpp).
  std::vector<ContactStatistics> filtered;
  /// A finite line: each contact's loss events over the section (lengths in samples of the maximal
  /// runs of raw F ≤ 0, acceptance.hpp) and the sampling step, s.
  std::vector<std::vector<long>> loss_runs;
  double sample_dt = 0;
  double uplift_limit = NAN;  ///< m: the line's registration uplift limit (Catenary::uplift_limit), set by sweep
  bool uplift_limited = false;  ///< a stop limits that uplift (Catenary::uplift_limited), set by sweep
  /// A line with overlaps (Coupled::overlaps): each contact's statistics over the overlap spans in
  /// the section alone, raw and after the low-pass; empty otherwise.
  std::vector<ContactStatistics> overlap, overlap_filtered;
};

/// A finite line (Coupled::line_length): one pass from the static state until the leading
/// pantograph is 1 m short of the end, statistics of each contact over the analysis section.
/// Otherwise: from the static equilibrium of the coupled system, span by span until σ of every contact over
/// one span changes by less than `tolerance` from the previous span, for `settled_spans` spans in a
/// row (spec/06 §6.1); statistics over the last `window_spans` spans. A bilateral contact whose
/// force becomes negative throws NumericalError with t and F.
SpeedResult run_speed(catenary::Coupled& system, const RunOptions& options);

/// The estimated wall time of sweep(pantographs, catenary, speeds): each run's
/// Catenary::estimated_seconds, the speeds shared among the cores oneTBB uses. 0 for cheap lines.
double estimated_sweep_seconds(const std::vector<catenary::PantographOnLine>& pantographs,
                               const catenary::Catenary& catenary, const std::vector<double>& speeds);

/// Speed sweep (spec/06 §6.1): couples the pantographs to the catenary at every speed and runs them
/// in parallel (oneTBB). `progress(done, total)` is called after each speed (from worker threads,
/// serialised). Results are in the order of `speeds`; the failure of the first speed that fails is
/// rethrown (every speed runs).
std::vector<SpeedResult> sweep(const std::vector<catenary::PantographOnLine>& pantographs,
                               const catenary::Catenary& catenary, const std::vector<double>& speeds,
                               const RunOptions& options, const std::function<void(int, int)>& progress = {});
/// One pantograph at x0 = 0.
std::vector<SpeedResult> sweep(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                               const catenary::Contact& contact, const std::vector<double>& speeds,
                               const RunOptions& options, const std::function<void(int, int)>& progress = {});

/// One lane's run of run_lanes: what run_speed of its train coupled alone gives, or the exception it throws.
struct LaneResult {
  SpeedResult result;
  std::exception_ptr error;  ///< nullptr: `result` holds
};
/// run_speed of every lane of a finite line's CoupledLanes (issue 50), stepped together: each lane checked
/// and equilibrated (an exception fails that lane alone), then one pass of the running lanes; per lane its
/// statistics as run_speed computes them (the same recorder), in lane order. A lane's Coupled must answer
/// support_uplift() for its own state from inside its observer call. InvalidArgument on a periodic line.
std::vector<LaneResult> run_lanes(catenary::CoupledLanes& lanes, const RunOptions& options);

/// One train's sweep of sweep_lanes: what sweep gives, or the exception it throws (the first failing speed's).
struct LaneSweep {
  std::vector<SpeedResult> results;  ///< in the order of speeds; empty if `error`
  std::exception_ptr error;
};
/// sweep of several trains (designs: the same pantograph positions) on one catenary, per train bit for bit its
/// own sweep's result or exception. A finite line: at each speed the trains' lanes (Catenary::couple_lanes,
/// run_lanes), the speeds in parallel (oneTBB); trains that cannot be coupled together are run one by one. A
/// periodic line (no lanes: its runs settle span by span): each train's sweep, the trains in parallel.
std::vector<LaneSweep> sweep_lanes(const std::vector<std::vector<catenary::PantographOnLine>>& trains,
                                   const catenary::Catenary& catenary, const std::vector<double>& speeds,
                                   const RunOptions& options);

/// The same runs on two catenaries (two formulations of one line: e.g. the finite-element line's
/// direct and modal solves), one speed after the other, each timed (coupling, start and run, s).
struct RunComparison {
  double speed = 0;
  SpeedResult reference, candidate;
  double reference_s = 0, candidate_s = 0;
};
/// The results keep the leading contact's history (t, F) for loss_differences.
std::vector<RunComparison> compare(const std::vector<catenary::PantographOnLine>& pantographs,
                                   const catenary::Catenary& reference, const catenary::Catenary& candidate,
                                   const std::vector<double>& speeds, const RunOptions& options);

/// Where two runs of the same sampling lose contact differently: the maximal runs of samples in which
/// exactly one of the two leading contacts has F ≤ 0, from the first to the last sample time of each
/// (s), and which run loses contact there (true: the candidate). Over the common samples of the two
/// histories (SpeedResult::t, F); empty if they agree.
struct LossDifference {
  double t_from = 0, t_to = 0;
  bool candidate = false;
};
std::vector<LossDifference> loss_differences(const SpeedResult& reference, const SpeedResult& candidate);

}  // namespace inerta::analysis
