#include "inerta/io/model_study_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/mbs/road.hpp"
#include "inerta/network/layouts.hpp"
#include "network_options.hpp"

namespace inerta::io {

namespace {

// yaml-cpp throws on the type of a missing key's node: test IsDefined first.
bool is_scalar(const YAML::Node& n) { return n.IsDefined() && n.IsScalar(); }
bool is_map(const YAML::Node& n) { return n.IsDefined() && n.IsMap(); }
bool is_seq(const YAML::Node& n) { return n.IsDefined() && n.IsSequence(); }

void only_keys(const std::string& path, const YAML::Node& map, const std::string& where,
               const std::vector<std::string>& allowed) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      yaml_fail(path, it->first, k, fmt::format("unknown key{}; expected one of: {}", where.empty() ? "" : " in " + where, list));
    }
  }
}

double positive(const std::string& path, const YAML::Node& n, const std::string& key, const char* unit) {
  const double v = yaml_number(path, n, key);
  if (!(v > 0) || !std::isfinite(v)) yaml_fail(path, n, key, fmt::format("must be a finite number > 0 ({}), got {}", unit, n.Scalar()));
  return v;
}


std::vector<std::string> names(const std::string& path, const YAML::Node& n, const std::string& key) {
  if (!is_seq(n) || n.size() == 0) yaml_fail(path, n, key, "expected a list of names, e.g. [road]");
  std::vector<std::string> out;
  for (const auto& x : n) {
    if (!is_scalar(x)) yaml_fail(path, x, key, "expected a name");
    out.push_back(x.Scalar());
  }
  return out;
}

// {name: weight, ...} (or a list of names: weight 1).
std::vector<optim::WeightedOutput> weighted(const std::string& path, const YAML::Node& n, const std::string& key) {
  std::vector<optim::WeightedOutput> out;
  if (is_seq(n)) {
    for (const auto& name : names(path, n, key)) out.push_back({name, 1.0});
  } else if (is_map(n) && n.size() > 0) {
    for (auto it = n.begin(); it != n.end(); ++it)
      out.push_back({it->first.as<std::string>(), positive(path, it->second, it->first.as<std::string>(), "weight")});
  } else {
    yaml_fail(path, n, key, "expected outputs with weights, e.g. {a_body: 1}, or a list of output names");
  }
  return out;
}


