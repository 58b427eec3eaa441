#pragma once
// The commands of `inerta` (docs/cli.md), one file each: each adds its subcommand(s) to the app and
// returns what runs it once parsed (main.cpp parses and dispatches).
#include <CLI/CLI.hpp>

#include "common.hpp"

namespace inerta::cli {

Command add_check_command(CLI::App& app);              // check.cpp
Command add_simulate_command(CLI::App& app);           // simulate.cpp
Command add_admittance_command(CLI::App& app);         // admittance.cpp
Command add_sweep_command(CLI::App& app);              // sweep.cpp
Command add_modes_command(CLI::App& app);              // modes.cpp
Command add_frf_command(CLI::App& app);                // modes.cpp
Command add_catenary_response_command(CLI::App& app);  // catenary.cpp
Command add_catenary_commands(CLI::App& app);          // catenary.cpp: fit, check-reduction
Command add_optimise_command(CLI::App& app);           // optimise.cpp

}  // namespace inerta::cli
