#include "inerta/io/model_study_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "inerta/io/files.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/structure_results.hpp"

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

}  // namespace inerta::io
