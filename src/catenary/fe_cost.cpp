// The cost of work on a finite-element line from its data alone (catenary/fe_catenary.hpp,
// FeCostEstimate): what the cost guard of the CLI and Python knows before building anything.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fe_compile.hpp"
#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::catenary {

double mesh_unknowns(const FeCatenaryData& d) {
  // The compiled mesh (fe_compile.hpp) of the line's first spans, not of the whole line: the cost guard
  // must not allocate what it may refuse. Every interior span has the same marks (its masts' stitch
  // wires on both sides), so the unknowns grow by the same count with each span from the second on.
  if (!(d.element_length >= 1e-3 && d.span / d.element_length <= 1e5) || d.spans < 1)  // validate()'s range
    return std::numeric_limits<double>::infinity();
  if (d.spans <= 3) return compile::mesh(d).n_dofs;
  FeCatenaryData few = d;
  few.spans = 2;
  const double two = compile::mesh(few).n_dofs;
  few.spans = 3;
  const double three = compile::mesh(few).n_dofs;
  return two + (d.spans - 2) * (three - two);
}

FeCostEstimate estimate_cost(const FeCatenaryData& d, const std::vector<double>& x0, double speed, double t_end,
                             bool setup, bool modes) {
  // Measured on the reference machine (docs/benchmarks.md "Run-time estimate"; 3-mass and HSX, 5–160
  // spans): a direct step ≈ 35 ns per unknown of the line, a modal step ≈ 4 ns per unknown of the
  // window, a pantograph ≈ 20 µs a step; building the line ≈ 6 µs per unknown; a window's modes
  // ≈ 0.3 µs per (unknown × mode), the modes below the cut-off ≈ 0.9 · Σ 2 L f_c / c over both wires
  // (a tensioned string's count), the first and the interior window solved in parallel.
  FeCostEstimate e;
  e.unknowns = mesh_unknowns(d);
  const double length = d.span * d.spans;
  double lo = length, hi = 0;
  for (double x : x0) lo = std::min(lo, x), hi = std::max(hi, x);
  if (x0.empty()) lo = hi = 0;
  const double T = t_end > 0 ? t_end : std::max(0.0, length - lo) / speed;
  const double steps = T / d.time_step, per_pantograph = 20e-6 * static_cast<double>(x0.size());
  if (setup) e.setup = 6e-6 * e.unknowns;
  e.bytes = 8.0 * 40 * e.unknowns;  // M, K, C, the band factors (half bandwidth 7) and the static state
  // Every sample (the default L/(400 v)) records the uplift of every support, kept twice (the history
  // and its rows for the EN 50317 uplift) and written to OUT.supports.csv: ≈ 0.15 µs and 16 bytes a
  // value (measured: 1000 spans at 250 km/h, 4·10⁸ values, ≈ 1.5 min and 7 GB before this term).
  const double samples = 400 * T * speed / d.span, supports = std::max(0, d.spans - 1);
  const double recorded = speed > 0 && std::isfinite(samples) ? samples * supports : 0;
  e.run += 0.15e-6 * recorded;
  e.bytes += 16 * recorded;
  if (d.solver == FeCatenaryData::Solver::Direct) {
    e.run += steps * (35e-9 * e.unknowns + per_pantograph);
    return e;
  }
  const double spread = std::max(0.0, hi - lo);
  int window_spans = d.spans;
  if (d.window_behind >= 0 && d.window_ahead >= 0)
    window_spans = std::min(d.spans, d.window_behind + 1 + d.window_ahead +
                                         static_cast<int>(std::ceil(spread / d.span - 1e-9)));
  const double window = static_cast<double>(window_spans) / d.spans;
  const double n_window = window * e.unknowns, l_window = window * length;
  double m = 0;
  for (const FeWire* w : {&d.messenger, &d.contact_wire}) m += 0.9 * 2 * l_window * d.modal_cutoff / w->wave_speed();
  m = std::min(m, n_window);
  if (modes) e.modes = 0.3e-6 * n_window * m;
  e.bytes += 8.0 * n_window * m * (window_spans < d.spans ? 3 : 1);  // first, interior and last window
  e.run += steps * (4e-9 * n_window + per_pantograph);
  return e;
}

}  // namespace inerta::catenary
