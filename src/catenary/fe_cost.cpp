// The cost of work on a finite-element line from its data alone (catenary/fe_catenary.hpp,
// FeCostEstimate): what the cost guard of the CLI and Python knows before building anything.
#include <algorithm>
#include <cmath>

#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::catenary {

double mesh_unknowns(const FeCatenaryData& d) {
  // FeLine's mesh: stations at the masts and droppers, each interval in ceil(length / h) elements.
  double per_span = 0, prev = 0;
  std::vector<double> marks = d.dropper_x;
  if (d.stitch.present) {  // its droppers and (with the stitch wire) its clamps are stations too
    for (double p : d.stitch.dropper_x) marks.push_back(p > 0 ? p : d.span + p);
    if (d.has_stitch()) marks.push_back(0.5 * d.stitch.length), marks.push_back(d.span - 0.5 * d.stitch.length);
    std::sort(marks.begin(), marks.end());
  }
  marks.push_back(d.span);
  for (double x : marks) {
    per_span += std::max(1.0, std::ceil((x - prev) / d.element_length - 1e-9));
    prev = x;
  }
  const double nodes = per_span * d.spans + 1;
  double stitch = 0;  // w and θ of a stitch wire at its stations (its clamps' w are the messenger's)
  if (d.has_stitch()) stitch = (2 * std::ceil(d.stitch.length / d.element_length) - 1) * (d.spans - 1);
  return 4 * nodes - 4 + stitch;  // w and θ of both wires at every node; w fixed at both ends
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
