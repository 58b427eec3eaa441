#pragma once
// Structure-based suspension design (spec/07): for each candidate layout, optimise its free element
// values by pattern search to minimise J2 = max over catenary variants of σ_max over the speeds.
#include <cmath>
#include <cstddef>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/commission.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/network.hpp"
#include "inerta/numerics/model_search.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::optim {

/// Hard limits on the contact force, over every catenary variant and speed (docs/studies.md
/// "Limits"); NaN: no limit. Like the model studies' limits: a design that breaks one ranks after
/// every design that keeps them all (StudyCost::penalised).
struct ContactLimits {
  double mean_min = NAN, mean_max = NAN;  ///< N: the mean contact force F_m within [min, max]
  double loss_max = NAN;                  ///< %: contact loss (samples with F <= 0) at most this
  double statistical_min = NAN;           ///< N: the statistical minimum F_m − 3σ at least this
  double uplift_max = NAN;                ///< m: the largest support uplift (a finite line) at most this
  /// Every criterion of an acceptance set as a hard limit (`limits: {acceptance: PRESET|FILE}`), with the
  /// others above: all apply. Needs a finite line (the 20 Hz statistics, the registrations' uplift).
  std::shared_ptr<const analysis::AcceptanceCriteria> acceptance;
  bool any() const {
    return !std::isnan(mean_min) || !std::isnan(mean_max) || !std::isnan(loss_max) || !std::isnan(statistical_min) ||
           !std::isnan(uplift_max) || acceptance;
  }
};

/// The physical range of one kind of element (inerter b, damper c, spring k), SI: the search keeps
/// its values in [lo, hi] or open (0); rigid (∞) only if hi is ∞.
struct ElementBounds {
  double lo = 0.1, hi = 1e9;
};

struct Study {
  std::string name, source;
  /// How J2 is computed: the periodic fast path (harmonic balance on a lumped catenary) or the time
  /// domain (analysis::sweep; the method of a finite-element line, by its modal solve).
  enum class Method { Periodic, Time };
  Method method = Method::Periodic;
  ContactLimits limits;
  /// Per element kind ('b', 'c', 'k'): its bounds; a kind not listed has the search's [lo, hi], 0 and ∞.
  std::map<char, ElementBounds> bounds;
  /// Multi-fidelity (`coarse:` in the file): each layout is first optimised on this study (its own
  /// catenaries, speeds and search, usually the periodic fast path on a lumped catenary), then
  /// refined here by a pattern search from that optimum with `refine`'s options (docs/studies.md).
  std::shared_ptr<const Study> coarse;
  numerics::Options refine;
  /// Multi-fidelity, `refine: {worst_speed_first: true}`: the refinement first searches at the speed
  /// of the coarse optimum's worst σ on this study only (half the budget), then at every speed from
  /// that optimum on a finer mesh (the rest).
  bool worst_speed_first = false;
  /// Multi-fidelity, `refine: {candidates: N}`: the refinement starts from the N best distinct end
  /// points of the coarse search's starts (best first; fewer if fewer differ), each with `refine`'s
  /// budget, and keeps the best (1: the coarse optimum only).
  int refine_candidates = 1;
  /// `layouts: all` with a coarse study, `refine: {best_networks: K}`: the exhaustive search runs on the
  /// coarse study only, then the K best distinct reduced networks (feasible first) are refined here
  /// (docs/studies.md "Every network on the finite-element line").
  int refine_networks = 5;
  /// `layouts: all` with a coarse study, `refine: {screen: N}` (N ≥ best_networks; 0: none): the N best
  /// distinct reduced networks of the coarse search are first evaluated here at their coarse optimum (one
  /// evaluation each, in parallel), and the refine_networks best of them by that cost are refined — the
  /// fine stage chooses what it refines, where the coarse line cannot tell near-ties apart (issue 49).
  int refine_screen = 0;
  /// Multi-fidelity, `refine: {optimiser: bobyqa | cobyla | pattern}`: the refinement's optimiser — the
  /// pattern search, or NLopt's BOBYQA (the limits as an exact penalty) or COBYLA (the limits as a
  /// constraint) on the same log-scaled variables (numerics/model_search.hpp, docs/studies.md).
  numerics::Optimiser refine_optimiser = numerics::Optimiser::Pattern;
  pantograph::Pantograph pantograph;
  /// `pantographs: [0, 200]`: copies of the pantograph at these positions along the line, m (the time
  /// domain only); J2 and the limits are taken over every contact (the trailing one's too).
  std::vector<double> positions{0.0};
  std::vector<std::shared_ptr<const catenary::Catenary>> catenaries;  ///< the variants (J1: one)
  std::vector<std::string> catenary_labels;
  catenary::Contact contact;
  std::vector<double> speeds;        ///< m/s
  std::vector<std::string> layouts;  ///< named layouts or expressions
  /// `layouts: all`: the layouts are every network these options allow (network::enumerate), searched
  /// by optim::optimise_all.
  std::optional<network::EnumerationOptions> all;
  /// `admittance: [2, 3]`: also optimise a positive-real admittance of each degree (the bound of
  /// optim/admittance_search.hpp).
  std::vector<int> admittance_degrees;
  numerics::Options search;
  double lo = 0.1, hi = 1e9;  ///< bounds of every free value (SI), 0 and ∞ reachable
  int harmonics = 8;
  /// Per catenary: the actuator's length at the static equilibrium of the pantograph with its own
  /// suspension under that catenary. Without `trim`, candidate networks are relaxed there (the
  /// thesis's procedure), so they carry no static load and the static (≈ mean) contact force stays
  /// the design's under every catenary.
  std::vector<double> operating_length;
  /// `trim: {aerodynamic_at: {speed, unit}}` (issue 49): each design, the default included, is
  /// commissioned once on `reference` (analysis::commission: its static springs relaxed at standstill,
  /// its aerodynamic uplift a v² fitted so that the mean contact force meets the target there); every
  /// catenary then runs with those values, nothing re-set. The target: the acceptance set's curve.
  std::optional<analysis::Trim> trim;
  /// The study's `catenary:` as written (no variant's overrides): the line designs are commissioned on.
  std::shared_ptr<const catenary::Catenary> reference;
  /// `working_range: {below, above}` (m): the contact-wire heights around the reference line's over which
  /// a commissioned design's static contact force is computed (the static_force criterion).
  analysis::WorkingRange working_range;
  /// The set whose static_contact_force criterion judges a commissioned design (the study's acceptance set;
  /// a coarse study, which cannot take the others on a lumped line, takes its study's).
  std::shared_ptr<const analysis::AcceptanceCriteria> static_criteria;
  /// `objective: {type: j2 | sigma_over_mean}`: J = max σ (N), or max σ / F_m (σ and F_m as the acceptance
  /// set's σ criterion reads them: the 20 Hz statistics of a finite line; the raw ones of a lumped line).
  enum class Objective { J2, SigmaOverMean };
  Objective objective = Objective::J2;
  bool commissioned() const { return trim.has_value(); }
};

