#pragma once
// The files of an exhaustive structure search (`layouts: all`, docs/networks.md#outputs):
//   structure.csv:  rank,network,elements,springs,dampers,inerters,J,vs_default_pct,feasible,
//                   reduced,reduced_elements,reduced_inerters,values,evaluations,seconds,warm_from
//                   (ranked; values "name=value;…", 0 open, inf rigid; J in the study's unit)
//   structure.json: {"study", "objective", "unit", "default_J", "networks": [...the same fields...]}
//   pareto.csv:     elements,inerters,J,vs_default_pct,pareto,network — the best reduced network for
//                   each number of elements and of inerters; pareto = 1 if no network with no more
//                   elements and no more inerters does better
#include <string>
#include <vector>

#include "inerta/io/json.hpp"
#include "inerta/optim/admittance_search.hpp"
#include "inerta/optim/structure_search.hpp"

namespace inerta::io {

Json structure_results_json(const std::string& study, const std::string& objective, const std::string& unit,
                            double default_J, const std::vector<optim::StructureEntry>& entries);

/// Writes DIR/structure.csv, DIR/structure.json and DIR/pareto.csv; returns their paths.
std::vector<std::string> write_structure_results(const std::string& dir, const std::string& study,
                                                 const std::string& objective, const std::string& unit, double default_J,
                                                 const std::vector<optim::StructureEntry>& entries);

/// The admittance bounds (`admittance: [2, 3]`, docs/networks.md#the-admittance-bound):
///   admittance.csv:  degree,J,vs_default_pct,best_network,best_network_J,gap_pct,num,den,pr_re_min,realised,
///                    realised_elements,realised_reactive,minimal_reactive,method,realised_J,evaluations
///                    (num, den: coefficients, highest power first, space-separated; SI)
///   admittance.json: a row per degree. Returns their paths.
std::vector<std::string> write_admittance_results(const std::string& dir, const std::vector<optim::AdmittanceBound>& bounds,
                                                  double default_J);

}  // namespace inerta::io