optim::Objective read_objective(const std::string& path, const YAML::Node& o, const mbs::Model& model) {
  optim::Objective obj;
  if (!is_map(o)) yaml_fail(path, o, "objective", "expected a mapping with type: rms | hinf | peak");
  const YAML::Node type = o["type"];
  if (!is_scalar(type)) yaml_fail(path, o, "type", "missing; expected rms, hinf or peak");
  const std::string t = type.Scalar();
  auto known_output = [&](const YAML::Node& at, const std::string& name) {
    for (const auto& out : model.outputs)
      if (out.name == name) return;
    std::string list;
    for (const auto& out : model.outputs) list += (list.empty() ? "" : ", ") + out.name;
    yaml_fail(path, at, name, fmt::format("no output of that name in the model; outputs: {}", list));
  };
  auto check_outputs = [&](const YAML::Node& n) {
    for (const auto& w : obj.outputs) known_output(n, w.name);
  };
  if (t == "rms") {
    obj.kind = optim::Objective::Kind::Rms;
    only_keys(path, o, "objective", {"type", "outputs", "road", "white_noise", "limits"});
    if (!o["outputs"].IsDefined()) yaml_fail(path, o, "outputs", "missing; expected e.g. {a_body: 1}");
    obj.outputs = weighted(path, o["outputs"], "outputs");
    check_outputs(o["outputs"]);
    const YAML::Node road = o["road"], noise = o["white_noise"];
    if (road.IsDefined() == noise.IsDefined())
      yaml_fail(path, o, "objective", "give exactly one excitation: road: {class, speed, inputs} or white_noise: {INPUT: intensity}");
    if (road.IsDefined()) {
      if (!is_map(road)) yaml_fail(path, road, "road", "expected {class: A..H or gd0, speed, inputs, delays, pade_order}");
      only_keys(path, road, "road", {"class", "gd0", "speed", "inputs", "delays", "pade_order"});
      analysis::Road r;
      if (road["class"].IsDefined() == road["gd0"].IsDefined())
        yaml_fail(path, road, "road", "give one of class (ISO 8608, A to H) and gd0 (m³)");
      if (road["class"].IsDefined()) {
        const std::string c = road["class"].Scalar();
        try {
          if (c.size() != 1) throw InvalidArgument("class");
          r.gd0 = mbs::iso8608_gd0(c[0]);
        } catch (const InvalidArgument&) {
          yaml_fail(path, road["class"], "class", fmt::format("expected an ISO 8608 class A to H, got '{}'", c));
        }
      } else {
        r.gd0 = positive(path, road["gd0"], "gd0", "m³");
      }
      if (!road["speed"].IsDefined()) yaml_fail(path, road, "speed", "missing; expected the speed in m/s");
      r.speed = positive(path, road["speed"], "speed", "m/s");
      if (!road["inputs"].IsDefined()) yaml_fail(path, road, "inputs", "missing; expected the driving joints that see the road");
      r.inputs = names(path, road["inputs"], "inputs");
      if (road["delays"].IsDefined()) {
        const YAML::Node d = road["delays"];
        if (!is_seq(d) || d.size() != r.inputs.size())
          yaml_fail(path, d, "delays", fmt::format("expected {} delay(s) in s, one per input", r.inputs.size()));
        for (const auto& x : d) {
          const double v = yaml_number(path, x, "delays");
          if (!(v >= 0) || !std::isfinite(v)) yaml_fail(path, x, "delays", "must be >= 0 (s)");
          r.delays.push_back(v);
        }
      }
      if (road["pade_order"].IsDefined()) r.pade_order = yaml_whole(path, road["pade_order"], "pade_order", 1, 20);
      obj.road = r;
    } else {
      if (!is_map(noise) || noise.size() == 0)
        yaml_fail(path, noise, "white_noise", "expected {INPUT: intensity, ...}: E[u(t)u(s)] = intensity δ(t − s)");
      for (auto it = noise.begin(); it != noise.end(); ++it) {
        obj.noise_inputs.push_back(it->first.as<std::string>());
        obj.noise_intensity.push_back(positive(path, it->second, it->first.as<std::string>(), "intensity, unit² s"));
      }
    }
    if (const YAML::Node l = o["limits"]; l.IsDefined()) {
      if (!is_map(l) || l.size() == 0) yaml_fail(path, l, "limits", "expected {OUTPUT: largest rms, ...}");
      for (auto it = l.begin(); it != l.end(); ++it) {
        const std::string name = it->first.as<std::string>();
        known_output(it->first, name);
        obj.limits.push_back({name, positive(path, it->second, name, "the output's unit")});
      }
    }
  } else if (t == "hinf") {
    obj.kind = optim::Objective::Kind::Hinf;
    only_keys(path, o, "objective", {"type", "input", "outputs", "band"});
    if (!is_scalar(o["input"])) yaml_fail(path, o["input"].IsDefined() ? o["input"] : o, "input", "missing; expected one input name");
    obj.input = o["input"].Scalar();
    if (!o["outputs"].IsDefined()) yaml_fail(path, o, "outputs", "missing; expected e.g. {x: 1}");
    obj.outputs = weighted(path, o["outputs"], "outputs");
    check_outputs(o["outputs"]);
    const YAML::Node b = o["band"];
    if (!is_map(b)) yaml_fail(path, b.IsDefined() ? b : o, "band", "expected {from, to, points, spacing: linear|log} in Hz");
    only_keys(path, b, "band", {"from", "to", "points", "spacing"});
    const double f0 = positive(path, b["from"], "from", "Hz"), f1 = positive(path, b["to"], "to", "Hz");
    if (!(f1 > f0)) yaml_fail(path, b, "band", "expected from < to");
    const int n = b["points"].IsDefined() ? yaml_whole(path, b["points"], "points", 2, 100000) : 500;
    const std::string sp = b["spacing"].IsDefined() ? b["spacing"].Scalar() : "linear";
    if (sp != "linear" && sp != "log") yaml_fail(path, b["spacing"], "spacing", "expected linear or log");
    for (int k = 0; k < n; ++k) {
      const double a = static_cast<double>(k) / (n - 1);
      obj.frequencies.push_back(sp == "log" ? f0 * std::pow(f1 / f0, a) : f0 + a * (f1 - f0));
    }
  } else if (t == "peak") {
    obj.kind = optim::Objective::Kind::Peak;
    only_keys(path, o, "objective", {"type", "outputs", "t_end", "sample"});
    if (!o["outputs"].IsDefined()) yaml_fail(path, o, "outputs", "missing; expected e.g. {travel: 1}");
    obj.outputs = weighted(path, o["outputs"], "outputs");
    check_outputs(o["outputs"]);
    if (o["t_end"].IsDefined()) obj.t_end = positive(path, o["t_end"], "t_end", "s");
    if (o["sample"].IsDefined()) obj.sample = positive(path, o["sample"], "sample", "s");
    if (obj.t_end / obj.sample > 1e7) yaml_fail(path, o["sample"], "sample", "more than 1e7 samples; expected a larger sample");
  } else {
    yaml_fail(path, type, "type", fmt::format("unknown objective '{}'; expected rms, hinf or peak (j2: a pantograph study with catenary:)", t));
  }
  return obj;
}