/// The unit of a study's J: "N" (J2) or "" (σ/F_m).
const char* objective_unit(const Study& study);
/// The objective's name for reports: "J2" or "sigma/F_m".
const char* objective_name(const Study& study);

/// A design as the study runs it: the pantograph under each catenary (commissioned once: the same for
/// every catenary; else relaxed under each) and, when commissioned, what commissioning set.
struct DesignPantographs {
  std::vector<pantograph::Pantograph> pantographs;  ///< one per study.catenaries
  std::optional<analysis::Commissioning> commissioning;
};
DesignPantographs design_pantographs(const Study& study, const network::Network& net);

/// Per catenary: the actuator's length at the static equilibrium of the pantograph with its own
/// suspension under that catenary (Study::operating_length).
std::vector<double> operating_lengths(const Study& study);

struct StudyCost {
  double J = 0;      ///< max over catenaries of σ_max, N
  double speed = 0;  ///< speed of the worst σ, m/s
  double mean = 0;   ///< mean contact force there, N
  int catenary = 0;  ///< index of the worst catenary
  /// > 0: the periodic solution is unstable at this speed, m/s (Floquet check, analysis/periodic.hpp):
  /// the design is infeasible and J = +∞.
  double unstable_speed = 0;
  /// Periodic method: the largest Floquet multiplier |μ| (per span) over catenaries and speeds. Close
  /// to 1 the slowest free vibration takes ln 0.01 / ln |μ| spans to decay to 1 %; a time-domain run
  /// shorter than that measures the transient, not the steady state (settling_spans()).
  double floquet = 0;
  double settling_spans() const { return floquet > 0 && floquet < 1 ? std::log(0.01) / std::log(floquet) : 0; }
  // The study's limits (Study::limits), set by cost_of.
  bool feasible = true;
  double excess = 0;      ///< Σ relative excess of the limits broken
  std::string violation;  ///< the largest relative excess, in words ("" if feasible)
  /// With acceptance limits: the criterion with the smallest margin relative to its limit over every
  /// catenary, speed and pantograph ("sigma at 300 km/h"), and that relative margin (< 0: it fails).
  std::string binding;
  double binding_margin = NAN;
  // The limited quantities, worst over catenaries and speeds (for the report).
  double mean_min = NAN, mean_max = NAN, loss_pct = 0, statistical_min = NAN, uplift = NAN;
  /// σ and F_m of the worst σ/F_m (the objective sigma_over_mean), N.
  double sigma = NAN;
  /// A commissioned study (Study::trim): what commissioning set for this design.
  std::optional<analysis::Commissioning> commissioning;
  /// What the search minimises and designs are ranked by: J if every limit holds, else
  /// 1e100 (1 + excess): such a design ranks after every one that keeps them, the smaller excess first.
  double penalised() const { return feasible ? J : 1e100 * (1 + excess); }
};

