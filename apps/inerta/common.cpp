#include "common.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <sstream>

#include "inerta/analysis/commission.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::cli {

network::Params parse_params(const std::vector<std::string>& list) {
  network::Params params;
  for (const auto& p : list) {
    auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CLI::ValidationError("--param", "expected NAME=VALUE, got '" + p + "'");
    std::string name = p.substr(0, eq), v = p.substr(eq + 1);
    double value = 0;
    if (params.count(name)) throw CLI::ValidationError("--param", "'" + name + "' is given twice");
    std::string lower = v;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower == "inf" || lower == ".inf")
      value = INFINITY;
    else if (lower.find("0x") != std::string::npos)  // strtod reads hex; a value in SI is never written so
      throw CLI::ValidationError("--param", "a hexadecimal number in '" + p + "': give the value in decimal, SI units");
    else if (!CLI::detail::lexical_cast(v, value))
      throw CLI::ValidationError("--param", "not a number in '" + p + "'");
    params[name] = value;
  }
  return params;
}


std::pair<pantograph::Pantograph, io::CatenaryFile> pantograph_setup(const std::string& path, const CatenaryArgs& c,
                                                                     bool no_centripetal, const BeforeWork& before_work) {
  // --set NAME.KEY: to the model if NAME is one of its elements, bodies or joints (or lumped_pantograph),
  // else to the catenary file.
  const auto [panto_sets, cat_sets] = io::split_overrides(path, c.sets);
  pantograph::Pantograph p = io::load_pantograph(path, panto_sets);
  if (no_centripetal) p.model.options.centripetal = false;
  io::CatenaryFile cat = io::load_catenary(c.catenary, cat_sets);
  if (!c.contact.empty())
    cat.contact.kind = c.contact == "penalty" ? catenary::Contact::Kind::Penalty : catenary::Contact::Kind::Bilateral;
  if (before_work) before_work(p, cat);
  if (!c.suspension.empty()) {
    network::Network net;
    try {
      net = network::resolve(c.suspension, parse_params(c.params));
    } catch (const network::NetworkError& e) {
      throw ModelError(fmt::format("--suspension '{}': {}", c.suspension, e.what()));
    }
    // --relaxed: at the actuator's length of the static equilibrium with the model's own suspension
    // under this catenary, as a study's candidates (analysis::operating_length); else the old network's.
    p.model = pantograph::with_suspension(p.model, net, c.relaxed ? analysis::operating_length(p, *cat.catenary, cat.contact) : -1);
  } else if (!c.params.empty()) {
    throw CLI::ValidationError("--param", "needs --suspension LAYOUT");
  } else if (c.relaxed) {
    throw CLI::ValidationError("--relaxed", "needs --suspension LAYOUT");
  }
  return {p, cat};
}

void add_catenary_options(CLI::App* app, CatenaryArgs& c, bool required) {
  auto* o = app->add_option("--catenary", c.catenary, "Catenary file (models/catenary.yaml)");
  if (required) o->required();
  app->add_option("--unit", c.unit, "Speed unit: ms (m/s) or kmh")
      ->check(CLI::IsMember({"ms", "kmh"}))
      ->capture_default_str();
  app->add_option("--set", c.sets,
                  "Override a value NAME.KEY=VALUE of the model (a force element, body or joint: k_s.k=12000, "
                  "drive.speed=20, lumped_pantograph.static_uplift=90) or of the catenary (catenary.kc0=5000); "
                  "repeatable");
  app->add_option("--contact", c.contact, "bilateral (thesis) or penalty; default: the catenary file's")
      ->check(CLI::IsMember({"bilateral", "penalty"}));
  app->add_option("--suspension", c.suspension, "Replace the actuator's dynamic network by this layout or expression");
  app->add_option("--param", c.params, "Suspension element value NAME=VALUE (repeatable)");
  app->add_flag("--allow-supercritical", c.allow_supercritical,
                "Run above the contact wire's wave speed (refused otherwise; a warning from 70 % of it)");
  app->add_flag("--relaxed", c.relaxed,
                "Relax the --suspension network at the static equilibrium with the model's own suspension under this "
                "catenary, as a study's candidates (default: at the replaced network's reference length)");
}

void cost_guard(double seconds, double bytes, double max_seconds, const std::string& what, const std::string& cheaper) {
  analysis::check_memory(bytes, what, cheaper);
  if (max_seconds > 0) analysis::check_cost(seconds, max_seconds, what, "give --max-seconds", cheaper);
  if (const std::string note = analysis::cost_note(seconds, what); !note.empty()) fmt::print(stderr, "{}\n", note);
}

std::vector<double> frequency_range(const std::string& spec, const char* option, const RangeRule& rule) {
  double f0 = 0, df = 0, f1 = 0;
  char c1 = 0, c2 = 0;
  std::istringstream in(spec);
  if (!(in >> f0 >> c1 >> df >> c2 >> f1) || c1 != ':' || c2 != ':' || !(in >> std::ws).eof() || !(rule.positive ? f0 > 0 : f0 >= 0) ||
      !(df > 0) || !(f1 >= f0))
    throw CLI::ValidationError(option, fmt::format("expected A:STEP:B with 0 {} A <= B and STEP > 0, got '{}'", rule.positive ? "<" : "<=", spec));
  // At most max_range_points points (docs/cli.md), counted in floating point before any cast (issue 15).
  const double n = std::floor((f1 - f0) / df + 1e-9);
  if (!std::isfinite(f1) || !(n < rule.max_points))
    throw CLI::ValidationError(option, fmt::format("'{}' has {:.3g} points; at most {} are accepted (a larger STEP "
                                                   "or a shorter range)",
                                                   spec, n + 1, rule.max_points));
  std::vector<double> f;
  for (long k = 0; k <= static_cast<long>(n); ++k) f.push_back(f0 + static_cast<double>(k) * df);
  for (std::size_t k = 1; k < f.size(); ++k)
    if (!(f[k] > f[k - 1]))
      throw CLI::ValidationError(option, fmt::format("'{}': STEP {:g} is below the resolution of the values", spec, df));
  return f;
}

void print_assembly(std::FILE* to, const mbs::Model& model, const mbs::AssemblyReport& a) {
  fmt::print(to, "assembly: max |C| {:.3g} -> {:.3g} in {} Newton iteration(s)", a.initial_residual, a.residual,
             a.iterations);
  if (a.dq.size() > 0 && a.dq.cwiseAbs().maxCoeff() > 0)
    fmt::print(to, "; largest correction {:+.4g} {} on {}", a.dq[a.largest],
               model.spatial() ? (a.largest % 7 >= 3 ? "" : "m") : (a.largest % 3 == 2 ? "rad" : "m"),
               model.coord_name(a.largest));
  fmt::print(to, "\n");
}

void append_number(std::string& s, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 10);
  s.append(buf, r.ptr);
}

}  // namespace inerta::cli
