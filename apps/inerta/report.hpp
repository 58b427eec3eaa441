#pragma once
// Reports in the CLI (docs/cli.md "Reports"): `--report FILE.html` of simulate, sweep and
// check-reduction, and `inerta verify-report FILE.html`.
#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

#include "inerta/report/provenance.hpp"

namespace inerta::cli {

/// The command line as given to main (set by main before parsing).
void set_command_line(int argc, char** argv);
const std::vector<std::string>& command_line();

/// Adds --report FILE.html to a command.
void add_report_option(CLI::App* app, std::string& report);

/// The provenance of this run with `settings` (solver, overrides, …).
report::Provenance run_provenance(std::vector<std::pair<std::string, std::string>> settings);

/// Writes the report `html` to `path` (a safe output: complete or absent) and says so.
void write_report(const std::string& path, const std::string& html);

/// Adds `inerta verify-report FILE.html`.
CLI::App* add_verify_report_command(CLI::App& app);
int run_verify_report();

}  // namespace inerta::cli
