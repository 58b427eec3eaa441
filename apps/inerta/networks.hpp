#pragma once
// `inerta networks` (the enumeration, docs/networks.md) and the printing of an exhaustive
// structure search (`layouts: all`) for both kinds of study. Thin layers over
// network/enumeration.hpp and optim/structure_search.hpp.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "inerta/optim/admittance_search.hpp"
#include "inerta/optim/structure_search.hpp"

namespace inerta::cli {

CLI::App* add_networks_command(CLI::App& app);
int run_networks();

/// A progress printer for optim::optimise_all: one rewritten line on a terminal (networks done,
/// elapsed, estimated remaining, best so far), else a line every ~5 % of the networks.
optim::StructureProgressFn structure_progress(const std::string& unit);

/// Prints the ranked table (the first `rows`) and the performance-vs-complexity summary.
void print_structure(const std::vector<optim::StructureEntry>& entries, double default_J, const std::string& unit,
                     std::size_t rows = 25);

/// Runs scripts/NAME DIR of the data folder (io::data_dir(): a plotting script) with Debian's python3; false if
/// it is missing or fails.
bool run_script(const std::string& name, const std::string& dir);

/// Prints one degree's admittance bound (optim::admittance_bounds' `done`): the bound, the gap of the
/// best network to it and the realisation; a heading before the first.
std::function<void(const optim::AdmittanceBound&)> print_admittance_bound(double default_J, const std::string& unit);

}  // namespace inerta::cli
