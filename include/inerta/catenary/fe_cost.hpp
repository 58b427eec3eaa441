#pragma once
// The cost of work on a finite-element line, from its data alone (the cost guard).
#include <vector>

#include "inerta/catenary/fe_data.hpp"

namespace inerta::catenary {

/// The cost of work on a finite-element line before it starts, from its data alone (nothing is
/// built), on the 2-core reference machine (docs/benchmarks.md "Run-time estimate"): a guide for
/// the cost guard, not a bound.
struct FeCostEstimate {
  double unknowns = 0;  ///< of the line's mesh (FeLine::n_dofs() without building it)
  double setup = 0;     ///< s: mesh, matrices, form-finding and factorisation of the line
  double modes = 0;     ///< s: the first decomposition of the modal solve's windows (0: direct solve)
  double run = 0;       ///< s: the time steps
  double bytes = 0;     ///< memory kept: the line's matrices and factor, the windows' modes
  double total() const { return setup + modes + run; }
};
/// The unknowns of the line's mesh (both wires, w and θ at every node, w fixed at the ends).
double mesh_unknowns(const FeCatenaryData& d);
/// A run with pantographs at x0 (m) at `speed` (m/s) for t_end s (≤ 0: until the leading one
/// reaches the line's end); `setup`/`modes`: include building the line / its first modes.
FeCostEstimate estimate_cost(const FeCatenaryData& d, const std::vector<double>& x0, double speed, double t_end,
                             bool setup = true, bool modes = true);

}  // namespace inerta::catenary
