#include "inerta/optim/study.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::optim {

namespace {
Study read_study(const std::string& path) {
  YAML::Node loaded;
  try {
    loaded = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ModelError(fmt::format("{}: cannot open the study file", path));
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", path, e.mark.line + 1, e.msg));
  }
  const YAML::Node& root = loaded;
  if (!root.IsMap()) io::yaml_fail(path, root, "", "expected a study (model, catenary, catenaries, speeds, layouts)");
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    static const char* allowed[] = {"name",   "model",   "catenary", "catenaries",
                                    "speeds", "layouts", "search",   "harmonics"};
    if (std::find_if(std::begin(allowed), std::end(allowed), [&](const char* a) { return k == a; }) ==
        std::end(allowed))
      io::yaml_fail(path, it->first, k,
                    "unknown key; expected name, model, catenary, catenaries, speeds, layouts, search, harmonics");
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  auto rel = [&](const YAML::Node& n, const char* key) {
    if (!n.IsDefined() || !n.IsScalar())
      io::yaml_fail(path, n.IsDefined() ? n : root, key, "missing; expected a file path");
    return (dir / n.Scalar()).string();
  };
  Study s;
  s.source = path;
  s.name = root["name"].IsDefined() ? root["name"].as<std::string>() : path;
  s.pantograph = io::load_model(rel(root["model"], "model"));
  const std::string cat_path = rel(root["catenary"], "catenary");
  const YAML::Node cats = root["catenaries"];
  if (cats.IsDefined()) {
    if (!cats.IsSequence() || cats.size() == 0)
      io::yaml_fail(path, cats, "catenaries", "expected a list of override lists");
    for (const auto& c : cats) {
      std::vector<std::string> sets;
      if (!c.IsSequence()) io::yaml_fail(path, c, "catenaries", "expected a list such as [catenary.kc0=5000]");
      for (const auto& x : c) sets.push_back(x.as<std::string>());
      io::CatenaryFile f = io::load_catenary(cat_path, sets);
      s.catenaries.push_back(f.catenary);
      s.contact = f.contact;
      std::string label;
      for (const auto& x : sets) label += (label.empty() ? "" : " ") + x;
      s.catenary_labels.push_back(label.empty() ? "default" : label);
    }
  } else {
    io::CatenaryFile f = io::load_catenary(cat_path);
    s.catenaries.push_back(f.catenary), s.contact = f.contact, s.catenary_labels.push_back("default");
  }
  const YAML::Node sp = root["speeds"];
  if (!sp.IsMap()) io::yaml_fail(path, sp.IsDefined() ? sp : root, "speeds", "expected {from, to, step, unit: kmh|ms}");
  const double from = io::yaml_number(path, sp["from"], "from"), to = io::yaml_number(path, sp["to"], "to"),
               step = io::yaml_number(path, sp["step"], "step");
  const std::string unit = sp["unit"].IsDefined() ? sp["unit"].as<std::string>() : "ms";
  if (unit != "kmh" && unit != "ms") io::yaml_fail(path, sp["unit"], "unit", "expected kmh or ms");
  if (!(from > 0) || !(to >= from) || !(step > 0))
    io::yaml_fail(path, sp, "speeds", "expected 0 < from <= to and step > 0");
  for (long k = 0; from + k * step <= to + 1e-9 * step; ++k)
    s.speeds.push_back((from + k * step) / (unit == "kmh" ? 3.6 : 1.0));
  const YAML::Node ls = root["layouts"];
  if (!ls.IsSequence() || ls.size() == 0)
    io::yaml_fail(path, ls.IsDefined() ? ls : root, "layouts", "expected a list of layouts");
  for (const auto& l : ls) {
    const std::string name = l.as<std::string>();
    try {
      network::parse(network::find_layout(name) ? network::find_layout(name)->expression : name);
    } catch (const network::NetworkError& e) {
      io::yaml_fail(path, l, "layouts", fmt::format("'{}': {}", name, e.what()));
    }
    s.layouts.push_back(name);
  }
  if (const YAML::Node se = root["search"]; se.IsDefined()) {
    for (auto it = se.begin(); it != se.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      const YAML::Node v = it->second;
      if (k == "starts")
        s.search.starts = static_cast<int>(io::yaml_number(path, v, k));
      else if (k == "seed")
        s.search.seed = static_cast<unsigned>(io::yaml_number(path, v, k));
      else if (k == "lo")
        s.lo = io::yaml_number(path, v, k);
      else if (k == "hi")
        s.hi = io::yaml_number(path, v, k);
      else if (k == "min_step")
        s.search.min_step = io::yaml_number(path, v, k);
      else if (k == "max_evaluations")
        s.search.max_evaluations = static_cast<int>(io::yaml_number(path, v, k));
      else
        io::yaml_fail(path, it->first, k,
                      "unknown key in search; expected starts, seed, lo, hi, min_step, max_evaluations");
    }
    if (!(s.lo > 0) || !(s.hi > s.lo)) io::yaml_fail(path, se, "search", "expected 0 < lo < hi");
    if (s.search.starts < 1) io::yaml_fail(path, se["starts"], "starts", "must be >= 1");
  }
  if (root["harmonics"].IsDefined())
    s.harmonics = static_cast<int>(io::yaml_number(path, root["harmonics"], "harmonics"));
  int act = -1;
  for (std::size_t k = 0; k < s.pantograph.forces.size(); ++k)
    if (std::dynamic_pointer_cast<const mbs::Actuator>(s.pantograph.forces[k])) act = static_cast<int>(k);
  if (act < 0)
    io::yaml_fail(path, root["model"], "model", "the pantograph has no actuator whose suspension the study replaces");
  for (const auto& cat : s.catenaries) {
    mbs::Model m =
        catenary::couple(s.pantograph, cat, s.contact, 1.0, s.pantograph.contact_marker, s.pantograph.rig_joint);
    mbs::State x = mbs::assemble(m, 0.0);
    mbs::static_equilibrium(m, 0.0, x);
    s.operating_length.push_back(m.forces[static_cast<std::size_t>(act)]->length(m, x));
  }
  return s;
}
}  // namespace

