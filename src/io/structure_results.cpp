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

std::vector<std::string> write_admittance_results(const std::string& dir, const std::vector<optim::AdmittanceBound>& bounds,
                                                  double default_J) {
  namespace fs = std::filesystem;
  auto poly = [](const network::Poly& p) {
    std::string t;
    for (double c : p) t += fmt::format("{}{:.8g}", t.empty() ? "" : " ", c);
    return t;
  };
  std::string csv = "degree,J,vs_default_pct,best_network,best_network_J,gap_pct,num,den,pr_re_min,realised,realised_elements,"
                    "realised_reactive,minimal_reactive,method,realised_J,evaluations\n";
  Json rows = Json::array();
  for (const auto& b : bounds) {
    const auto& r = b.result;
    const std::string realised = r.synthesis ? network::to_string(r.synthesis->network, true) : "";
    csv += fmt::format("{},{:.10g},{:.4g},{},{:.10g},{:.4g},{},{},{:.6g},{},{},{},{},{},{:.10g},{}\n", r.degree, r.J,
                       pct(r.J, default_J), b.best ? "\"" + b.best->label + "\"" : "", b.best ? b.best->J : NAN, b.gap_pct(),
                       poly(r.y.num), poly(r.y.den), r.pr.re_min, r.synthesis ? "\"" + realised + "\"" : "",
                       r.synthesis ? r.synthesis->elements : 0, r.synthesis ? r.synthesis->reactive : 0,
                       r.synthesis && r.synthesis->minimal_reactive ? 1 : 0, r.synthesis ? r.synthesis->method : "",
                       r.J_realised, r.evaluations);
    rows.push_back({{"degree", r.degree}, {"feasible", b.feasible()}, {"J", r.J}, {"num", r.y.num}, {"den", r.y.den},
                    {"positive_real", r.pr.positive_real}, {"re_min", r.pr.re_min},
                    {"best_network", b.best ? b.best->label : ""}, {"best_network_J", b.best ? b.best->J : NAN},
                    {"realised", realised}, {"realised_elements", r.synthesis ? r.synthesis->elements : 0},
                    {"minimal_reactive", r.synthesis && r.synthesis->minimal_reactive}, {"realised_J", r.J_realised},
                    {"evaluations", r.evaluations}});
  }
  fs::create_directories(dir);
  const std::string csv_path = (fs::path(dir) / "admittance.csv").string(), json_path = (fs::path(dir) / "admittance.json").string();
  write_text_file(csv_path, csv);
  write_json(json_path, rows);
  return {csv_path, json_path};
}

}  // namespace inerta::io
