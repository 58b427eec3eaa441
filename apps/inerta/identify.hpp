#pragma once
// `inerta identify …` (docs/cli.md#identify): parameter identification from measured CSV data.
#include <CLI/CLI.hpp>

namespace inerta::cli {

/// Adds the `identify` subcommand (head-suspension, frf-fit, actuator-static, actuator-dynamic).
CLI::App* add_identify_commands(CLI::App& app);

/// Runs the parsed identify subcommand; returns the exit code. Input errors are ModelError (exit 2).
int run_identify();

}  // namespace inerta::cli
