#include "inerta/io/model_study_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "inerta/io/files.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::io {

namespace {
std::string results_csv(const optim::ModelStudyResult& r) {
  const optim::Objective& o = r.study.objective;
  const double J0 = r.baseline_cost.J;
  // A column per element name of any layout.
  std::vector<std::string> elements;
  for (const auto& x : r.results)
    for (const auto& [k, v] : x.values)
      if (std::find(elements.begin(), elements.end(), k) == elements.end()) elements.push_back(k);
  std::string s = "layout,expression,J,vs_default_pct,feasible,evaluations";
  for (const auto& w : o.outputs) s += fmt::format(",{}", csv_field(w.name));
  for (const auto& lim : o.limits) s += fmt::format(",{}", csv_field(lim.output));
  for (const auto& e : elements) s += fmt::format(",{}", csv_field(e));
  s += "\n";
  auto line = [&](const std::string& layout, const std::string& expr, const optim::ModelCost& c, int evals,
                  const network::Params& p) {
    s += fmt::format("{},{},{:.10g},{:.6g},{},{}", csv_field(layout), csv_field(expr), c.J, 100 * (c.J - J0) / J0,
                     c.feasible ? 1 : 0, evals);
    for (double v : c.values) s += fmt::format(",{:.10g}", v);
    for (double v : c.limit_values) s += fmt::format(",{:.10g}", v);
    for (const auto& e : elements) {
      const auto it = p.find(e);
      s += it == p.end() ? std::string(",") : fmt::format(",{:.10g}", it->second);
    }
    s += "\n";
  };
  line("default", network::to_string(r.baseline, true), r.baseline_cost, 1, {});
  for (const auto& x : r.results) line(x.layout, x.expression, x.cost, x.evaluations, x.values);
  return s;
}

Json results_json(const optim::ModelStudyResult& r) {
  Json j;
  j["study"] = r.study.name;
  j["objective"] = optim::Objective::name(r.study.objective.kind);
  j["default"] = {{"network", network::to_string(r.baseline, true)},
                  {"J", r.baseline_cost.J},
                  {"values", r.baseline_cost.values},
                  {"limits", r.baseline_cost.limit_values}};
  Json rows = Json::array();
  for (const auto& x : r.results) {
    Json v = Json::object();
    for (const auto& [k, val] : x.values) v[k] = std::isinf(val) ? Json("inf") : Json(val);
    rows.push_back({{"layout", x.layout}, {"expression", x.expression}, {"J", x.cost.J}, {"feasible", x.cost.feasible},
                    {"outputs", x.cost.values}, {"limits", x.cost.limit_values}, {"values", v}, {"at_limits", x.at_bounds},
                    {"evaluations", x.evaluations}});
  }
  j["layouts"] = rows;
  j["best"] = r.results.empty() ? std::string() : r.results[r.best].layout;
  return j;
}

std::string frf_csv(const optim::StudyFrf& d, const optim::StudyFrf& b) {
  std::string s = "f_hz";
  for (const auto& n : d.outputs) s += fmt::format(",{0}_default,{0}_best", n);
  s += "\n";
  for (std::size_t k = 0; k < d.f.size(); ++k) {
    s += fmt::format("{:.10g}", d.f[k]);
    for (std::size_t i = 0; i < d.outputs.size(); ++i) s += fmt::format(",{:.10g},{:.10g}", d.magnitude[i][k], b.magnitude[i][k]);
    s += "\n";
  }
  return s;
}

std::string map_csv(const optim::ObjectiveMap& m, optim::Objective::Kind kind) {
  std::string s = fmt::format("# {} of layout {} over {} (rows) and {} (columns)\n{}", optim::Objective::name(kind), m.layout,
                              m.x_name, m.y_name, m.x_name + "\\" + m.y_name);
  for (double y : m.y) s += fmt::format(",{:.6g}", y);
  s += "\n";
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    s += fmt::format("{:.6g}", m.x[i]);
    for (double v : m.J[i]) s += fmt::format(",{:.8g}", v);
    s += "\n";
  }
  return s;
}
}  // namespace

std::vector<std::string> write_model_study_results(const std::string& dir, const optim::ModelStudyResult& r,
                                                   const optim::ModelStudyFigures& fig) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  std::vector<std::string> written;
  if (!r.admittance.empty()) written = write_admittance_results(dir, r.admittance, r.baseline_cost.J);
  if (r.study.all)
    for (auto& p : write_structure_results(dir, r.study.name, optim::Objective::name(r.study.objective.kind), "",
                                           r.baseline_cost.J, r.entries))
      written.push_back(std::move(p));
  auto put = [&](const std::string& name, const std::string& text) {
    const std::string path = (fs::path(dir) / name).string();
    write_text_file(path, text);
    written.push_back(path);
  };
  put("results.csv", results_csv(r));
  const std::string json_path = (fs::path(dir) / "results.json").string();
  write_json(json_path, results_json(r));
  written.push_back(json_path);
  if (fig.frf_default && fig.frf_best) put("frf.csv", frf_csv(*fig.frf_default, *fig.frf_best));
  if (fig.map) put("map.csv", map_csv(*fig.map, r.study.objective.kind));
  return written;
}

std::string model_study_table(const optim::ModelStudyResult& run) {
  const optim::ModelStudy& study = run.study;
  const optim::Objective& o = study.objective;
  const network::Network& baseline = run.baseline;
  const optim::ModelCost& def = run.baseline_cost;
  const auto& results = run.results;
  std::string t = fmt::format("\n  {:<14} {:<14} {:>12} {:>10}", "layout", "network", "J", "vs default");
  for (const auto& w : o.outputs) t += fmt::format(" {:>12}", w.name);
  for (const auto& lim : o.limits) t += fmt::format(" {:>12}", lim.output + "≤" + fmt::format("{:g}", lim.limit));
  t += "  values (SI)\n";
  auto row = [&](const std::string& layout, const std::string& expr, const optim::ModelCost& c, const std::string& values,
                 const std::string& bounds, bool exhausted) {
    t += fmt::format("  {:<14} {:<14} {:>12.6g} {:>9.1f}%", layout, expr, c.J, 100 * (c.J - def.J) / def.J);
    for (double v : c.values) t += fmt::format(" {:>12.5g}", v);
    for (double v : c.limit_values) t += fmt::format(" {:>12.5g}", v);
    t += fmt::format("  {}{}{}{}\n", values, bounds.empty() ? "" : "  at limits: " + bounds, c.feasible ? "" : "  INFEASIBLE",
                     exhausted ? "  budget exhausted (max_evaluations reached before min_step)" : "");
  };
  row("(default)", network::to_string(baseline), def, network::to_string(baseline, true), "", false);
  const std::size_t shown = study.all ? 25 : results.size();
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (i == shown) t += fmt::format("  … {} more in results.csv (with --out)\n", results.size() - shown);
    std::string values, bounds;
    for (const auto& [k, v] : r.values) values += fmt::format("{}{}={}", values.empty() ? "" : " ", k, numerics::describe(v));
    for (const auto& b : r.at_bounds) bounds += (bounds.empty() ? "" : ",") + b;
    if (i < shown) row(r.layout, r.expression, r.cost, values, bounds, r.budget_exhausted);
  }
  const auto& best = results[run.best];
  t += fmt::format("default ({}) J = {:.6g}; best {} ({}) J = {:.6g} ({:+.1f} %); wall {:.2f} s\n",
                   network::to_string(baseline, true), def.J, best.layout, best.expression, best.cost.J,
                   100 * (best.cost.J - def.J) / def.J, run.seconds);
  return t;
}

}  // namespace inerta::io