Study load_study(const std::string& path) {
  try {
    return read_study(path);
  } catch (const YAML::Exception& e) {  // a wrong node type (a map where a layout name belongs, ...)
    throw ModelError(
        fmt::format("{}:{}: {}; expected the study file format of docs/model-format.md", path, e.mark.line + 1, e.msg));
  }
}

network::Network default_suspension(const Study& study) {
  for (const auto& f : study.pantograph.forces)
    if (auto a = std::dynamic_pointer_cast<const mbs::Actuator>(f)) return a->network();
  throw ModelError(
      fmt::format("{}: the pantograph has no actuator whose suspension the study could replace", study.source));
}

StudyCost evaluate(const Study& study, const network::Network& net) {
  StudyCost c;
  c.J = -1;
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {
    mbs::Model m = pantograph::with_suspension(study.pantograph, net, study.operating_length[i]);
    auto r = analysis::sweep_periodic(m, study.catenaries[i], study.contact, study.speeds, study.harmonics);
    for (const auto& x : r)
      if (x.stats.std > c.J)
        c.J = x.stats.std, c.speed = x.speed, c.mean = x.stats.mean, c.catenary = static_cast<int>(i);
  }
  return c;
}

StudyCost evaluate_time(const Study& study, const network::Network& net) {
  StudyCost c;
  c.J = -1;
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {
    mbs::Model m = pantograph::with_suspension(study.pantograph, net, study.operating_length[i]);
    auto r = analysis::sweep(m, study.catenaries[i], study.contact, study.speeds, analysis::RunOptions{});
    for (const auto& x : r)
      if (x.stats.std > c.J)
        c.J = x.stats.std, c.speed = x.speed, c.mean = x.stats.mean, c.catenary = static_cast<int>(i);
  }
  return c;
}

std::vector<std::string> free_parameters(const std::string& layout) {
  auto named = network::find_layout(layout);
  std::vector<std::string> names;
  for (const auto& name : network::parameter_names(network::parse(named ? named->expression : layout)))
    if (!named || !named->fixed.count(name)) names.push_back(name);
  return names;
}

LayoutResult optimise_layout(const Study& study, const std::string& layout, const numerics::Progress& progress) {
  LayoutResult r;
  r.layout = layout;
  auto named = network::find_layout(layout);
  r.expression = named ? named->expression : layout;
  const network::Params fixed = named ? named->fixed : network::Params{};
  std::vector<numerics::Variable> vars;
  for (const auto& name : free_parameters(layout)) vars.push_back({name, study.lo, study.hi, true, true});
  auto params_of = [&](const std::vector<double>& values) {
    network::Params p;
    for (std::size_t i = 0; i < vars.size(); ++i) p[vars[i].name] = values[i];
    return p;
  };
  auto J = [&](const std::vector<double>& values) {
    const network::Network net = network::resolve(layout, params_of(values));
    // A rigid suspension locks the pantograph (with_suspension refuses it): no design.
    if (network::simplify(net).kind == network::Network::Kind::Rigid) return static_cast<double>(INFINITY);
    try {
      return evaluate(study, net).J;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);  // no static equilibrium or steady state for these values
    }
  };
  std::vector<double> best;
  if (vars.empty()) {
    r.evaluations = 1;
  } else {
    numerics::Result s = numerics::pattern_search(vars, J, study.search, progress);
    best = s.values;
    r.evaluations = s.evaluations;
  }
  r.values = fixed;
  for (const auto& [k, v] : params_of(best)) r.values[k] = v;
  r.cost = evaluate(study, network::resolve(layout, params_of(best)));
  return r;
}

}  // namespace inerta::optim
