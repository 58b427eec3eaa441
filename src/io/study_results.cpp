#include "inerta/io/study_results.hpp"

#include <fmt/format.h>

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
    layouts.push_back(std::move(l));
  }
  Json j;
  j["study"] = study;
  j["default_J2"] = default_cost.J;
  j["layouts"] = std::move(layouts);
  return j;
}

std::vector<std::string> write_study_results(const std::string& dir, const std::string& study,
                                             const optim::StudyCost& default_cost,
                                             const std::vector<optim::LayoutResult>& results) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::string csv_path = (fs::path(dir) / "results.csv").string(),
                    json_path = (fs::path(dir) / "results.json").string();
  std::string csv = "layout,network,b,c,k,J2,reduction_pct,v_kmh,mean_N,evaluations\n";
  for (const auto& r : results)
    csv += fmt::format("{},{},{},{},{},{:.6g},{:.4g},{:.6g},{:.6g},{}\n", csv_field(r.layout),
                       csv_field(r.expression), csv_field(value_text(r.values, "b")), csv_field(value_text(r.values, "c")),
                       csv_field(value_text(r.values, "k")), r.cost.J,
                       reduction_pct(r.cost, default_cost), r.cost.speed * 3.6, r.cost.mean, r.evaluations);
  write_text_file(csv_path, csv);
  write_json(json_path, study_results_json(study, default_cost, results));
  return {csv_path, json_path};
}

}  // namespace inerta::io
