#include "inerta/io/structure_results.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "inerta/io/files.hpp"

namespace inerta::io {

namespace {
std::string values_text(const network::Params& p) {
  std::string s;
  for (const auto& [k, v] : p)
    s += fmt::format("{}{}={}", s.empty() ? "" : ";", k, v == 0 ? std::string("0") : std::isinf(v) ? std::string("inf") : fmt::format("{:.10g}", v));
  return s;
}
double pct(double J, double def) { return 100 * (J - def) / def; }
}  // namespace

Json structure_results_json(const std::string& study, const std::string& objective, const std::string& unit,
                            double default_J, const std::vector<optim::StructureEntry>& entries) {
  Json rows = Json::array();
  int rank = 0;
  for (std::size_t i : optim::ranking(entries)) {
    const auto& e = entries[i];
    Json values = Json::object();
    for (const auto& [k, v] : e.values) values[k] = std::isinf(v) ? Json("inf") : Json(v);
    rows.push_back({{"rank", ++rank},
                    {"network", e.expression},
                    {"elements", e.counts.elements},
                    {"springs", e.counts.springs},
                    {"dampers", e.counts.dampers},
                    {"inerters", e.counts.inerters},
                    {"J", std::isfinite(e.J) ? Json(e.J) : Json(nullptr)},
                    {"feasible", e.feasible},
                    {"reduced", e.reduced},
                    {"reduced_elements", e.reduced_counts.elements},
                    {"reduced_inerters", e.reduced_counts.inerters},
                    {"values", values},
                    {"evaluations", e.evaluations},
                    {"unstable", e.unstable},
                    {"seconds", e.seconds},
                    {"warm_from", e.warm_from}});
  }
  return {{"study", study}, {"objective", objective}, {"unit", unit}, {"default_J", default_J}, {"networks", rows}};
}

std::vector<std::string> write_structure_results(const std::string& dir, const std::string& study,
                                                 const std::string& objective, const std::string& unit, double default_J,
                                                 const std::vector<optim::StructureEntry>& entries) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::string csv_path = (fs::path(dir) / "structure.csv").string(),
                    json_path = (fs::path(dir) / "structure.json").string(),
                    pareto_path = (fs::path(dir) / "pareto.csv").string();
  std::string csv =
      "rank,network,elements,springs,dampers,inerters,J,vs_default_pct,feasible,reduced,reduced_elements,"
      "reduced_inerters,values,evaluations,seconds,warm_from,unstable\n";
  int rank = 0;
  for (std::size_t i : optim::ranking(entries)) {
    const auto& e = entries[i];
    csv += fmt::format("{},{},{},{},{},{},{:.10g},{:.4g},{},{},{},{},{},{},{:.3f},{},{}\n", ++rank, csv_field(e.expression),
                       e.counts.elements, e.counts.springs, e.counts.dampers, e.counts.inerters, e.J, pct(e.J, default_J),
                       e.feasible ? 1 : 0, csv_field(e.reduced), e.reduced_counts.elements, e.reduced_counts.inerters,
                       csv_field(values_text(e.values)), e.evaluations, e.seconds, csv_field(e.warm_from),
                       e.unstable);
  }
  write_text_file(csv_path, csv);
  write_json(json_path, structure_results_json(study, objective, unit, default_J, entries));
  std::string p = "elements,inerters,J,vs_default_pct,pareto,network\n";
  for (const auto& q : optim::pareto_points(entries))
    p += fmt::format("{},{},{:.10g},{:.4g},{},{}\n", q.elements, q.inerters, q.J, pct(q.J, default_J), q.pareto ? 1 : 0,
                     csv_field(q.network));
  write_text_file(pareto_path, p);
  return {csv_path, json_path, pareto_path};
}

}  // namespace inerta::io
