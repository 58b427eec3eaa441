#include "inerta/io/study_report.hpp"

#include "inerta/io/files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>

#include "inerta/io/json.hpp"

namespace inerta::io {

namespace {

// A number in report.json: NaN as null, ±∞ as "inf" / "-inf".
Json number(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

Json params(const network::Params& p) {
  Json j = Json::object();
  for (const auto& [k, v] : p) j[k] = number(v);
  return j;
}

// A CSV of the report, written safely (io/files.hpp): complete only after commit().
struct File {
  explicit File(const std::filesystem::path& p) : path(p.string()), f(path) {}
  std::string path;
  OutputFile f;
  void commit() { f.commit(); }
};

void write_curves(std::FILE* out, const std::string& prefix, const std::vector<optim::SpeedCurve>& curves) {
  for (const auto& c : curves)
    for (std::size_t k = 0; k < c.speed.size(); ++k)
      fmt::print(out, "{},{},{:.10g},{:.10g},{:.10g}\n", prefix, csv_field(c.catenary), c.speed[k] * 3.6, c.sigma[k],
                 c.mean[k]);
}

}  // namespace

std::vector<std::string> write_study_report(const optim::Report& r, const std::string& dir) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  std::vector<std::string> written;
  {
    File csv(fs::path(dir) / "sigma.csv");
    fmt::print(csv.f.get(), "design,catenary,v_kmh,sigma_N,mean_N\n");
    write_curves(csv.f.get(), "default", r.sigma_default);
    write_curves(csv.f.get(), "best", r.sigma_best);
    csv.commit();
    written.push_back(csv.path);
  }
  {
    File csv(fs::path(dir) / "frf.csv");
    fmt::print(csv.f.get(), "design,f_hz,mag,phase_deg\n");
    for (const auto& [name, frf] : {std::pair{"default", &r.frf_default}, std::pair{"best", &r.frf_best}})
      for (std::size_t k = 0; k < frf->f.size(); ++k)
        fmt::print(csv.f.get(), "{},{:.10g},{:.10g},{:.10g}\n", name, frf->f[k], std::abs(frf->H[0][k]),
                   std::arg(frf->H[0][k]) * 180 / std::numbers::pi);
    csv.commit();
    written.push_back(csv.path);
  }
  {
    File csv(fs::path(dir) / "contact.csv");
    fmt::print(csv.f.get(), "design,catenary,t_s,F_N\n");
    for (const auto& [name, hs] : {std::pair{"default", &r.history_default}, std::pair{"best", &r.history_best}})
      for (const auto& h : *hs)
        for (std::size_t k = 0; k < h.t.size(); ++k)
          fmt::print(csv.f.get(), "{},{},{:.10g},{:.10g}\n", name, csv_field(h.catenary), h.t[k], h.F[k]);
    csv.commit();
    written.push_back(csv.path);
  }
  if (!r.margins.empty()) {  // every criterion of the acceptance set: the band of F_m(v), σ's limit, each margin
    File csv(fs::path(dir) / "acceptance_margins.csv");
    fmt::print(csv.f.get(), "design,catenary,v_kmh,contact,criterion,value,limit,unit,margin,relative_margin,assessed,passed\n");
    for (const optim::MarginRow& m : r.margins)
      fmt::print(csv.f.get(), "{},{},{:.6g},{},{},{:.10g},{:.10g},{},{:.10g},{:.10g},{},{}\n", csv_field(m.design),
                 csv_field(m.catenary), m.speed * 3.6, m.contact, m.result.criterion, m.result.value, m.result.limit,
                 m.result.unit, m.result.margin, m.relative, m.result.assessed ? 1 : 0, m.result.passed ? 1 : 0);
    csv.commit();
    written.push_back(csv.path);
  }
  if (r.map) {
    File csv(fs::path(dir) / "j2_map.csv");
    fmt::print(csv.f.get(), "{},{},J2_N\n", r.map->x, r.map->y);
    for (std::size_t i = 0; i < r.map->xs.size(); ++i)
      for (std::size_t j = 0; j < r.map->ys.size(); ++j)
        fmt::print(csv.f.get(), "{:.10g},{:.10g},{:.10g}\n", r.map->xs[i], r.map->ys[j], r.map->at(i, j));
    csv.commit();
    written.push_back(csv.path);
  }
  {
    File csv(fs::path(dir) / "centripetal.csv");
    fmt::print(csv.f.get(), "design,centripetal,catenary,v_kmh,sigma_N,mean_N\n");
    for (const auto& c : r.centripetal) {
      write_curves(csv.f.get(), csv_field(c.design.label) + ",on", c.on);
      if (c.off_simulated) write_curves(csv.f.get(), csv_field(c.design.label) + ",off", c.off);
    }
    csv.commit();
    written.push_back(csv.path);
  }
  {
    auto design = [](const optim::Design& d) {
      return Json{{"label", d.label},
                  {"layout", d.layout},
                  {"values", params(d.values)},
                  {"network", network::to_string(d.net, true)}};
    };
    auto cost = [](const optim::StudyCost& c) {
      return Json{{"J2", number(c.J)}, {"v_kmh", number(c.speed * 3.6)}, {"mean_N", number(c.mean)}, {"catenary", c.catenary}};
    };
    Json j;
    j["study"] = r.study;
    j["catenaries"] = r.catenaries;
    if (!r.acceptance.empty()) j["acceptance"] = r.acceptance;
    j["default"] = design(r.baseline);
    j["default_cost"] = cost(r.default_cost);
    j["best"] = design(r.best);
    j["best_cost"] = cost(r.best_cost);
    j["time_check"] = cost(r.time_check);
    j["frf_output"] = r.frf_output;
    j["history_v_kmh"] = number(r.history_speed * 3.6);
    if (r.map) {
      j["map"] = Json{{"layout", r.map->layout},
                      {"x", r.map->x},
                      {"y", r.map->y},
                      {"values", params(r.map->values)},
                      {"optimum", Json{{"x", number(r.map_opt_x)}, {"y", number(r.map_opt_y)}, {"J2", number(r.map_opt_J)}}}};
    } else {
      j["map"] = nullptr;
      j["map_note"] = r.map_note;
    }
    Json cs = Json::array();
    for (const auto& c : r.centripetal)
      cs.push_back(Json{{"design", design(c.design)},
                        {"on", cost(optim::worst_of(c.on))},
                        {"off", cost(optim::worst_of(c.off))},
                        {"inerter", optim::has_inerter(c.design.net)},
                        {"off_simulated", c.off_simulated}});
    j["centripetal"] = cs;
    const std::string path = (fs::path(dir) / "report.json").string();
    write_json(path, j);
    written.push_back(path);
  }
  return written;
}


}  // namespace inerta::io
