#include "inerta/io/study_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>

#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/network/layouts.hpp"
#include "network_options.hpp"

namespace inerta::io {

namespace {
constexpr double max_study_speeds = 10000;

optim::Study read_study(const std::string& path) {
  const YAML::Node loaded = yaml_load_file(path, "study file");
  const YAML::Node& root = loaded;
  if (!root.IsMap()) yaml_fail(path, root, "", "expected a study (model, catenary, catenaries, speeds, layouts)");
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    static const char* allowed[] = {"name",   "model",   "catenary", "catenaries",
                                    "speeds", "layouts", "search",   "harmonics", "objective", "networks", "admittance"};
    if (std::find_if(std::begin(allowed), std::end(allowed), [&](const char* a) { return k == a; }) ==
        std::end(allowed))
      yaml_fail(path, it->first, k,
                    "unknown key; expected name, model, catenary, catenaries, speeds, layouts, networks, admittance, search, "
                    "harmonics, objective");
  }
  if (const YAML::Node o = root["objective"]; o.IsDefined()) {  // optional: a pantograph study's objective is J2
    if (!o.IsMap() || o.size() != 1 || !o["type"].IsDefined() || !o["type"].IsScalar() || o["type"].Scalar() != "j2")
      yaml_fail(path, o, "objective", "a study with catenary: optimises J2; expected objective: {type: j2} or no objective");
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  auto rel = [&](const YAML::Node& n, const char* key) {
    if (!n.IsDefined() || !n.IsScalar())
      yaml_fail(path, n.IsDefined() ? n : root, key, "missing; expected a file path");
    return (dir / n.Scalar()).string();
  };
  optim::Study s;
  s.source = path;
  s.name = root["name"].IsDefined() ? root["name"].as<std::string>() : path;
  s.pantograph = load_pantograph(rel(root["model"], "model"));
  const std::string cat_path = rel(root["catenary"], "catenary");
  const YAML::Node cats = root["catenaries"];
  if (cats.IsDefined()) {
    if (!cats.IsSequence() || cats.size() == 0)
      yaml_fail(path, cats, "catenaries", "expected a list of override lists");
    for (const auto& c : cats) {
      std::vector<std::string> sets;
      if (!c.IsSequence()) yaml_fail(path, c, "catenaries", "expected a list such as [catenary.kc0=5000]");
      for (const auto& x : c) sets.push_back(x.as<std::string>());
      CatenaryFile f = load_catenary(cat_path, sets);
      s.catenaries.push_back(f.catenary);
      s.contact = f.contact;
      std::string label;
      for (const auto& x : sets) label += (label.empty() ? "" : " ") + x;
      s.catenary_labels.push_back(label.empty() ? "default" : label);
    }
  } else {
    CatenaryFile f = load_catenary(cat_path);
    s.catenaries.push_back(f.catenary), s.contact = f.contact, s.catenary_labels.push_back("default");
  }
  const YAML::Node sp = root["speeds"];
  if (!sp.IsMap()) yaml_fail(path, sp.IsDefined() ? sp : root, "speeds", "expected {from, to, step, unit: kmh|ms}");
  for (auto it = sp.begin(); it != sp.end(); ++it)
    if (const std::string k = it->first.Scalar(); k != "from" && k != "to" && k != "step" && k != "unit")
      yaml_fail(path, it->first, k, "unknown key in speeds; expected from, to, step, unit");
  const double from = yaml_number(path, sp["from"], "from"), to = yaml_number(path, sp["to"], "to"),
               step = yaml_number(path, sp["step"], "step");
  const std::string unit = sp["unit"].IsDefined() ? sp["unit"].as<std::string>() : "ms";
  if (unit != "kmh" && unit != "ms") yaml_fail(path, sp["unit"], "unit", "expected kmh or ms");
  if (!(from > 0) || !(to >= from) || !(step > 0))
    yaml_fail(path, sp, "speeds", "expected 0 < from <= to and step > 0");
  if (!((to - from) / step < max_study_speeds))
    yaml_fail(path, sp, "speeds", fmt::format("more than {} speeds; a larger step", max_study_speeds));
  for (long k = 0; from + k * step <= to + 1e-9 * step; ++k)
    s.speeds.push_back((from + k * step) / (unit == "kmh" ? 3.6 : 1.0));
  const YAML::Node ls = root["layouts"];
  s.all = read_all_layouts(path, root);
  s.admittance_degrees = read_admittance_degrees(path, root);
  if (s.all) {
    s.layouts = network::enumerate(*s.all);
    if (s.layouts.empty()) yaml_fail(path, root["networks"], "networks", "no network satisfies these options");
  } else if (!ls.IsSequence() || ls.size() == 0) {
    yaml_fail(path, ls.IsDefined() ? ls : root, "layouts", "expected a list of layouts, or all (with networks: {max_elements: N})");
  }
  for (const auto& l : s.all ? YAML::Node(YAML::NodeType::Sequence) : ls) {
    const std::string name = l.as<std::string>();
    try {
      network::parse(network::find_layout(name) ? network::find_layout(name)->expression : name);
    } catch (const network::NetworkError& e) {
      yaml_fail(path, l, "layouts", fmt::format("'{}': {}", name, e.what()));
    }
    s.layouts.push_back(name);
  }
  if (const YAML::Node se = root["search"]; se.IsDefined()) {
    for (auto it = se.begin(); it != se.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      const YAML::Node v = it->second;
      if (k == "starts")
        s.search.starts = static_cast<int>(yaml_integer(path, v, k, 1, 10000));
      else if (k == "seed")
        s.search.seed = static_cast<unsigned>(yaml_integer(path, v, k, 0, 4294967295L));
      else if (k == "lo")
        s.lo = yaml_number(path, v, k);
      else if (k == "hi")
        s.hi = yaml_number(path, v, k);
      else if (k == "min_step")
        s.search.min_step = yaml_number_in(path, v, k, 1e-9, 10, "a mesh size from 1e-9 to 10 (decades)");
      else if (k == "max_evaluations")
        s.search.max_evaluations = static_cast<int>(yaml_integer(path, v, k, 1, 100000000));
      else
        yaml_fail(path, it->first, k,
                      "unknown key in search; expected starts, seed, lo, hi, min_step, max_evaluations");
    }
    if (!(s.lo > 0) || !(s.hi > s.lo)) yaml_fail(path, se, "search", "expected 0 < lo < hi (SI units)");
    if (s.search.initial_step < s.search.min_step) s.search.initial_step = s.search.min_step;
  }
  if (root["harmonics"].IsDefined())
    s.harmonics = static_cast<int>(yaml_integer(path, root["harmonics"], "harmonics", 1, analysis::max_harmonics));
  try {
    s.operating_length = optim::operating_lengths(s);
  } catch (const ModelError& e) {
    yaml_fail(path, root["model"], "model", e.what());
  }
  return s;
}
}  // namespace

optim::Study load_study(const std::string& path) {
  try {
    return read_study(path);
  } catch (const YAML::Exception& e) {  // a wrong node type (a map where a layout name belongs, ...)
    throw ModelError(
        fmt::format("{}:{}: {}; expected the study file format of docs/model-format.md", path, e.mark.line + 1, e.msg));
  }
}

}  // namespace inerta::io
