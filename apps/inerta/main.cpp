// inerta — command-line interface (docs/cli.md): the commands, each in its own file, and their exit codes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <vector>

#include "acceptance.hpp"
#include "commands.hpp"
#include "identify.hpp"
#include "install.hpp"
#include "linear.hpp"
#include "networks.hpp"
#include "report.hpp"
#include "inerta/error.hpp"
#include "inerta/io/files.hpp"
#include "inerta/report/provenance.hpp"

using namespace inerta;

int main(int argc, char** argv) {
  cli::find_installed_data();               // an installed copy reads its own criteria, models, scripts
  io::remove_partial_outputs_on_signal();  // Ctrl-C leaves no half-written file (io/files.hpp)
  io::protect_inputs();                     // no output replaces a file the command read
  report::record_inputs();                  // each input's SHA-256 for a report's provenance
  cli::set_command_line(argc, argv);
  CLI::App app{"Inerta — inerter-based vibration suppression for multibody systems (docs/cli.md)"};
  app.require_subcommand(1);
  const std::vector<cli::Command> commands{
      cli::add_check_command(app),
      cli::add_simulate_command(app),
      cli::add_admittance_command(app),
      cli::add_sweep_command(app),
      cli::add_modes_command(app),
      cli::add_frf_command(app),
      cli::add_catenary_response_command(app),
      cli::add_catenary_commands(app),
      {cli::add_identify_commands(app), cli::run_identify},  // identify.cpp
      {cli::add_rms_command(app), cli::run_rms},             // linear.cpp
      {cli::add_networks_command(app), cli::run_networks},   // networks.cpp
      {cli::add_pantograph_command(app), cli::run_pantograph},  // acceptance.cpp
      cli::add_optimise_command(app),
      {cli::add_verify_report_command(app), cli::run_verify_report},  // report.cpp
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ModelError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const NumericalError& e) {
    fmt::print(stderr, "numerical failure: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
