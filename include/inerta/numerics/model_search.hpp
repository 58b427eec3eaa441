#pragma once
// Model-based derivative-free refinement (NLopt): BOBYQA (Powell 2009: quadratic models in a trust
// region, bounds only) and COBYLA (Powell 1994: linear models, inequality constraints) on the
// pattern search's log10-scaled variables (pattern_search.hpp), for expensive evaluations
// (docs/studies.md "Refinement optimisers").
//
// The model runs on the finite range [log10 lo, log10 hi] of the variables it varies; the limits 0
// (open) and ∞ (rigid) are reached by a limit check: at the model's end, each variable is tried at
// each of its reachable limits (a variable already at one: at the finite end next to it), all in one
// batch; the best, if better, is taken and the model runs again from it on the variables then
// finite. A variable that starts open or rigid stays there during a model run.
//
// Constraints: cost gives an objective f and a constraint g (≤ 0: feasible). Designs rank as the
// pattern search ranks them (ranked()): f when feasible, else after every feasible design, the smaller
// g first. BOBYQA minimises the exact penalty f + 10 |f₀| g (f₀: the start's f); COBYLA minimises f
// subject to g ≤ 0. A point whose f is not finite is given 100 |f₀| (a model needs numbers). The
// result is the best point evaluated by ranked(), never worse than the start.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inerta/numerics/pattern_search.hpp"

namespace inerta::numerics {

enum class Optimiser { Pattern, Bobyqa, Cobyla };
/// "pattern", "bobyqa" or "cobyla".
const char* optimiser_name(Optimiser o);
/// The optimiser of that name, or nothing.
std::optional<Optimiser> parse_optimiser(std::string_view name);

/// One point's objective f and constraint g (≤ 0: feasible).
struct Evaluation {
  double f = 0, g = 0;
};
/// The rank of a point (smaller is better): f if g ≤ 0, else 1e100 (1 + g) — after every feasible
/// point, the smaller violation first (as optim::StudyCost::penalised).
double ranked(const Evaluation& e);

using ConstrainedCost = std::function<Evaluation(const std::vector<double>& values)>;
/// Several points at once (e.g. on a cluster), in order, each what ConstrainedCost gives.
using ConstrainedBatch = std::function<std::vector<Evaluation>(const std::vector<std::vector<double>>& values)>;

/// Minimises cost from each of options.initial_values (one run per start, random starts are not
/// drawn: a refinement), by BOBYQA or COBYLA (Optimiser::Pattern: pattern_search on ranked(cost)).
/// Options: initial_step (decades: the model's first trust radius), min_step (decades: stop when the
/// steps are finer — NLopt's xtol_abs), max_evaluations (per start, the limit check included: it is
/// kept back from the model's budget). Result::exhausted: some start's model stopped at its budget
/// before its steps reached min_step. Evaluations are counted once per distinct decoded point (a
/// cache, as the pattern search's); the model's points are evaluated one at a time (through `batch`
/// as one-point batches when given), the limit check's in one batch (in parallel threads otherwise).
/// Result::cost is ranked() of the best point. Deterministic. Throws std::invalid_argument as
/// pattern_search, and if there are no initial values.
Result model_search(const std::vector<Variable>& vars, const ConstrainedCost& cost, const Options& options,
                    Optimiser optimiser, const Progress& progress = {}, const ConstrainedBatch& batch = {});

}  // namespace inerta::numerics
