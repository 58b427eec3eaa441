#pragma once
// The study engine (docs/studies.md "One call"): a whole design study in one call — the default
// design, the searches (named layouts, or every network of `layouts: all` warm-started from its
// sub-networks), the time-domain re-checks, the verified best design, the admittance bounds and the
// report's data — for J2 studies and model studies alike, with progress events, returning one
// StudyOutcome. `inerta optimise`, `inerta.optimise` and the Dask driver all call it; where the
// evaluations run is a StudyExecutor (here, or a cluster's workers).
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inerta/optim/admittance_search.hpp"
#include "inerta/optim/model_study_result.hpp"
#include "inerta/optim/report.hpp"
#include "inerta/optim/structure_search.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::optim {

/// One search of a study: a layout with further starts (a network of `layouts: all`: its best
/// sub-network's optimum).
struct SearchTask {
  std::string layout;
  std::vector<network::Params> warm;
  bool network = false;  ///< a network of `layouts: all`: a grid start (≤ 2 elements), its optimum pruned
  /// Multi-fidelity `layouts: all`: the search runs on the study's coarse study (the exhaustive search).
  bool coarse = false;
  /// Multi-fidelity `layouts: all`: the refinement on this study from warm.front() (a coarse optimum:
  /// refine_layout), no coarse search.
  bool refine = false;
};

/// What a search task computes: optimise_layout(study, layout, progress, warm, batch); for a network
/// of `layouts: all` as optimise_all does (a failed search: J = ∞, no values).
LayoutResult run_search(const Study& study, const SearchTask& task, const numerics::Progress& progress = {},
                        const DesignBatch& batch = {});

/// What a search task computes for a model study: optimise_layout(study, layout, progress, warm); a network
/// of `layouts: all` as optimise_all does (a failed search: infeasible, no values). No coarse or refine tasks.
ModelLayoutResult run_search(const ModelStudy& study, const SearchTask& task, const numerics::Progress& progress = {});

/// What a network's search result gives optim::structure_search (J, penalised cost, feasible, evaluations).
StructureOutcome structure_outcome(const LayoutResult& result);
StructureOutcome structure_outcome(const ModelLayoutResult& result);

/// One design to evaluate: the study's default suspension (`layout` empty) or a layout with its values,
/// by the study's method or (`time`) by the time-domain reference.
struct CheckTask {
  std::string layout;
  network::Params values;
  bool time = false;
  /// Early stop (a time-domain evaluation; issue 50): a feasible incumbent's J and worst run. The evaluation stops
  /// once the design cannot rank ahead of it (evaluate_time_batch's stops); none: evaluated in full.
  EarlyStop stop = {};
};
struct CheckResult {
  StudyCost cost;
  std::string failure;  ///< a NumericalError's message (cost.J = ∞), else ""
  /// Stopped early (CheckTask::stop): cost is of the runs done, its J a lower bound; it ranks behind the incumbent.
  bool stopped = false;
};
/// What a check task computes: evaluate or evaluate_time of the design.
CheckResult run_check(const Study& study, const CheckTask& task);
/// run_check of several tasks, each bit for bit run_check's: the time-domain ones (task.time, or a time-domain
/// study's) in lanes (evaluate_time_batch), the others one after another (LocalExecutor's checks: the screen,
/// the re-checks). An exception other than a NumericalError is rethrown, the first task's in order.
std::vector<CheckResult> run_checks(const Study& study, const std::vector<CheckTask>& tasks);
struct ModelCheckResult {
  ModelCost cost;
  std::string failure;  ///< a NumericalError's message (cost.J = ∞), else ""
};
/// The same for a model study: evaluate of the design (a model study has no time-domain check).
ModelCheckResult run_check(const ModelStudy& study, const CheckTask& task);

/// The one rule for a study's best design, both kinds: the first of the smallest penalised cost (within
/// the limits first, then the least excess: StudyCost::penalised, ModelCost::penalised).
std::size_t best_design(const std::vector<double>& penalised);

/// Where a study's evaluations run: the extension point of the CLI (LocalExecutor) and of Dask
/// (python/inerta/distributed.py). Each result must equal run_search's / run_check's; an overload per
/// kind of study (J2, model).
class StudyExecutor {
 public:
  template <class Result>
  using Done = std::function<void(std::size_t, const Result&)>;
  using Searching = std::function<void(std::size_t, int, int, double)>;
  virtual ~StudyExecutor() = default;
  /// Independent searches; results in task order. done(i, result) as each finishes (never two at
  /// once); searching(i, start, evaluations, best) during a search, if the executor can tell.
  virtual std::vector<LayoutResult> search(const Study& study, const std::vector<SearchTask>& tasks,
                                           const Done<LayoutResult>& done, const Searching& searching) = 0;
  virtual std::vector<ModelLayoutResult> search(const ModelStudy& study, const std::vector<SearchTask>& tasks,
                                                const Done<ModelLayoutResult>& done, const Searching& searching) = 0;
  /// Independent evaluations; results in task order.
  virtual std::vector<CheckResult> check(const Study& study, const std::vector<CheckTask>& tasks) = 0;
  virtual std::vector<ModelCheckResult> check(const ModelStudy& study, const std::vector<CheckTask>& tasks) = 0;
};