/// The pantograph's own suspension network (its actuator's), the baseline of the study.
network::Network default_suspension(const Study& study);

/// J2 of the pantograph with its suspension replaced by `net` (bound), by the study's method (the
/// periodic fast path, or the time domain for Method::Time), with its limits applied.
/// A design whose periodic solution is unstable at some speed costs J = +∞ (unstable_speed set).
StudyCost evaluate(const Study& study, const network::Network& net);

/// One design's result of evaluate_batch: its cost, or the exception evaluate throws for it.
struct BatchEvaluation {
  StudyCost cost;
  std::exception_ptr error;  ///< nullptr: `cost` holds
  /// Stopped early (evaluate_time_batch's `stops`): `cost` is of the runs done, J a lower bound of the
  /// design's J; either that J already exceeds the bound or a limit is broken (cost.feasible false).
  bool stopped = false;
  /// The cost, or the design's exception rethrown.
  const StudyCost& get() const;
};
/// How many designs a batch steps together on one line (the lanes of Catenary::couple_lanes): a batch is
/// cut into chunks of at most this many, in the given order. Eight keeps a chunk's states (the finite-element
/// line's B states of the contact rows) small beside the line's shared matrices, and a study's polls and
/// re-checks (a few to a dozen designs) in one or two chunks.
inline constexpr std::size_t lane_chunk = 8;
/// evaluate of several designs, each design's result bit for bit evaluate's (or its exception): a time-domain
/// study runs them through evaluate_time_batch; the periodic fast path evaluates them one after another.
std::vector<BatchEvaluation> evaluate_batch(const Study& study, const std::vector<network::Network>& nets);
/// An early stop (issue 50): a feasible incumbent's J, and the run where it reached it (its worst, run first).
struct EarlyStop {
  double above = INFINITY;  ///< the incumbent's J; +∞: no stop
  int catenary = -1;        ///< its worst run: the index in study.catenaries (-1: unknown)
  double speed = NAN;       ///< and its speed, m/s (one of study.speeds)
  /// Behind an incumbent: its J and worst run if it is feasible, else no stop.
  static EarlyStop behind(const StudyCost& incumbent);
};
/// evaluate_time of several designs, each bit for bit evaluate_time's (or its exception): each design
/// commissioned on its own (design_pantographs; its exception is the design's), then per catenary the designs'
/// trains in lanes (analysis::sweep_lanes, lane_chunk at a time), the (chunk, catenary) pairs and their speeds
/// in parallel; a design's exception is its first failing catenary's.
/// Early stops (`stops`: empty, or one per design): a design with a bound runs in rounds — the incumbent's worst
/// run, the other catenaries at that speed, then each other speed, the fastest first — and after a round, a
/// design whose J over the runs done (J is a maximum over runs: a lower bound) exceeds the bound, or that has
/// broken a limit, cannot rank ahead of the incumbent: its remaining runs are skipped (stopped). Which runs a
/// design does depends on its own bound alone (a batch or a lone design: the same). A design that is not
/// stopped gets evaluate_time's cost bit for bit; one whose run failed runs to the end (evaluate_time's exception).
std::vector<BatchEvaluation> evaluate_time_batch(const Study& study, const std::vector<network::Network>& nets,
                                                 const std::vector<EarlyStop>& stops = {});

/// The limits applied to the sweeps of each catenary (sets J, penalised, feasible, violation and the
/// worst limited quantities); `sweeps[i]` under study.catenaries[i].
StudyCost cost_of(const Study& study, const std::vector<std::vector<analysis::SpeedResult>>& sweeps,
                  const std::optional<analysis::Commissioning>& commissioning = std::nullopt);

struct LayoutResult {
  std::string layout, expression;
  network::Params values;  ///< all element values (fixed and optimised; 0 = open, inf = rigid)
  StudyCost cost;
  /// Multi-fidelity: the coarse study's optimum (values, its cost there) and its cost here before
  /// the refinement; empty/NaN otherwise.
  network::Params coarse_values;
  StudyCost coarse_cost, coarse_here;
  int coarse_evaluations = 0;
  int evaluations = 0;
  int unstable = 0;                     ///< designs the search refused as unstable (Floquet multiplier ≥ 1)
  bool budget_exhausted = false;        ///< the search stopped at max_evaluations (numerics::Result::exhausted)
  /// Where each start of the search ended (values of every element, cost), best first: the
  /// candidates a multi-fidelity refinement may start from.
  std::vector<std::pair<network::Params, double>> ends;
  int refined_from = 0;                 ///< multi-fidelity: the refinement starts it took (refine_candidates at most)
  std::vector<std::string> at_bounds;   ///< free values that ended on the search's limits (lo, hi, 0 or ∞)
  /// The pantograph's own suspension, ranked with the others (a commissioned multi-fidelity study's final
  /// ranking, issue 49: the recommendation is never worse than it); layout = its expression.
  bool stock = false;
};

