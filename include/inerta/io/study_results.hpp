#pragma once
// The results of `inerta optimise STUDY --out DIR` (docs/cli.md#inerta-optimise): one line per
// layout with its element values, J2 (spec/07), the change against the default suspension, the
// worst speed, the mean contact force there and the number of cost evaluations.
//   results.csv:  layout,network,b,c,k,J2,reduction_pct,v_kmh,mean_N,evaluations
//                 (b, c, k: "open", "rigid", the value (4 digits) or "-" if the layout has none)
//   results.json: {"study", "default_J2", "layouts": [{"layout", "network", "values" (every
//                 element; 0 as 0, ∞ as "inf"), "J2", "v_kmh", "mean_N", "evaluations"}, …]}
//                 and, where they apply: "feasible" and "violation" (a limit broken), "coarse":
//                 {"values", "J2", "J2_here", "evaluations"} (multi-fidelity).
// Units: N, km/h, SI element values.
#include <string>
#include <vector>

#include "inerta/io/json.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::io {

/// The results.json document.
Json study_results_json(const std::string& study, const optim::StudyCost& default_cost,
                        const std::vector<optim::LayoutResult>& results);

/// The table `inerta optimise` prints for named layouts (the same text from Python: inerta.study_table):
/// a row per layout (element values, '*' on a bound, J2, change against the default, worst speed, mean
/// force, limits broken), the study's limits and, for a multi-fidelity study, the coarse optimum's J2
/// on both fidelities and the refinement's change.
std::string study_table(const optim::Study& study, const optim::StudyCost& default_cost,
                        const std::vector<optim::LayoutResult>& results);

/// Writes DIR/results.csv and DIR/results.json (DIR created if needed); returns their paths.
/// Throws std::runtime_error "cannot write 'path'" if a file cannot be written.
std::vector<std::string> write_study_results(const std::string& dir, const std::string& study,
                                             const optim::StudyCost& default_cost,
                                             const std::vector<optim::LayoutResult>& results);

}  // namespace inerta::io
