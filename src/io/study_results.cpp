#include "inerta/io/study_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "inerta/io/files.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::io {

namespace {

// An element value in results.json: 0 (open) as the integer 0, ∞ (rigid) as "inf".
Json value_json(double v) {
  if (v == 0) return 0;
  if (std::isinf(v)) return "inf";
  return v;
}

// An element value in results.csv.
std::string value_text(const network::Params& p, const char* name) {
  auto it = p.find(name);
  return it == p.end() ? std::string("-") : numerics::describe(it->second);
}

double reduction_pct(const optim::StudyCost& c, const optim::StudyCost& def) { return 100 * (c.J - def.J) / def.J; }

}  // namespace

Json study_results_json(const std::string& study, const optim::StudyCost& default_cost,
                        const std::vector<optim::LayoutResult>& results) {
  Json layouts = Json::array();
  for (const auto& r : results) {
    Json values = Json::object();
    for (const auto& [k, v] : r.values) values[k] = value_json(v);
    Json l;
    l["layout"] = r.layout;
    l["network"] = r.expression;
    l["values"] = std::move(values);
    l["J2"] = r.cost.J;
    l["v_kmh"] = r.cost.speed * 3.6;
    l["mean_N"] = r.cost.mean;
    l["evaluations"] = r.evaluations;
    if (!r.cost.feasible) l["feasible"] = false, l["violation"] = r.cost.violation;
    if (!r.cost.binding.empty()) l["binding"] = r.cost.binding, l["binding_margin"] = r.cost.binding_margin;
    if (r.stock) l["stock"] = true;
    if (const auto& c = r.cost.commissioning)
      l["commissioning"] = Json{{"a", c->a},
                                {"static_stiffness", c->static_stiffness},
                                {"static_force", c->static_force},
                                {"static_force_min", c->range_min()},
                                {"static_force_max", c->range_max()},
                                {"operating_length", c->operating_length},
                                {"trim_mean", c->mean},
                                {"sigma", r.cost.sigma}};
    if (r.coarse_evaluations > 0) {
      Json cv = Json::object();
      for (const auto& [k, v] : r.coarse_values) cv[k] = value_json(v);
      l["coarse"] = Json{{"values", std::move(cv)}, {"J2", r.coarse_cost.J}, {"J2_here", r.coarse_here.J},
                         {"evaluations", r.coarse_evaluations}};
    }
    layouts.push_back(std::move(l));
  }
  Json j;
  j["study"] = study;
  j["default_J2"] = default_cost.J;
  j["layouts"] = std::move(layouts);
  return j;
}

