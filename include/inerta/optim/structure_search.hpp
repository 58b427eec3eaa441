#pragma once
// Exhaustive structure search (docs/networks.md): every network of a list (network::enumerate)
// optimised against a study's objective, smallest networks first and the networks of one size in
// parallel (oneTBB). Each network also starts from its best sub-network's optimum (one element
// opened or made rigid, the rest mapped onto the sub-network's values), so the optimum of a network
// is never worse than that of any network it contains with one element fewer.
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "inerta/network/enumeration.hpp"
#include "inerta/optim/model_study.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::optim {

struct StructureEntry {
  std::string expression;          ///< the enumerated network
  network::ElementCounts counts;   ///< its elements
  network::Params values;          ///< its optimum (0 = open, inf = rigid)
  double J = std::numeric_limits<double>::infinity();     ///< the objective (the study's unit)
  double cost = std::numeric_limits<double>::infinity();  ///< what the search minimised (limits as penalties)
  bool feasible = true;
  int evaluations = 0;
  int unstable = 0;  ///< designs refused as unstable during the search (J2 studies: Floquet multiplier ≥ 1)
  /// The optimum with its open and rigid elements removed and same-type neighbours merged, renamed,
  /// with values ("open"/"rigid" if the whole network is), and its elements.
  std::string reduced, reduced_structure;
  network::ElementCounts reduced_counts;
  std::string warm_from;  ///< structure of the sub-network whose optimum was the warm start, or ""
  double seconds = 0;     ///< wall time of this network's search
  bool reduces() const { return reduced_counts.elements < counts.elements; }
};

/// What one network's optimisation returns to structure_search.
struct StructureOutcome {
  network::Params values;
  double J = std::numeric_limits<double>::infinity(), cost = std::numeric_limits<double>::infinity();
  bool feasible = true;
  int evaluations = 0;
  int unstable = 0;  ///< designs refused as unstable (LayoutResult::unstable)
  double seconds = -1;  ///< wall time of the search if the optimiser measured it (structure_search_batched); < 0: not
};
/// Optimises the network `expression` with these further starts (complete value sets).
using StructureOptimiser =
    std::function<StructureOutcome(std::size_t index, const std::string& expression, const std::vector<network::Params>& warm)>;

struct StructureProgress {
  int done = 0, total = 0;
  double elapsed = 0, remaining = 0;  ///< s; remaining: estimated from the time per element so far
  const StructureEntry* last = nullptr;
  double best_J = std::numeric_limits<double>::infinity();
  std::string best;  ///< the best network so far
};
/// Called after each network, serialised (from worker threads).
using StructureProgressFn = std::function<void(const StructureProgress&)>;

/// Optimises every network of `expressions` (each with distinct element names) by `optimise`;
/// entries in the order of `expressions`.
std::vector<StructureEntry> structure_search(const std::vector<std::string>& expressions, const StructureOptimiser& optimise,
                                             const StructureProgressFn& progress = {});

/// Removes elements that do not matter at an optimum: each element with a finite value, in order,
/// is opened (0) or else made rigid (∞) if that raises cost(values) by at most `tolerance` relative
/// (a damper of 5e8 N·s/m in series is rigid for the objective). Returns the values with those
/// elements removed. optimise_all prunes every network's optimum with tolerance 1e-4.
network::Params prune(const std::string& expression, network::Params values,
                      const std::function<double(const network::Params&)>& cost, double tolerance);

/// One network to optimise: its index in the list, expression and further starts.
struct StructureTask {
  std::size_t index = 0;
  std::string expression;
  std::vector<network::Params> warm;
};
/// Optimises the (independent) networks of one size; calls done(k, outcome) for tasks[k] as each
/// finishes, never two at once.
using StructureBatch = std::function<void(const std::vector<StructureTask>& tasks,
                                          const std::function<void(std::size_t, const StructureOutcome&)>& done)>;
/// structure_search with the networks of each size handed over together (e.g. to a cluster): the
/// same entries, as each size's warm starts come from smaller networks only.
std::vector<StructureEntry> structure_search_batched(const std::vector<std::string>& expressions, const StructureBatch& optimise,
                                                     const StructureProgressFn& progress = {});

/// An entry's reduced network as a design of its own: the expression (canonical, renamed: `reduced`
/// without values) and its element values; nullopt if the entry has no design or reduces to open or rigid.
std::optional<std::pair<std::string, network::Params>> reduced_design(const StructureEntry& entry);

/// Indices of the entries from best to worst: feasible first, by cost, then by fewer reduced
/// elements, then by the order of the list.
std::vector<std::size_t> ranking(const std::vector<StructureEntry>& entries);

/// Performance against complexity: the best entry for each (elements, inerters) of the reduced
/// networks, and whether it is Pareto-optimal (no other point with no more elements, no more
/// inerters and a lower objective).
struct ParetoPoint {
  int elements = 0, inerters = 0;
  double J = 0;
  std::string network;  ///< the reduced network with values
  std::size_t entry = 0;
  bool pareto = false;
};
std::vector<ParetoPoint> pareto_points(const std::vector<StructureEntry>& entries);

/// The study's `layouts` (from `layouts: all`) searched exhaustively; `results[i]` is entry i's
/// layout result (its J2 by the periodic fast path).
std::vector<StructureEntry> optimise_all(const Study& study, std::vector<LayoutResult>& results,
                                         const StructureProgressFn& progress = {});
/// The same for a model study: `results[i]` is entry i's layout result.
std::vector<StructureEntry> optimise_all(const ModelStudy& study, std::vector<ModelLayoutResult>& results,
                                         const StructureProgressFn& progress = {});

}  // namespace inerta::optim
