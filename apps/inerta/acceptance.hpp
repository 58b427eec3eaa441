#pragma once
// The acceptance verdict in the CLI (docs/cli.md "Acceptance"): `--acceptance PRESET|FILE` and
// `--strict` of simulate and sweep, the verdict table and OUT.acceptance.csv; `inerta pantograph
// aero-fit`.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "inerta/analysis/acceptance.hpp"

namespace inerta::cli {

/// Exit code of `--strict` when a criterion fails (docs/cli.md "Exit codes").
inline constexpr int exit_acceptance_failed = 6;

struct AcceptanceArgs {
  std::string criteria;  ///< a preset (en50367-ac, en50367-ac15, en50367-dc3, en50367-dc1.5) or a criteria file; empty: no verdict
  bool strict = false;
};

/// Adds --acceptance and --strict to a command.
void add_acceptance_options(CLI::App* app, AcceptanceArgs& a);

/// Prints the verdict table (per speed, per pantograph, per criterion), writes OUT.acceptance.csv
/// when `out` is a file (OUT = out without .csv), and returns 0, or exit_acceptance_failed with
/// --strict unless the verdict is PASS (a criterion failed, or none was assessed: analysis::judge). `kmh`: speeds printed in km/h.
int report_acceptance(std::FILE* info, const analysis::AcceptanceCriteria& criteria,
                      const std::vector<analysis::VerdictRow>& rows, const std::string& out, bool strict, bool kmh);

/// The path of OUT.acceptance.csv beside `out` ("" for standard output).
std::string acceptance_path(const std::string& out);

/// Adds the `pantograph` command (aero-fit).
CLI::App* add_pantograph_command(CLI::App& app);
/// Runs the parsed pantograph subcommand; returns the exit code.
int run_pantograph();

}  // namespace inerta::cli
