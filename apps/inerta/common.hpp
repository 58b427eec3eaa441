#pragma once
// Pieces shared by the commands (docs/cli.md): the pantograph-under-a-catenary options of simulate,
// sweep and check-reduction, --param lists, ranges such as --freq F0:DF:F1, and the cost guard.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "inerta/io/catenary_file.hpp"
#include "inerta/io/files.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/network/network.hpp"
#include "inerta/pantograph/pantograph.hpp"

namespace inerta::cli {

/// A parsed subcommand and what runs it.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// A CSV destination: the file given with --out (written safely, io/files.hpp), or standard output.
using io::OutputFile;

// Options shared by simulate and sweep for a pantograph running under a catenary (issue 4).
struct CatenaryArgs {
  std::string catenary, unit = "ms", suspension, contact;
  std::vector<std::string> sets, params;
  bool relaxed = false;  ///< relax --suspension at the operating point under the catenary (as a study)
  bool allow_supercritical = false;  ///< run above the contact wire's wave speed (analysis::check_run_speed)
};

/// NAME=VALUE list of --param (inf and .inf: rigid).
network::Params parse_params(const std::vector<std::string>& list);

inline double to_ms(double v, const std::string& unit) { return unit == "kmh" ? v / 3.6 : v; }

/// The pantograph with the requested suspension, and the catenary file with its overrides.
/// `before_work`: called once both are read and before anything is computed on the catenary (the
/// cost guard: a finite-element line is built when first used, catenary/fe_catenary.hpp).
using BeforeWork = std::function<void(const pantograph::Pantograph&, const io::CatenaryFile&)>;
std::pair<pantograph::Pantograph, io::CatenaryFile> pantograph_setup(const std::string& path, const CatenaryArgs& c,
                                                                     bool no_centripetal = false,
                                                                     const BeforeWork& before_work = {});

void add_catenary_options(CLI::App* app, CatenaryArgs& c, bool required);

/// The cost guard (analysis/cost_guard.hpp): an estimate beyond 10 s is printed on standard error
/// before the work starts; beyond max_seconds (--max-seconds; ≤ 0: no limit) the command is refused
/// (exit 2) with how to proceed.
void cost_guard(double seconds, double bytes, double max_seconds, const std::string& what, const std::string& cheaper);

/// What makes work on a finite-element line cheaper (the keys of --set).
inline constexpr const char* kFeCheaper =
    "fewer spans with --set line.spans=N, a coarser mesh with mesh.element_length, the modal solve with solver.type=modal";

/// The assembly's Newton iterations and largest correction (check, simulate).
void print_assembly(std::FILE* to, const mbs::Model& model, const mbs::AssemblyReport& a);

/// CSV numbers: 10 significant digits, shortest general form.
void append_number(std::string& s, double v);

/// Largest number of points of a range option (--freq, --speeds, --fp).
inline constexpr double max_range_points = 1e6;

/// What a range accepts: a first value > 0 (speeds) or >= 0, and at most this many points.
struct RangeRule {
  bool positive = false;
  double max_points = max_range_points;
};

/// "F0:DF:F1" → F0, F0 + DF, ..., F1 (inclusive within 1e-9 DF); a usage error naming `option` otherwise.
std::vector<double> frequency_range(const std::string& spec, const char* option = "--freq", const RangeRule& rule = {});

}  // namespace inerta::cli
