#pragma once
// Pattern search over element values (spec/07; in the spirit of MATLAB's patternsearch): a
// generalised pattern search (compass poll ±Δ along each coordinate, mesh halved on failure) on
// log10-scaled values, so that ten decades are searched evenly, with random multi-start
// (deterministic for a seed) and the poll points evaluated in parallel (oneTBB).
//
// Each variable lives in a box [log10 lo − 1, log10 hi + 1] of decades: the last half decade below
// lo means "0" (open) and the last half decade above hi means "∞" (rigid), when allowed — so the
// limits are reachable and reported as such (the thesis reads values at its bounds as rigid).
//
// The cost is called from worker threads. It may return +∞ for a point it cannot evaluate; any
// exception it throws propagates out of pattern_search (a bug is never read as a bad design).
#include <functional>
#include <string>
#include <vector>

namespace inerta::numerics {

struct Variable {
  std::string name;
  double lo = 1e-3, hi = 1e9;  ///< finite range, > 0 (SI)
  bool can_open = true;        ///< value 0 reachable
  bool can_rigid = true;       ///< value ∞ reachable
};

/// Value of a variable at the search coordinate u (decades).
double decode(const Variable& v, double u);
/// "open", "rigid" or the number.
std::string describe(double value);

struct Options {
  int starts = 4;  ///< random starts (the first at the box centre); 0 allowed with initial_values
  unsigned seed = 1;
  double initial_step = 1.0;   ///< decades
  double min_step = 1e-3;      ///< decades: stop when the mesh is finer
  int max_evaluations = 5000;  ///< per start
  /// Further starts after the random ones, as values (0 = open, ∞ = rigid; others clamped to
  /// [lo, hi]), one per variable: warm starts, e.g. the optimum of a smaller layout. The result is
  /// never worse than the best of them.
  std::vector<std::vector<double>> initial_values;
  /// With at most `grid_variables` variables (0: never): first evaluate a grid of one point per
  /// decade over the whole box (the 0 and ∞ cells included), in parallel, and start once more from
  /// its best point — a global look at small problems, whose narrow optima random starts can miss.
  int grid_variables = 0;
};

struct Result {
  std::vector<double> values;  ///< decoded (0 and ∞ possible), one per variable
  std::vector<double> u;       ///< search coordinates
  double cost = 0;             ///< +∞ (or NaN) if no point had a finite cost: values are the first start's
  int evaluations = 0;  ///< all starts
  int best_start = 0;
  bool exhausted = false;  ///< some start stopped at max_evaluations before its mesh reached min_step
  /// Where each start ended, in start order: decoded values and cost.
  struct End {
    std::vector<double> values;
    double cost = 0;
  };
  std::vector<End> ends;
};

using Cost = std::function<double(const std::vector<double>& values)>;
/// The costs of several points at once (e.g. on a cluster): one per point, in order, each what `Cost`
/// would give for it.
using BatchCost = std::function<std::vector<double>(const std::vector<std::vector<double>>& values)>;
/// progress(start, evaluations so far, best cost so far)
using Progress = std::function<void(int, int, double)>;

/// Minimises cost(values). Throws std::invalid_argument unless 0 < lo < hi < ∞ for every variable,
/// 0 < min_step <= initial_step and max_evaluations >= 1. Always returns a point (values has one entry
/// per variable), with cost +∞ or NaN when no point had a finite cost.
/// Deterministic for a given seed (ties broken by poll order).
/// `batch`: when given, the points of a poll (and of the grid) that are not cached are evaluated by it
/// in one call instead of by `cost` in parallel threads; the result is the same.
Result pattern_search(const std::vector<Variable>& vars, const Cost& cost, const Options& options = {},
                      const Progress& progress = {}, const BatchCost& batch = {});

}  // namespace inerta::numerics
