#pragma once
// Reports in the CLI (docs/cli.md "Reports"): `--report FILE.html` of simulate, sweep and
// check-reduction, and `inerta verify-report FILE.html`.
#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

#include "common.hpp"
#include "inerta/analysis/acceptance.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/report/provenance.hpp"
#include "inerta/report/run_reports.hpp"

namespace inerta::cli {

/// The command line as given to main (set by main before parsing).
void set_command_line(int argc, char** argv);
const std::vector<std::string>& command_line();

/// Adds --report FILE.html to a command.
void add_report_option(CLI::App* app, std::string& report);

/// The provenance of this run with `settings` (solver, overrides, …).
report::Provenance run_provenance(std::vector<std::pair<std::string, std::string>> settings);

/// The context of the report of a run on `line`: the provenance with `settings` (the solver's) and the
/// overrides, suspension and criteria; the model and its --suspension network drawn; the line; the unit; the
/// verdict rows (criteria may be null: no verdict).
report::RunContext line_run_context(const std::string& model, const CatenaryArgs& cat, const catenary::Catenary& line,
                                    const analysis::AcceptanceCriteria* criteria,
                                    const std::vector<analysis::VerdictRow>& verdict,
                                    std::vector<std::pair<std::string, std::string>> settings);

/// Writes the report `html` to `path` (a safe output: complete or absent) and says so.
void write_report(const std::string& path, const std::string& html);

/// Adds `inerta verify-report FILE.html`.
CLI::App* add_verify_report_command(CLI::App& app);
int run_verify_report();

}  // namespace inerta::cli
