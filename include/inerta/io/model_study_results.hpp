#pragma once
// The files of `inerta optimise MODEL_STUDY --out DIR` (docs/studies.md#outputs), also written by
// inerta.write_study_results from Python:
//   results.csv:  layout,expression,J,vs_default_pct,feasible,evaluations, then the rms/peak of each
//                 objective output, of each limited output, and a column per element of any layout
//                 (SI; empty if the layout has none); the default's row first
//   results.json: {"study", "objective", "default": {network, J, values, limits}, "layouts": [...], "best"}
//   frf.csv:      f_hz, then per weighted output |H| of the default and of the best design (not for peak)
//   map.csv:      the objective over the best layout's first two finite elements (if it has two)
//   structure.csv, structure.json, pareto.csv: `layouts: all` (io/structure_results.hpp)
//   admittance.csv, admittance.json: `admittance: [d, …]` (io/structure_results.hpp)
#include <string>
#include <vector>

#include "inerta/optim/model_study_result.hpp"

namespace inerta::io {

/// Writes the files above in DIR (created if needed); returns their paths in the order written.
/// Throws std::runtime_error "cannot write 'path'" if a file cannot be written.
std::vector<std::string> write_model_study_results(const std::string& dir, const optim::ModelStudyResult& result,
                                                   const optim::ModelStudyFigures& figures);

/// The table `inerta optimise` prints for a model study (the same text from Python: inerta.model_study_table):
/// the default, each layout (the first 25 of `layouts: all`), and the line with the default and the best.
std::string model_study_table(const optim::ModelStudyResult& result);

}  // namespace inerta::io
