#pragma once
// Linear analysis of any model from the command line (docs/cli.md): `frf --input` and `rms` (a model
// study's `optimise` is in optimise.cpp). Thin layers over analysis/state_space.hpp.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace inerta::cli {

/// `inerta frf MODEL --input NAME --outputs A,B --freq F0:DF:F1 [--out CSV] [--set ...]`.
int run_frf_any(const std::string& model, const std::vector<std::string>& sets, const std::string& input,
                const std::vector<std::string>& outputs, const std::vector<double>& f, const std::string& out);

/// Adds `rms` (random response by Lyapunov equations).
CLI::App* add_rms_command(CLI::App& app);
int run_rms();

/// Writes the state space of `model` (all loads and driving joints as inputs, all outputs) next to
/// the modes' export: JSON at `path`. Returns a one-line summary.
std::string export_state_space(const std::string& model_path, const std::vector<std::string>& sets, const std::string& path,
                               const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace inerta::cli
