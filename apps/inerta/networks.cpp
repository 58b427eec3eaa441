#include "networks.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "inerta/io/data_dir.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/io/files.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/network/schematic.hpp"
#include "common.hpp"

namespace inerta::cli {

namespace {
struct NetworksArgs {
  int max_elements = 4;
  std::string elements = "kcb", static_load = "any", out;
  int max_springs = -1, max_dampers = -1, max_inerters = -1;
} networks_args;
CLI::App* networks_cmd = nullptr;

struct DrawArgs {
  std::string layout, out;
  std::vector<std::string> params;
} draw_args;
CLI::App* draw_cmd = nullptr;

// `inerta networks draw LAYOUT [--param NAME=VALUE …] --out FILE.svg`: the schematic (network/schematic.hpp).
int run_draw() {
  const DrawArgs& a = draw_args;
  io::check_output_path(a.out);
  network::Network net;
  try {
    if (a.params.empty()) {  // names only: the expression's, or the named layout's
      const auto named = network::find_layout(a.layout);
      net = network::parse(named ? named->expression : a.layout);
    } else {
      net = network::resolve(a.layout, parse_params(a.params));
    }
  } catch (const network::NetworkError& e) {
    std::string where = e.column > 0 ? fmt::format("\n  {}\n  {:>{}}", a.layout, "^", e.column) : "";
    throw ModelError(fmt::format("network '{}': {}{}", a.layout, e.what(), where));
  }
  const std::string svg = network::schematic_svg(net, {.values = true, .title = network::to_string(net)});
  if (a.out.empty()) {
    fmt::print("{}", svg);
    return 0;
  }
  io::write_text_file(a.out, svg);
  fmt::print("wrote {} (the schematic of {})\n", a.out, network::to_string(net, !a.params.empty()));
  return 0;
}

std::string seconds_text(double s) {
  if (s < 90) return fmt::format("{:.0f} s", s);
  if (s < 5400) return fmt::format("{:.1f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}
}  // namespace

CLI::App* add_networks_command(CLI::App& app) {
  NetworksArgs& a = networks_args;
  networks_cmd = app.add_subcommand("networks", "List every series–parallel spring/damper/inerter network up to N elements");
  networks_cmd->add_option("--max-elements", a.max_elements, fmt::format("Largest number of elements, 1 … {}", network::max_enumerated_elements))
      ->capture_default_str();
  networks_cmd->add_option("--elements", a.elements, "Element types allowed, letters of k (spring), c (damper), b (inerter)")
      ->capture_default_str();
  networks_cmd->add_option("--max-springs", a.max_springs, "At most this many springs (-1: no limit)");
  networks_cmd->add_option("--max-dampers", a.max_dampers, "At most this many dampers (-1: no limit)");
  networks_cmd->add_option("--max-inerters", a.max_inerters, "At most this many inerters (-1: no limit)");
  networks_cmd->add_option("--static-load", a.static_load,
                           "any | required (a spring path between the terminals) | excluded")
      ->capture_default_str();
  networks_cmd->add_option("--out", a.out, "Write the list to this file (one expression per line) instead of stdout");
  DrawArgs& d = draw_args;
  draw_cmd = networks_cmd->add_subcommand("draw", "Draw a network as a mechanical schematic (SVG)");
  draw_cmd->add_option("layout", d.layout, "A layout name (S2-5) or an expression such as \"k1|(k2-c-b)\"")->required();
  draw_cmd->add_option("--param", d.params, "Element values NAME=VALUE (SI), shown on the drawing; all or none");
  draw_cmd->add_option("--out", d.out, "Write the SVG to this file (default: standard output)");
  return networks_cmd;
}

int run_networks() {
  if (draw_cmd->parsed()) return run_draw();
  const NetworksArgs& a = networks_args;
  network::EnumerationOptions o;
  o.max_elements = a.max_elements;
  o.springs = o.dampers = o.inerters = false;
  for (char c : a.elements) {
    if (c == 'k') o.springs = true;
    else if (c == 'c') o.dampers = true;
    else if (c == 'b') o.inerters = true;
    else if (c != ',' && c != ' ')
      throw CLI::ValidationError("--elements", fmt::format("'{}' is not an element type; expected letters of k, c, b", c));
  }
  o.max_springs = a.max_springs, o.max_dampers = a.max_dampers, o.max_inerters = a.max_inerters;
  if (a.static_load == "any") o.static_load = network::StaticLoad::Any;
  else if (a.static_load == "required") o.static_load = network::StaticLoad::Required;
  else if (a.static_load == "excluded") o.static_load = network::StaticLoad::Excluded;
  else throw CLI::ValidationError("--static-load", "expected any, required or excluded, got '" + a.static_load + "'");
  std::vector<std::string> nets;
  try {
    nets = network::enumerate(o);
  } catch (const network::NetworkError& e) {
    throw CLI::ValidationError(e.what());  // already "networks: ..."
  }
  std::map<int, int> per;
  std::string text;
  for (const auto& e : nets) {
    const auto c = network::count_elements(network::parse(e));
    ++per[c.elements];
    text += e + "\n";
  }
  if (a.out.empty()) fmt::print("{}", text);
  else io::write_text_file(a.out, text);
  std::string summary;
  for (const auto& [n, k] : per) summary += fmt::format("{}{} with {}", summary.empty() ? "" : ", ", k, n);
  std::fprintf(a.out.empty() ? stderr : stdout, "%s\n",
               fmt::format("{} networks ({}){}", nets.size(), summary.empty() ? "none" : summary,
                           a.out.empty() ? "" : "; wrote " + a.out)
                   .c_str());
  return 0;
}

optim::StructureProgressFn structure_progress(const std::string& unit) {
  const bool tty = isatty(STDOUT_FILENO);
  auto last_pct = std::make_shared<int>(-1);
  return [tty, unit, last_pct](const optim::StructureProgress& p) {
    const std::string line =
        fmt::format("  [{}/{}] {:<22} J = {:<10.5g} best {:.5g} {} ({})  elapsed {}, ≈ {} left", p.done, p.total,
                    p.last ? p.last->expression : "", p.last ? p.last->J : NAN, p.best_J, unit, p.best,
                    seconds_text(p.elapsed), seconds_text(p.remaining));
    if (tty) {
      fmt::print("\r{:<150.150}", line);
      if (p.done == p.total) fmt::print("\n");
    } else {
      const int pct = 20 * p.done / std::max(1, p.total);
      if (pct != *last_pct || p.done == p.total) fmt::print("{}\n", line), *last_pct = pct;
    }
    std::fflush(stdout);
  };
}

void print_structure(const std::vector<optim::StructureEntry>& entries, double default_J, const std::string& unit,
                     std::size_t rows) {
  const auto order = optim::ranking(entries);
  const std::string J = unit.empty() ? "J" : "J [" + unit + "]";
  if (rows > 0) fmt::print("\n  {:>4}  {:<24} {:>12} {:>10}  {:<8}  {}\n", "rank", "network", J, "vs default", "elements",
             "optimum (reduced network, SI values)");
  for (std::size_t r = 0; r < std::min(rows, order.size()); ++r) {
    const auto& e = entries[order[r]];
    fmt::print("  {:>4}  {:<24} {:>12.6g} {:>9.2f}%  {:<8}  {}{}{}\n", r + 1, e.expression, e.J, 100 * (e.J - default_J) / default_J,
               e.reduces() ? fmt::format("{}→{}", e.counts.elements, e.reduced_counts.elements) : fmt::format("{}", e.counts.elements),
               e.reduced, e.feasible ? "" : "  INFEASIBLE",
               e.unstable ? fmt::format("  ({} unstable designs refused)", e.unstable) : std::string());
  }
  if (rows > 0 && order.size() > rows) fmt::print("  … {} more networks in structure.csv (with --out)\n", order.size() - rows);
  int reduced = 0;
  for (const auto& e : entries) reduced += e.reduces() ? 1 : 0;
  fmt::print("{} of {} networks reduce at their optimum to a smaller network (an element open or rigid, or merged)\n", reduced,
             entries.size());
  int unstable_networks = 0, unstable_designs = 0;
  for (const auto& e : entries) unstable_networks += e.unstable ? 1 : 0, unstable_designs += e.unstable;
  if (unstable_designs)
    fmt::print("{} networks met designs whose periodic solution is unstable (Floquet multiplier ≥ 1): {} designs refused "
               "(J = ∞; the `unstable` column of structure.csv)\n",
               unstable_networks, unstable_designs);
  fmt::print("\nbest by complexity (reduced networks; * = Pareto-optimal: nothing simpler does better):\n");
  fmt::print("  {:>8} {:>8} {:>12} {:>10}  {}\n", "elements", "inerters", J, "vs default", "network");
  for (const auto& p : optim::pareto_points(entries))
    fmt::print("  {:>8} {:>8} {:>12.6g} {:>9.2f}%  {}{}\n", p.elements, p.inerters, p.J, 100 * (p.J - default_J) / default_J,
               p.network, p.pareto ? "  *" : "");
}

bool run_script(const std::string& name, const std::string& dir) {
  const std::filesystem::path script = io::data_dir() / "scripts" / name;
  if (!std::filesystem::exists(script)) return false;
  auto q = [](const std::string& x) {
    std::string r = "'";
    for (char c : x) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return r + "'";
  };
  std::fflush(stdout);
  // With Debian's interpreter by name (another python3 first on PATH may lack matplotlib), not the shebang's.
  return std::system((q(INERTA_PYTHON) + " " + q(script.string()) + " " + q(dir)).c_str()) == 0;
}

std::function<void(const optim::AdmittanceBound&)> print_admittance_bound(double default_J, const std::string& unit) {
  return [default_J, u = unit.empty() ? std::string() : " " + unit, first = true](const optim::AdmittanceBound& b) mutable {
    if (first) fmt::print("\npositive-real admittance bound (degree d: any network with at most d springs and inerters):\n");
    first = false;
    const auto& r = b.result;
    fmt::print("  degree {}: J = {:.6g}{} ({:+.2f} % vs default){} after {} evaluations, {:.1f} s; started from {}\n", r.degree,
               r.J, u, 100 * (r.J - default_J) / default_J, b.feasible() ? "" : ", a limit is EXCEEDED", r.evaluations,
               b.seconds, r.warm_from);
    fmt::print("    {}\n", network::to_string(network::admittance_leaf(r.y.num, r.y.den)));
    fmt::print("    positive real: {} (min Re Y(jω) = {:.4g} at ω = {:.4g} rad/s)\n", r.pr.positive_real ? "yes" : "NO: " + r.pr.reason,
               r.pr.re_min, r.pr.omega_min);
    if (b.best)
      fmt::print("    best network with ≤ {} springs+inerters: {} J = {:.6g}{}, {:.2f} % above the bound\n", r.degree, b.best->label,
                 b.best->J, u, b.gap_pct());
    if (r.synthesis)
      fmt::print("    realised ({}): {} — {} elements, {} reactive{}; {}\n", r.synthesis->method,
                 network::to_string(r.synthesis->network, true), r.synthesis->elements, r.synthesis->reactive,
                 r.synthesis->minimal_reactive ? " (= degree: minimal in springs and inerters)" : " (not known to be minimal)",
                 std::isfinite(r.J_realised) ? fmt::format("J = {:.6g}{}", r.J_realised, u)
                                             : std::string("not evaluable (a pole beyond 1e6 rad/s: elements too small or large)"));
    else
      fmt::print("    not realised: {}\n", r.synthesis_error);
  };
}

}  // namespace inerta::cli