/// This process: named layouts one after another (each search's evaluations in parallel; a time-domain
/// study's polls in lanes, design_costs), the networks of one size in parallel (oneTBB), a J2 study's checks
/// together (run_checks), a model study's one after another (each in parallel inside).
class LocalExecutor : public StudyExecutor {
 public:
  std::vector<LayoutResult> search(const Study& study, const std::vector<SearchTask>& tasks, const Done<LayoutResult>& done,
                                   const Searching& searching) override;
  std::vector<ModelLayoutResult> search(const ModelStudy& study, const std::vector<SearchTask>& tasks,
                                        const Done<ModelLayoutResult>& done, const Searching& searching) override;
  std::vector<CheckResult> check(const Study& study, const std::vector<CheckTask>& tasks) override;
  std::vector<ModelCheckResult> check(const ModelStudy& study, const std::vector<CheckTask>& tasks) override;
};

struct StudyOutcome;

/// Progress events of a study; each is called on the calling thread or serialised, in this order.
class StudyEvents {
 public:
  virtual ~StudyEvents() = default;
  /// During named layout `index`'s search: start, evaluations so far, best J so far.
  virtual void searching(std::size_t /*index*/, int /*start*/, int /*evaluations*/, double /*best*/) {}
  /// After named layout `index` (J2 study).
  virtual void searched(std::size_t /*index*/, const LayoutResult&) {}
  /// After named layout `index` (model study).
  virtual void searched(std::size_t /*index*/, const ModelLayoutResult&) {}
  /// `layouts: all`: after each network.
  virtual void network(const StructureProgress&) {}
  /// Multi-fidelity `layouts: all` with a screen: before it, the coarse entries screened (their indices).
  virtual void screening(const std::vector<std::size_t>& /*entries*/) {}
  /// Multi-fidelity `layouts: all`: before the refinements, the coarse entries refined (their indices).
  virtual void refining(const std::vector<std::size_t>& /*entries*/) {}
  /// Multi-fidelity `layouts: all`: after the refinement of the k-th network refined (in `refining`'s order).
  virtual void refined(std::size_t /*k*/, const LayoutResult&) {}
  /// After the searches (and a `layouts: all` J2 study's re-checks): the outcome without its bounds and report.
  virtual void searches_done(const StudyOutcome&) {}
  /// After each admittance bound.
  virtual void bound(const AdmittanceBound&) {}
  /// The report's steps (ReportProgress).
  virtual void report(int /*step*/, int /*steps*/, const std::string& /*what*/, int /*done*/, int /*total*/) {}
};

struct StudyOptions {
  /// Compute the report's data (make_report; what `optimise --out` writes). Its time check is then the
  /// periodic best's verification.
  bool report = false;
  ReportOptions report_options;
  int rechecks = 5;  ///< `layouts: all` (J2): re-check the best few distinct feasible designs in the time domain
  /// Early stops where they are exact (issue 50): the re-checks after the fast path's best (their incumbent) and
  /// a screen's candidates after the first best_networks (the incumbent: the worst of those to be refined) stop
  /// once they cannot rank ahead of it. The winner, the networks refined and every design evaluated in full are
  /// the same without them; a stopped design is reported with its J as a lower bound ("stopped: J ≥ x").
  bool early_stops = true;
};

/// A `layouts: all` J2 study's time-domain re-check of one design.
struct Recheck {
  std::size_t entry = 0;   ///< index in StudyOutcome::entries
  int periodic_rank = 0;   ///< its rank among the re-checked by the fast path (1: best)
  StudyCost time;          ///< its J2 in the time domain (J = ∞ if it failed)
  std::string failure;     ///< why the time-domain run failed, or ""
  double settling_spans = 0;  ///< the slowest free vibration's decay (periodic path), spans; 0 if unknown
  bool stopped = false;       ///< stopped early behind the best (StudyOptions::early_stops): time.J is a lower bound
};

/// Multi-fidelity `layouts: all`: where a refined network came from.
struct Refinement {
  std::size_t entry = 0;  ///< index in StudyOutcome::entries (the coarse search's); kStock: the stock suspension
  int coarse_rank = 0;    ///< its rank among the refined (with a screen: the screened) by the coarse search (1: best); 0 for the stock one
  int screen_rank = 0;    ///< with a screen: its rank by the screen's cost (1: best); else 0
  static constexpr std::size_t kStock = static_cast<std::size_t>(-1);
};