/// The estimated wall time of one evaluation of a design (analysis::estimated_sweep_seconds of each
/// catenary variant, the variants in parallel); 0 with the periodic fast path.
double estimated_evaluation_seconds(const Study& study);

/// The estimated wall time of a whole study (issue 52): the search stage (the study's own, or its
/// coarse study's: every layout, about 60 evaluations per free value and start, at most the search's
/// limit) and the refinement (`refine`'s budget for each refined layout). One evaluation: the time
/// domain's estimate (estimated_evaluation_seconds), or the periodic path timed on the stock suspension.
struct StudyEstimate {
  long search_evaluations = 0, refine_evaluations = 0;
  double search_seconds = 0, refine_seconds = 0;
  double seconds() const { return search_seconds + refine_seconds; }
};
StudyEstimate estimated_study_seconds(const Study& study);

/// J2 of a design by the time-domain reference (analysis::sweep), to re-check the fast path's winner
/// (with the study's limits).
StudyCost evaluate_time(const Study& study, const network::Network& net);

/// The search variables of a layout's free elements: the study's [lo, hi] (0 and ∞ reachable), or
/// the bounds of the element's kind.
std::vector<numerics::Variable> search_variables(const Study& study, const std::string& layout);

/// The element names of a layout (name or expression) that the optimiser varies: all but those the
/// named layout fixes, in order of appearance.
std::vector<std::string> free_parameters(const std::string& layout);

/// The network of a design: `layout` with the free values of `values` (a layout result's values also
/// list what a named layout fixes, e.g. S2-default's c; those stay the layout's). ModelError if a
/// free value is missing.
network::Network design_network(const std::string& layout, const network::Params& values);

/// Optimises one layout (no free values: just evaluates it). progress(start, evaluations, best J).
/// `warm`: other designs' element values as further starts (as for model studies:
/// optim::optimise_layout(const ModelStudy&, …)), so the result is never worse than any of them.
/// What the search minimises for one design of a layout (its free values `params`): J2 penalised by
/// the limits (StudyCost::penalised), +∞ for a rigid suspension or one without a static equilibrium
/// or steady state; `unstable` when a periodic solution is unstable at some speed.
struct DesignCost {
  double cost = 0;
  bool unstable = false;
  double J = INFINITY;  ///< J2 alone, N (StudyCost::J; ∞: no design)
  double excess = 0;    ///< Σ relative excess of the limits (StudyCost::excess; 0: feasible)
};
DesignCost design_cost(const Study& study, const std::string& layout, const network::Params& params);

/// Evaluates designs in order, each result independent of the others (evaluate_batch's contract).
using BatchEvaluator = std::function<std::vector<BatchEvaluation>(const std::vector<network::Network>&)>;
/// design_cost of several designs of one layout, in order, through evaluate_batch or `evaluate` (the
/// engine's local DesignBatch; refinements side by side: their LaneBatcher). An exception other than a
/// NumericalError is rethrown (the first design's in order).
std::vector<DesignCost> design_costs(const Study& study, const std::string& layout,
                                     const std::vector<network::Params>& params, const BatchEvaluator& evaluate = {});

/// The design costs of several designs at once, in order (e.g. on a cluster: inerta.distributed);
/// each must equal design_cost's.
using DesignBatch = std::function<std::vector<DesignCost>(const std::vector<network::Params>& params)>;

/// `batch`: when given, the time-domain searches (a time-domain study's, a multi-fidelity study's
/// refinement) evaluate their polls through it instead of in threads here; the result is the same.
LayoutResult optimise_layout(const Study& study, const std::string& layout, const numerics::Progress& progress = {},
                             const std::vector<network::Params>& warm = {}, const DesignBatch& batch = {});

/// Multi-fidelity: the refinement of `layout` on `study` (which has a coarse study) from a coarse result
/// (its values, and its ends as further candidates, refine_candidates at most); what optimise_layout does
/// after its coarse search. The result's coarse_* fields are the coarse result's.
LayoutResult refine_layout(const Study& study, const std::string& layout, const LayoutResult& coarse,
                           const numerics::Progress& progress = {}, const DesignBatch& batch = {});

}  // namespace inerta::optim
