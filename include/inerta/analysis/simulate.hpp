#pragma once
// Time simulation as a library call (`inerta simulate`, the Python module): the outputs of a model
// sampled over a run, their summaries, and the same for pantographs running under a catenary with
// the contact-force statistics of spec/06 §6.1.
#include "inerta/error.hpp"
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inerta/analysis/contact_quality.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::analysis {

/// Largest number of output samples of a run (t_end / sample); InvalidArgument above it.
inline constexpr long max_samples = 10'000'000;

/// Sampled outputs: t and one column per output, in the order of the model's outputs.
struct TimeHistory {
  std::vector<std::string> names;
  std::vector<double> t;                     ///< s
  std::vector<std::vector<double>> columns;  ///< columns[k][i]: output k at t[i] (SI)
};

/// min / max / mean of one output over the steady part of a run, and its initial value.
struct OutputSummary {
  std::string name;
  double initial = 0, min = 0, max = 0, mean = 0;
  long samples = 0;
};

/// Summaries of every output over t ≥ from (initial value: the first sample).
std::vector<OutputSummary> summarise(const TimeHistory& history, double from);

/// progress(t, t_end), called now and then from the integrating thread.
using TimeProgress = std::function<void(double t, double t_end)>;

/// The rules of a run's length and sampling interval when given (`inerta simulate --t-end/--sample`,
/// `inerta.simulate(t_end=, sample=)`): one rule, one message for both.
inline constexpr NumberRule t_end_rule{1e-12, 1e7, "> 0 s, at most 1e7 s"};
inline constexpr NumberRule sample_rule{1e-300, 1e300, "> 0 s"};

struct SimulateOptions {
  double t_end = -1;   ///< s; ≤ 0: the model's options.t_end
  double sample = -1;  ///< s; ≤ 0: the model's options.sample
  solve::IntegratorOptions integrator;
  bool from_equilibrium = false;  ///< start from the static equilibrium under all loads
  double steady_from = -1;        ///< ≥ 0: summaries of every output over t ≥ steady_from
};

struct Simulation {
  TimeHistory history;
  mbs::AssemblyReport assembly;
  std::optional<mbs::EquilibriumReport> equilibrium;  ///< with from_equilibrium
  solve::RunStats stats;
  std::vector<OutputSummary> steady;  ///< with steady_from ≥ 0
  double t_end = 0, sample = 0;
};

/// Assembles the model at t = 0 (and its static equilibrium if asked), integrates to t_end and
/// samples every output. NumericalError with the time on failure.
Simulation simulate(const mbs::Model& model, const SimulateOptions& options, const TimeProgress& progress = {});

struct CoupledOptions {
  int spans = 12;      ///< run length in spans (t_end = spans · L / v) unless t_end > 0; a finite line: to its end
  double t_end = -1;   ///< s
  double sample = -1;  ///< s; ≤ 0: L / (400 v)
  int window_spans = 2;  ///< contact statistics over the last window_spans spans
  solve::IntegratorOptions integrator;
  double filter_cutoff = 20;  ///< Hz: a finite line's filtered statistics (contact_quality.hpp)
  int filter_order = 4;
  bool allow_supercritical = false;  ///< run above the catenary's wave speed (check_run_speed)
};
/// The rules of CoupledOptions (the CLI's --spans, --t-end, --sample; Python's simulate_coupled).
inline constexpr CountRule spans_rule{1, 10000};
inline constexpr CountRule window_spans_rule{1, 10000};
/// InvalidArgument "spans: …", "window_spans: …", and "t_end: …", "sample: …" for a value that is
/// set (not ≤ 0) but breaks t_end_rule, sample_rule (NaN is not unset).
void check(const CoupledOptions& options);

/// Contact-force statistics of one contact over the window, and where contact was first lost.
struct ContactSummary {
  ContactStatistics stats;           ///< over the window (loss_pct: % of samples with F ≤ 0)
  double first_loss_t = -1;          ///< s, time of the first sample with F ≤ 0 over the whole run (−1: none)
  double first_loss_x = 0;           ///< m, the contact point's position along the line there
  long lost_samples = 0;             ///< over the whole run
};

struct CoupledSimulation {
  /// Per contact: the outputs of its multibody model (F_contact among them); on a finite line then
  /// x_contact (m along the line) and wire_uplift (m, the wire at the contact point above its
  /// static height).
  std::vector<TimeHistory> histories;
  std::vector<ContactSummary> contacts;   ///< per contact
  solve::RunStats stats;
  double speed = 0, span = 0, t_end = 0, sample = 0, window_from = 0;
  /// A finite line: the statistics are over this section (by the contact point's position), the run
  /// ends before the leading pantograph reaches the end; the supports' uplift (m) over time.
  catenary::Section section;
  std::vector<double> support_x;
  TimeHistory supports;
  std::vector<ContactQuality> quality;  ///< per contact: EN 50317 statistics raw and filtered, PSD
  /// A line with overlaps: the overlap spans in the section (m) and each contact's statistics there.
  std::vector<catenary::Section> overlaps;
  std::vector<PartStatistics> overlap_quality;
  std::vector<SupportUplift> uplift;    ///< the supports in the section: max uplift and when
  double uplift_limit = NAN;            ///< m: the line's registration uplift limit (Catenary::uplift_limit)
  bool uplift_limited = false;          ///< a stop limits that uplift (Catenary::uplift_limited)
};

/// Couples the pantographs to the catenary at `speed` (m/s), starts from the static equilibrium
/// (no start-up jolt), integrates and samples every output of each pantograph's model.
CoupledSimulation simulate_coupled(const std::vector<catenary::PantographOnLine>& pantographs,
                                   const catenary::Catenary& catenary, double speed, const CoupledOptions& options,
                                   const TimeProgress& progress = {});

}  // namespace inerta::analysis