/// Multi-fidelity `layouts: all` with `refine: {screen: N}`: a network evaluated here at its coarse optimum.
struct Screened {
  std::size_t entry = 0;  ///< index in StudyOutcome::entries
  int coarse_rank = 0;    ///< its rank among the screened by the coarse search (1: best)
  StudyCost cost;         ///< here, at its coarse optimum (J = ∞ if the evaluation failed)
  std::string failure;    ///< why the evaluation failed, or ""
  bool refined = false;   ///< among the best_networks best by `cost`: refined
  bool stopped = false;   ///< stopped early, behind the refined (StudyOptions::early_stops): cost.J is a lower bound
};

/// The design a study recommends.
struct BestDesign {
  std::size_t index = 0;  ///< in StudyOutcome::results (J2) or model->results
  std::string layout, expression;
  network::Params values;  ///< every element value (0 open, inf rigid)
  network::Network net;    ///< bound
  /// The objective of the recommendation: a J2 study's verified J2 (a periodic study's best in the time
  /// domain, N); a model study's J.
  double J = 0;
  bool feasible = true;
  /// `layouts: all` J2: the best by the time-domain re-checks (else the best by the search's ranking).
  bool verified = false;
};

struct StudyOutcome {
  /// A J2 study (catenary:); its parts below. A model study's whole result is `model`.
  std::optional<Study> study;
  std::optional<ModelStudyResult> model;
  network::Network baseline;  ///< the default suspension
  StudyCost default_cost;
  /// Multi-fidelity `layouts: all`: the default's cost on the coarse study (what the entries compare with).
  StudyCost coarse_default_cost;
  /// Named layouts: in the study's order. `layouts: all`: every network, ranked best first; with a coarse
  /// study (multi-fidelity) the refined networks, ranked by this study's cost (results[k] from
  /// entries[refinements[k].entry]).
  std::vector<LayoutResult> results;
  /// `layouts: all`: the structure search's entries (on the coarse study if there is one); without a
  /// coarse study results[k] = entries[order[k]].
  std::vector<StructureEntry> entries;
  std::vector<std::size_t> order;        ///< ranking(entries)
  std::vector<Refinement> refinements;  ///< multi-fidelity `layouts: all`: one per result
  /// Multi-fidelity `layouts: all`: Spearman's rank correlation of the order the refined networks were
  /// chosen in (the screen's with `refine: {screen: N}`, else the coarse search's) and this study's ranking
  /// of them (1: the same order; NaN: fewer than two).
  double rank_agreement = NAN;
  /// With a screen: the same for the coarse search's own order of the refined networks (rank_agreement is
  /// then the screen's, the order they were chosen in); without one, equal to rank_agreement.
  double coarse_rank_agreement = NAN;
  std::vector<Screened> screened;  ///< `refine: {screen: N}`: by their cost here, best first
  /// The recommendation is the stock suspension: no design ranked ahead of it (a commissioned study).
  bool stock_best = false;
  std::vector<Recheck> rechecks;        ///< `layouts: all`: ranked by the time-domain J2
  std::vector<AdmittanceBound> admittance;
  std::optional<Report> report;         ///< with StudyOptions::report (J2)
  std::optional<ModelStudyFigures> model_figures;  ///< with StudyOptions::report (model study)
  StudyCost time_check;                 ///< the best design's J2 in the time domain (a time study: its cost)
  BestDesign best;
  double seconds = 0;                   ///< wall time of the default's evaluation and the searches
  /// The screen as CSV (screened.csv): rank, network, coarse rank and J, J here, feasible, refined.
  std::string screened_csv() const;
  /// The re-checks as CSV (recheck.csv): network, reduced, J2 periodic and time, speed, rank, settling.
  std::string recheck_csv() const;
  /// Multi-fidelity `layouts: all` (refined.csv): rank, network refined, its coarse J and rank, its J here
  /// before and after the refinement, feasible, evaluations, values.
  std::string refined_csv() const;
};

/// Runs a whole study, J2 or model (one engine). The executor runs the searches and evaluations
/// (LocalExecutor if null). A model study's named layouts are searched in turn, each warm-started from the
/// default and the earlier optima; with options.report its figures (model_study_figures).
StudyOutcome run_study(const Study& study, const StudyOptions& options = {}, StudyEvents* events = nullptr,
                       StudyExecutor* executor = nullptr);
StudyOutcome run_study(const ModelStudy& study, const StudyOptions& options = {}, StudyEvents* events = nullptr,
                       StudyExecutor* executor = nullptr);

}  // namespace inerta::optim