optim::ModelStudy read(const std::string& path, bool evaluate_baseline) {
  const YAML::Node loaded = yaml_load_file(path, "study file");
  const YAML::Node& root = loaded;
  if (!is_map(root)) yaml_fail(path, root, "", "expected a study (model, strut, objective, layouts)");
  only_keys(path, root, "", {"name", "model", "set", "strut", "objective", "layouts", "networks", "admittance", "search"});
  optim::ModelStudy s;
  s.source = path;
  s.name = is_scalar(root["name"]) ? root["name"].Scalar() : path;
  if (!is_scalar(root["model"])) yaml_fail(path, root["model"].IsDefined() ? root["model"] : root, "model", "missing; expected a model file path");
  const std::string model_path = (std::filesystem::path(path).parent_path() / root["model"].Scalar()).string();
  std::vector<std::string> sets;
  if (root["set"].IsDefined()) sets = names(path, root["set"], "set");
  try {
    s.model = load_model(model_path, sets);
  } catch (const ModelError& e) {
    yaml_fail(path, root["model"], "model", e.what());
  }
  if (!is_scalar(root["strut"])) yaml_fail(path, root["strut"].IsDefined() ? root["strut"] : root, "strut", "missing; expected the name of a network strut");
  s.strut = s.model.find_force(root["strut"].Scalar());
  if (s.strut < 0 || !s.model.forces[static_cast<std::size_t>(s.strut)]->strut_network()) {
    std::string list;
    for (const auto& f : s.model.forces)
      if (f->strut_network()) list += (list.empty() ? "" : ", ") + f->name();
    yaml_fail(path, root["strut"], "strut", fmt::format("'{}' is not a network strut of the model; network struts: {}",
                                                        root["strut"].Scalar(), list.empty() ? "none" : list));
  }
  if (!root["objective"].IsDefined()) yaml_fail(path, root, "objective", "missing; expected {type: rms | hinf | peak, ...}");
  s.objective = read_objective(path, root["objective"], s.model);
  const YAML::Node ls = root["layouts"];
  s.all = read_all_layouts(path, root);
  s.admittance_degrees = read_admittance_degrees(path, root);
  if (s.all) {
    s.layouts = network::enumerate(*s.all);
    if (s.layouts.empty()) yaml_fail(path, root["networks"], "networks", "no network satisfies these options");
  } else if (!is_seq(ls) || ls.size() == 0) {
    yaml_fail(path, ls.IsDefined() ? ls : root, "layouts",
              "expected a list of layouts (network expressions or names), or all (with networks: {max_elements: N})");
  }
  for (const auto& l : s.all ? YAML::Node(YAML::NodeType::Sequence) : ls) {
    if (!is_scalar(l)) yaml_fail(path, l, "layouts", "expected a network expression or a layout name");
    const std::string name = l.Scalar();
    if (std::find(s.layouts.begin(), s.layouts.end(), name) != s.layouts.end())
      yaml_fail(path, l, "layouts", fmt::format("'{}' is given twice; each layout is optimised once", name));
    try {
      network::parse(network::find_layout(name) ? network::find_layout(name)->expression : name);
    } catch (const network::NetworkError& e) {
      std::string known;
      for (const auto& k : network::layouts()) known += (known.empty() ? "" : ", ") + k.name;
      yaml_fail(path, l, "layouts", fmt::format("'{}' is neither a network expression ({}) nor a named layout; named layouts: {}",
                                                name, e.what(), known));
    }
    s.layouts.push_back(name);
  }
  if (const YAML::Node se = root["search"]; se.IsDefined()) {
    if (!is_map(se)) yaml_fail(path, se, "search", "expected {starts, seed, lo, hi, min_step, max_evaluations}");
    only_keys(path, se, "search", {"starts", "seed", "lo", "hi", "min_step", "max_evaluations"});
    if (se["starts"].IsDefined()) s.search.starts = yaml_whole(path, se["starts"], "starts", 1, 1000);
    if (se["seed"].IsDefined()) s.search.seed = static_cast<unsigned>(yaml_whole(path, se["seed"], "seed", 0, 2147483647));
    if (se["lo"].IsDefined()) s.lo = positive(path, se["lo"], "lo", "SI");
    if (se["hi"].IsDefined()) s.hi = positive(path, se["hi"], "hi", "SI");
    if (se["min_step"].IsDefined()) s.search.min_step = positive(path, se["min_step"], "min_step", "decades");
    if (se["max_evaluations"].IsDefined()) s.search.max_evaluations = yaml_whole(path, se["max_evaluations"], "max_evaluations", 1, 100000000);
    if (!(s.hi > s.lo)) yaml_fail(path, se, "search", "expected lo < hi");
  }
  // The baseline must evaluate: unknown inputs, an output with infinite variance, ... fail here.
  if (evaluate_baseline) {
    try {
      optim::evaluate(s, optim::default_network(s));
    } catch (const std::exception& e) {
      yaml_fail(path, root["objective"], "objective", fmt::format("cannot evaluate the model's own strut: {}", e.what()));
    }
  }
  return s;
}

}  // namespace

bool is_model_study(const std::string& path) {
  const YAML::Node root = yaml_load_file(path, "study file");
  if (!is_map(root)) return false;
  const YAML::Node o = root["objective"];
  // A pantograph study has catenary: (its objective j2 or sigma_over_mean); a model study has none.
  if (root["catenary"].IsDefined()) return false;
  return o.IsDefined() && !(is_map(o) && is_scalar(o["type"]) &&
                            (o["type"].Scalar() == "j2" || o["type"].Scalar() == "sigma_over_mean"));
}

optim::ModelStudy load_model_study(const std::string& path, bool evaluate_baseline) {
  try {
    return read(path, evaluate_baseline);
  } catch (const YAML::Exception& e) {
    throw ModelError(fmt::format("{}:{}: {}; expected the study file format of docs/studies.md", path, e.mark.line + 1, e.msg));
  }
}

}  // namespace inerta::io