std::string study_table(const optim::Study& study, const optim::StudyCost& def,
                        const std::vector<optim::LayoutResult>& results) {
  const std::string J = study.objective == optim::Study::Objective::J2 ? "J2 [N]" : "σ/F_m";
  std::string t = fmt::format("\n  {:<12} {:<10} {:>11} {:>11} {:>11} {:>9} {:>11} {:>10} {:>10}\n", "layout", "network",
                              "b [kg]", "c [N·s/m]", "k [N/m]", J, "vs default", "v [km/h]", "F_m [N]");
  bool marked = false;
  for (const auto& r : results) {
    auto v = [&](const char* k) {  // '*': ended on a bound
      const bool at = std::find(r.at_bounds.begin(), r.at_bounds.end(), k) != r.at_bounds.end();
      marked = marked || at;
      return value_text(r.values, k) + (at ? "*" : "");
    };
    t += fmt::format("  {:<12} {:<10} {:>11} {:>11} {:>11} {:>9.3f} {:>10.1f}% {:>10.0f} {:>10.2f}{}{}\n", r.layout,
                     r.expression, v("b"), v("c"), v("k"), r.cost.J, reduction_pct(r.cost, def), r.cost.speed * 3.6,
                     r.cost.mean, r.budget_exhausted ? "  budget exhausted" : "",
                     r.cost.feasible ? "" : "  outside the limits: " + r.cost.violation);
    if (study.limits.acceptance && !r.cost.binding.empty())
      t += fmt::format("  {:<12} binds: {} (margin {:+.1f} % of its limit)\n", "", r.cost.binding, 100 * r.cost.binding_margin);
  }
  if (marked) t += "  *: on a bound (the search's lo/hi, an element kind's bounds, open or rigid)\n";
  const optim::ContactLimits& L = study.limits;
  if (L.any())
    t += fmt::format("  limits (every catenary and speed):{}{}{}{}{}\n",
                     std::isnan(L.mean_min) ? "" : fmt::format(" mean {:g}–{:g} N;", L.mean_min, L.mean_max),
                     std::isnan(L.loss_max) ? "" : fmt::format(" contact loss ≤ {:g} %;", L.loss_max),
                     std::isnan(L.statistical_min) ? "" : fmt::format(" F_m − 3σ ≥ {:g} N;", L.statistical_min),
                     std::isnan(L.uplift_max) ? "" : fmt::format(" support uplift ≤ {:g} m", L.uplift_max),
                     L.acceptance ? fmt::format("{}every criterion of the acceptance set {} ({})", std::isnan(L.uplift_max) ? " " : "; ", L.acceptance->name, L.acceptance->source) : "");
  if (study.coarse) {
    t += fmt::format("\n  multi-fidelity: J2 [N] of the coarse optimum on the coarse study and here, and after the refinement\n"
                     "  {:<12} {:>12} {:>12} {:>12} {:>9} {:>12}\n",
                     "layout", "coarse", "coarse here", "refined", "change", "evaluations");
    for (const auto& r : results)
      t += fmt::format("  {:<12} {:>12.3f} {:>12.3f} {:>12.3f} {:>8.1f}% {:>5} + {:<5}\n", r.layout, r.coarse_cost.J,
                       r.coarse_here.J, r.cost.J, 100 * (r.cost.J - r.coarse_here.J) / r.coarse_here.J,
                       r.coarse_evaluations, r.evaluations);
  }
  return t;
}

std::vector<std::string> write_study_results(const std::string& dir, const std::string& study,
                                             const optim::StudyCost& default_cost,
                                             const std::vector<optim::LayoutResult>& results) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::string csv_path = (fs::path(dir) / "results.csv").string(),
                    json_path = (fs::path(dir) / "results.json").string();
  // A commissioned study (issue 49): what commissioning set for each design, and which row is the stock one.
  const bool commissioned = std::any_of(results.begin(), results.end(), [](const auto& r) { return r.cost.commissioning.has_value(); });
  std::string csv = "layout,network,b,c,k,J2,reduction_pct,v_kmh,mean_N,evaluations";
  csv += commissioned ? ",stock,sigma_N,a,static_stiffness,static_force,static_force_min,static_force_max\n" : "\n";
  for (const auto& r : results) {
    csv += fmt::format("{},{},{},{},{},{:.6g},{:.4g},{:.6g},{:.6g},{}", csv_field(r.layout),
                       csv_field(r.expression), csv_field(value_text(r.values, "b")), csv_field(value_text(r.values, "c")),
                       csv_field(value_text(r.values, "k")), r.cost.J,
                       reduction_pct(r.cost, default_cost), r.cost.speed * 3.6, r.cost.mean, r.evaluations);
    if (!commissioned) {
      csv += "\n";
      continue;
    }
    const analysis::Commissioning c = r.cost.commissioning.value_or(analysis::Commissioning{});
    csv += fmt::format(",{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", r.stock ? 1 : 0, r.cost.sigma, c.a, c.static_stiffness,
                       c.static_force, c.range_min(), c.range_max());
  }
  write_text_file(csv_path, csv);
  write_json(json_path, study_results_json(study, default_cost, results));
  return {csv_path, json_path};
}

}  // namespace inerta::io
