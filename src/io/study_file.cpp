#include "inerta/io/study_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>

#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/network/layouts.hpp"
#include "network_options.hpp"

namespace inerta::io {

namespace {
constexpr double max_study_speeds = 10000;

// `limits: {mean: [lo, hi], contact_loss: %, statistical_min: N, support_uplift: m}` (optim::ContactLimits).
optim::ContactLimits read_limits(const std::string& path, const YAML::Node& n) {
  optim::ContactLimits l;
  if (!n.IsMap()) yaml_fail(path, n, "limits", "expected a map of mean, contact_loss, statistical_min, support_uplift, acceptance");
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    if (k == "mean") {
      if (!v.IsSequence() || v.size() != 2) yaml_fail(path, v, k, "expected [lo, hi], N");
      l.mean_min = yaml_number(path, v[0], k), l.mean_max = yaml_number(path, v[1], k);
      if (!(l.mean_min > 0) || !(l.mean_max > l.mean_min)) yaml_fail(path, v, k, "expected 0 < lo < hi (N)");
    } else if (k == "contact_loss") {
      l.loss_max = yaml_number_in(path, v, k, 0, 100, "a percentage from 0 to 100");
    } else if (k == "statistical_min") {
      l.statistical_min = yaml_number(path, v, k);
    } else if (k == "support_uplift") {
      l.uplift_max = yaml_number_in(path, v, k, 1e-6, 10, "> 0 (m)");
    } else if (k == "acceptance") {  // a preset, or a criteria file relative to the study file
      if (!v.IsScalar()) yaml_fail(path, v, k, "expected a preset (en50367-ac, en50367-ac15, en50367-dc3, en50367-dc1.5) or a criteria file");
      std::string what = v.Scalar();
      const bool file = what.find('/') != std::string::npos || what.ends_with(".yaml") || what.ends_with(".yml");
      if (file && std::filesystem::path(what).is_relative())
        what = (std::filesystem::path(path).parent_path() / what).string();
      try {
        l.acceptance = std::make_shared<const analysis::AcceptanceCriteria>(load_acceptance(what));
      } catch (const ModelError& e) {
        yaml_fail(path, v, k, e.what());
      }
    } else {
      yaml_fail(path, it->first, k, "unknown key in limits; expected mean, contact_loss, statistical_min, support_uplift, acceptance");
    }
  }
  return l;
}

// `bounds: {inerter: [lo, hi], damper: [lo, hi], spring: [lo, hi]}`, SI; hi may be .inf.
std::map<char, optim::ElementBounds> read_bounds(const std::string& path, const YAML::Node& n) {
  std::map<char, optim::ElementBounds> b;
  if (!n.IsMap()) yaml_fail(path, n, "bounds", "expected a map of inerter, damper, spring: [lo, hi]");
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    const char kind = k == "inerter" ? 'b' : k == "damper" ? 'c' : k == "spring" ? 'k' : 0;
    if (!kind) yaml_fail(path, it->first, k, "unknown element kind in bounds; expected inerter (kg), damper (N·s/m), spring (N/m)");
    if (!v.IsSequence() || v.size() != 2) yaml_fail(path, v, k, "expected [lo, hi] in SI units (hi may be .inf)");
    optim::ElementBounds e;
    e.lo = yaml_number(path, v[0], k);
    const bool inf = v[1].IsScalar() && (v[1].Scalar() == ".inf" || v[1].Scalar() == "inf");
    e.hi = inf ? INFINITY : yaml_number(path, v[1], k);
    if (!(e.lo > 0) || !(e.hi > e.lo)) yaml_fail(path, v, k, "expected 0 < lo < hi (an element can always be left out: 0)");
    b[kind] = e;
  }
  return b;
}

// The search options of `search:` (starts, seed, lo, hi, min_step, max_evaluations) or `refine:`
// (optimiser, initial_step, min_step, max_evaluations, worst_speed_first, candidates).
void read_search(const std::string& path, const YAML::Node& se, optim::Study& s, bool refine) {
  numerics::Options& o = refine ? s.refine : s.search;
  if (!se.IsMap()) yaml_fail(path, se, refine ? "refine" : "search", "expected a map");
  for (auto it = se.begin(); it != se.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    if (k == "starts" && !refine)
      o.starts = static_cast<int>(yaml_integer(path, v, k, 1, 10000));
    else if (k == "seed" && !refine)
      o.seed = static_cast<unsigned>(yaml_integer(path, v, k, 0, 4294967295L));
    else if (k == "lo" && !refine)
      s.lo = yaml_number(path, v, k);
    else if (k == "hi" && !refine)
      s.hi = yaml_number(path, v, k);
    else if (k == "worst_speed_first" && refine)
      s.worst_speed_first = yaml_bool(path, v, k);
    else if (k == "optimiser" && refine) {
      const auto opt = v.IsScalar() ? numerics::parse_optimiser(v.Scalar()) : std::nullopt;
      if (!opt) yaml_fail(path, v, k, "unknown optimiser; expected pattern, bobyqa or cobyla");
      s.refine_optimiser = *opt;
    } else if (k == "candidates" && refine)
      s.refine_candidates = static_cast<int>(yaml_integer(path, v, k, 1, 100));
    else if (k == "best_networks" && refine) {
      if (!s.all) yaml_fail(path, it->first, k, "refines the best networks of layouts: all; this study names its layouts");
      s.refine_networks = static_cast<int>(yaml_integer(path, v, k, 1, 1000));
    }
    else if (k == "screen" && refine) {
      if (!s.all) yaml_fail(path, it->first, k, "screens the best networks of layouts: all; this study names its layouts");
      s.refine_screen = static_cast<int>(yaml_integer(path, v, k, 1, 1000));
    }
    else if (k == "initial_step" && refine)
      o.initial_step = yaml_number_in(path, v, k, 1e-9, 10, "a mesh size from 1e-9 to 10 (decades)");
    else if (k == "min_step")
      o.min_step = yaml_number_in(path, v, k, 1e-9, 10, "a mesh size from 1e-9 to 10 (decades)");
    else if (k == "max_evaluations")
      o.max_evaluations = static_cast<int>(yaml_integer(path, v, k, 1, 100000000));
    else
      yaml_fail(path, it->first, k,
                refine ? "unknown key in refine; expected optimiser, initial_step, min_step, max_evaluations, worst_speed_first, "
                         "candidates, best_networks, screen"
                       : "unknown key in search; expected starts, seed, lo, hi, min_step, max_evaluations");
  }
  if (!refine && (!(s.lo > 0) || !(s.hi > s.lo))) yaml_fail(path, se, "search", "expected 0 < lo < hi (SI units)");
  if (refine && s.refine_screen > 0 && s.refine_screen < s.refine_networks)
    yaml_fail(path, se["screen"], "refine.screen",
              fmt::format("screens {} networks but refines {} (best_networks): expected screen >= best_networks", s.refine_screen,
                          s.refine_networks));
  if (o.initial_step < o.min_step) {
    if (refine) yaml_fail(path, se, "refine", "expected min_step <= initial_step (decades)");
    o.initial_step = o.min_step;
  }
}

optim::Study read_study(const std::string& path, const YAML::Node& root, bool coarse, bool operating_lengths) {
  if (!root.IsMap()) yaml_fail(path, root, "", "expected a study (model, catenary, catenaries, speeds, layouts)");
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    static const char* allowed[] = {"name",      "model",     "catenary", "catenaries", "speeds", "layouts",
                                    "search",    "harmonics", "objective", "networks",  "admittance", "method",
                                    "limits",    "bounds",    "coarse",   "refine",     "pantographs", "set",
                                    "trim",      "working_range", "reference"};
    if (std::find_if(std::begin(allowed), std::end(allowed), [&](const char* a) { return k == a; }) ==
        std::end(allowed))
      yaml_fail(path, it->first, k,
                    "unknown key; expected name, model, catenary, catenaries, speeds, layouts, networks, admittance, search, "
                    "harmonics, objective, method, limits, bounds, coarse, refine, pantographs, set, trim, working_range, reference");
  }
  optim::Study::Objective objective = optim::Study::Objective::J2;
  if (const YAML::Node o = root["objective"]; o.IsDefined()) {  // optional: a pantograph study's objective is J2
    const bool ok = o.IsMap() && o.size() == 1 && o["type"].IsDefined() && o["type"].IsScalar() &&
                    (o["type"].Scalar() == "j2" || o["type"].Scalar() == "sigma_over_mean");
    if (!ok)
      yaml_fail(path, o.IsMap() && o["type"].IsDefined() ? o["type"] : o, "objective",
                "a study with catenary: optimises J2 (max σ) or σ/F_m; expected objective: {type: j2}, "
                "{type: sigma_over_mean} or no objective");
    if (o["type"].Scalar() == "sigma_over_mean") objective = optim::Study::Objective::SigmaOverMean;
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  auto rel = [&](const YAML::Node& n, const char* key) {
    if (!n.IsDefined() || !n.IsScalar())
      yaml_fail(path, n.IsDefined() ? n : root, key, "missing; expected a file path");
    return (dir / n.Scalar()).string();
  };
  optim::Study s;
  s.source = path;
  s.objective = objective;
  s.name = root["name"].IsDefined() ? root["name"].as<std::string>() : path;
  // `set: [NAME.KEY=VALUE]`: overrides of the model (e.g. the aerodynamic uplift aero-fit gives).
  std::vector<std::string> model_sets;
  if (const YAML::Node st = root["set"]; st.IsDefined()) {
    if (!st.IsSequence()) yaml_fail(path, st, "set", "expected a list of model overrides NAME.KEY=VALUE");
    for (const auto& x : st) {
      if (!x.IsScalar()) yaml_fail(path, x, "set", "expected an override NAME.KEY=VALUE");
      model_sets.push_back(x.Scalar());
    }
  }
  const std::string model_path = rel(root["model"], "model");
  try {
    s.pantograph = load_pantograph(model_path, model_sets);
  } catch (const ModelError& e) {
    if (model_sets.empty()) throw;
    yaml_fail(path, root["set"], "set", e.what());
  }
  const std::string cat_path = rel(root["catenary"], "catenary");
  // A file named in an override (irregularity.height_errors=F.csv) is relative to the study file, as
  // every path written in it.
  auto study_override = [&](const std::string& o) {
    const std::string key = "irregularity.height_errors=";
    if (!o.starts_with(key)) return o;
    const std::filesystem::path f(o.substr(key.size())), dir = std::filesystem::path(path).parent_path();
    return f.is_absolute() || dir.empty() ? o : key + (dir / f).string();
  };
  const YAML::Node cats = root["catenaries"];
  if (cats.IsDefined()) {
    // A list of override lists, or {product: [FACTOR, ...]}: every combination of one override list of
    // each factor (a list of override lists), the first factor varying slowest (seeds × tensions).
    struct Set {
      std::string text;
      YAML::Node node;  // where it is written, for its errors
    };
    std::vector<std::vector<Set>> variants;
    if (cats.IsMap()) {
      if (cats.size() != 1 || !cats["product"].IsDefined())
        yaml_fail(path, cats, "catenaries", "expected a list of override lists, or {product: [[...], [...]]}");
      const YAML::Node fs = cats["product"];
      if (!fs.IsSequence() || fs.size() == 0)
        yaml_fail(path, fs, "product", "expected a list of factors, each a list of override lists");
      variants.push_back({});
      for (const auto& f : fs) {
        if (!f.IsSequence() || f.size() == 0)
          yaml_fail(path, f, "product",
                    "expected a factor: a list of override lists such as [[irregularity.seed=1], [irregularity.seed=2]]");
        std::vector<std::vector<Set>> next;
        for (const auto& v : variants)
          for (const auto& c : f) {
            if (!c.IsSequence()) yaml_fail(path, c, "product", "expected an override list such as [irregularity.seed=1]");
            auto sets = v;
            for (const auto& x : c) {
              if (!x.IsScalar()) yaml_fail(path, x, "product", "expected an override NAME.KEY=VALUE");
              sets.push_back({x.Scalar(), x});
            }
            next.push_back(std::move(sets));
          }
        variants = std::move(next);
        if (variants.size() > 1000) yaml_fail(path, fs, "product", "more than 1000 catenary variants");
      }
    } else {
      if (!cats.IsSequence() || cats.size() == 0)
        yaml_fail(path, cats, "catenaries", "expected a list of override lists, or {product: [[...], [...]]}");
      for (const auto& c : cats) {
        std::vector<Set> sets;
        if (!c.IsSequence()) yaml_fail(path, c, "catenaries", "expected a list such as [catenary.kc0=5000]");
        for (const auto& x : c) {
          if (!x.IsScalar()) yaml_fail(path, x, "catenaries", "expected an override NAME.KEY=VALUE");
          sets.push_back({x.Scalar(), x});
        }
        variants.push_back(std::move(sets));
      }
    }
    for (const auto& sets : variants) {
      std::vector<std::string> texts;
      for (const Set& x : sets) texts.push_back(study_override(x.text));
      CatenaryFile f;
      try {
        f = load_catenary(cat_path, texts);
      } catch (const ModelError& e) {  // at the line of the override that fails (alone), else of the list
        for (const Set& x : sets) try {
            (void)load_catenary(cat_path, {study_override(x.text)});
          } catch (const ModelError& one) {
            yaml_fail(path, x.node, "catenaries", one.what());
          }
        yaml_fail(path, cats, "catenaries", e.what());
      }
      s.catenaries.push_back(f.catenary);
      s.contact = f.contact;
      std::string label;
      for (const auto& x : sets) label += (label.empty() ? "" : " ") + x.text;
      s.catenary_labels.push_back(label.empty() ? "default" : label);
    }
    s.reference = load_catenary(cat_path).catenary;  // the line as written: where designs are commissioned
  } else {
    CatenaryFile f = load_catenary(cat_path);
    s.catenaries.push_back(f.catenary), s.contact = f.contact, s.catenary_labels.push_back("default");
    s.reference = f.catenary;
  }
  if (const YAML::Node r = root["reference"]; r.IsDefined()) {  // `catenary:` with these overrides: where designs are commissioned
    if (!r.IsSequence()) yaml_fail(path, r, "reference", "expected a list of catenary overrides, e.g. [catenary.mc1=0]");
    std::vector<std::string> sets;
    for (const auto& x : r) {
      if (!x.IsScalar()) yaml_fail(path, x, "reference", "expected an override NAME.KEY=VALUE");
      sets.push_back(study_override(x.Scalar()));
    }
    try {
      s.reference = load_catenary(cat_path, sets).catenary;
    } catch (const ModelError& e) {
      yaml_fail(path, r, "reference", e.what());
    }
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
  } else if (!ls.IsDefined()) {  // (IsSequence of a missing key threw yaml-cpp's "invalid node", line 0)
    yaml_fail(path, root, "layouts", "missing; expected a list of layouts (S2-1, b|c|k, ...), or all (with networks: {max_elements: N})");
  } else if (!ls.IsSequence() || ls.size() == 0) {
    yaml_fail(path, ls, "layouts", "expected a list of layouts, or all (with networks: {max_elements: N})");
  }
  for (const auto& l : s.all ? YAML::Node(YAML::NodeType::Sequence) : ls) {
    if (!l.IsScalar())
      yaml_fail(path, l, "layouts", "expected a layout name (S2-1, S2-default, ...) or a network expression, not a list or a mapping");
    const std::string name = l.as<std::string>();
    if (std::find(s.layouts.begin(), s.layouts.end(), name) != s.layouts.end())
      yaml_fail(path, l, "layouts", fmt::format("'{}' is given twice; each layout is optimised once", name));
    try {
      network::parse(network::find_layout(name) ? network::find_layout(name)->expression : name);
    } catch (const network::NetworkError& e) {
      yaml_fail(path, l, "layouts", fmt::format("'{}': {}", name, e.what()));
    }
    s.layouts.push_back(name);
  }
  if (const YAML::Node se = root["search"]; se.IsDefined()) read_search(path, se, s, false);
  if (root["harmonics"].IsDefined())
    s.harmonics = static_cast<int>(yaml_integer(path, root["harmonics"], "harmonics", 1, analysis::max_harmonics));
  // The method: the periodic fast path where every catenary has a point model, else the time domain.
  const bool periodic_possible = std::all_of(s.catenaries.begin(), s.catenaries.end(), [](const auto& c) { return c->point_model() != nullptr; });
  s.method = periodic_possible ? optim::Study::Method::Periodic : optim::Study::Method::Time;
  if (const YAML::Node m = root["method"]; m.IsDefined()) {
    const std::string v = m.IsScalar() ? m.Scalar() : "";
    if (v != "periodic" && v != "time") yaml_fail(path, m, "method", "expected periodic or time");
    if (v == "periodic" && !periodic_possible)
      yaml_fail(path, m, "method", "the periodic fast path needs a lumped catenary; this study's has no point model: use time");
    s.method = v == "time" ? optim::Study::Method::Time : optim::Study::Method::Periodic;
  }
  if (const YAML::Node pn = root["pantographs"]; pn.IsDefined()) {
    // Positions along the line at t = 0, m, increasing (the last one leads), as `simulate --positions`.
    if (!pn.IsSequence() || pn.size() < 1 || pn.size() > 8)
      yaml_fail(path, pn, "pantographs", "expected 1 to 8 positions along the line in m, e.g. [0, 200]");
    s.positions.clear();
    for (std::size_t k = 0; k < pn.size(); ++k) {
      const double x = yaml_number(path, pn[k], "pantographs");
      if (!(x >= 0 && x < 1e5) || (k > 0 && !(x > s.positions.back())))
        yaml_fail(path, pn[k], "pantographs", "expected increasing positions in m, from 0, below 1e5");
      s.positions.push_back(x);
    }
    if (s.positions.size() > 1 && s.method != optim::Study::Method::Time)
      yaml_fail(path, pn, "pantographs",
                "several pantographs need the time domain (method: time, on a finite-element or wire-profile line)");
    for (const auto& c : s.catenaries)
      if (static_cast<int>(s.positions.size()) > c->max_pantographs())
        yaml_fail(path, pn, "pantographs", fmt::format("this catenary carries at most {} pantograph(s)", c->max_pantographs()));
  }
  if (const YAML::Node l = root["limits"]; l.IsDefined()) {
    s.limits = read_limits(path, l);
    if (!std::isnan(s.limits.uplift_max) && std::isinf(s.catenaries.front()->line_length()))
      yaml_fail(path, l["support_uplift"], "support_uplift", "a support uplift needs a finite line (a finite-element catenary)");
    if (s.limits.acceptance && std::isinf(s.catenaries.front()->line_length()))
      yaml_fail(path, l["acceptance"], "acceptance",
                "acceptance criteria need a finite line (a finite-element catenary: the 20 Hz statistics, the registrations' uplift)");
  }
  if (const YAML::Node w = root["working_range"]; w.IsDefined()) {  // m around the reference line's height
    if (coarse) yaml_fail(path, w, "working_range", "a coarse study takes its study's working range; give it there");
    if (!w.IsMap()) yaml_fail(path, w, "working_range", "expected {below: m, above: m} (contact-wire heights around the reference line's)");
    for (auto it = w.begin(); it != w.end(); ++it)
      if (const std::string k = it->first.Scalar(); k != "below" && k != "above")
        yaml_fail(path, it->first, "working_range." + k, "unknown key; expected below, above (m)");
    for (const char* k : {"below", "above"})
      if (w[k].IsDefined()) {
        const double v = yaml_number(path, w[k], std::string("working_range.") + k);
        if (!(v >= 0 && v <= 2))
          yaml_fail(path, w[k], std::string("working_range.") + k, fmt::format("{} m; expected 0 … 2 m", w[k].Scalar()));
        (std::string(k) == "below" ? s.working_range.below : s.working_range.above) = v;
      }
    if (s.working_range.below + s.working_range.above <= 0)
      yaml_fail(path, w, "working_range", "below and above are both 0: no range");
  }
  if (const YAML::Node t = root["trim"]; t.IsDefined()) {  // trim: {aerodynamic_at: {speed, unit}} (issue 49)
    if (coarse) yaml_fail(path, t, "trim", "a coarse study is commissioned as its study says; give trim there");
    const char* expect = "expected trim: {aerodynamic_at: {speed: 250, unit: kmh}} (and target: N without an acceptance set)";
    if (!t.IsMap() || !t["aerodynamic_at"].IsDefined() || t.size() > 2 || (t.size() == 2 && !t["target"].IsDefined()))
      yaml_fail(path, t, "trim", expect);
    const YAML::Node a = t["aerodynamic_at"];
    if (!a.IsMap()) yaml_fail(path, a, "trim.aerodynamic_at", expect);
    for (auto it = a.begin(); it != a.end(); ++it)
      if (const std::string k = it->first.Scalar(); k != "speed" && k != "unit")
        yaml_fail(path, it->first, "trim.aerodynamic_at." + k, "unknown key; expected speed, unit");
    if (!a["speed"].IsDefined()) yaml_fail(path, a, "trim.aerodynamic_at.speed", "missing; expected the trim speed");
    const double v = yaml_number(path, a["speed"], "trim.aerodynamic_at.speed");
    const std::string u = a["unit"].IsDefined() ? a["unit"].as<std::string>() : "ms";
    if (u != "kmh" && u != "ms") yaml_fail(path, a["unit"], "trim.aerodynamic_at.unit", "expected kmh or ms");
    const double speed = v / (u == "kmh" ? 3.6 : 1.0);
    if (!(speed > 0 && speed < 200)) yaml_fail(path, a["speed"], "trim.aerodynamic_at.speed", "expected a speed > 0 and below 720 km/h");
    analysis::Trim trim;
    trim.speed = speed;
    if (const YAML::Node g = t["target"]; g.IsDefined()) {  // N, where no acceptance set gives it
      trim.target = yaml_number(path, g, "trim.target");
      if (!(trim.target > 0 && trim.target < 1e4)) yaml_fail(path, g, "trim.target", "expected a mean contact force > 0 and below 1e4 N");
    } else if (!s.limits.acceptance || !s.limits.acceptance->has_target) {
      yaml_fail(path, t, "trim", "the trim's target is the acceptance set's mean-force target: expected limits: {acceptance: "
                                 "PRESET|FILE} with a target curve (en50367-ac has one), or trim.target: N");
    } else {
      trim.target = s.limits.acceptance->target.at(speed * 3.6);
    }
    if (s.limits.acceptance)
      trim.options.filter_cutoff = s.limits.acceptance->filter_cutoff, trim.options.filter_order = s.limits.acceptance->filter_order;
    trim.periodic = s.method == optim::Study::Method::Periodic;
    trim.statistics = trim.periodic ? analysis::Statistics::Raw : analysis::Statistics::Filtered;
    trim.harmonics = s.harmonics;
    s.trim = trim;
    s.static_criteria = s.limits.acceptance;
  }
  if (const YAML::Node b = root["bounds"]; b.IsDefined()) s.bounds = read_bounds(path, b);
  if (!coarse && root["refine"].IsDefined() && !root["coarse"].IsDefined())
    yaml_fail(path, root["refine"], "refine", "refines the optimum of a coarse study: expected coarse: too");
  if (const YAML::Node c = root["coarse"]; c.IsDefined()) {
    if (coarse) yaml_fail(path, c, "coarse", "a coarse study has no coarse study of its own");
    if (!c.IsMap()) yaml_fail(path, c, "coarse", "expected a map of catenary, catenaries, speeds, search, harmonics, method, limits");
    // The coarse study: this one with the keys it gives replaced (model, layouts, networks and bounds
    // are this study's); this study's limits unless it has its own (a support uplift only on a finite line).
    YAML::Node merged(YAML::NodeType::Map);
    for (auto it = root.begin(); it != root.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      // The coarse search (the periodic fast path) runs one pantograph.
      if (k != "coarse" && k != "refine" && k != "method" && k != "admittance" && k != "pantographs" && k != "trim" &&
          k != "working_range")
        merged[k] = it->second;
    }
    for (auto it = c.begin(); it != c.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      static const char* allowed[] = {"catenary", "catenaries", "speeds", "search", "harmonics", "method", "limits", "reference"};
      if (std::find_if(std::begin(allowed), std::end(allowed), [&](const char* a) { return k == a; }) == std::end(allowed))
        yaml_fail(path, it->first, k,
                  "unknown key in coarse; expected catenary, catenaries, speeds, search, harmonics, method, limits, reference");
      merged[k] = it->second;
    }
    if (!c["catenaries"].IsDefined() && c["catenary"].IsDefined()) merged.remove("catenaries");
    if (!c["reference"].IsDefined()) merged.remove("reference");  // the study's overrides are of its own line
    if (!c["limits"].IsDefined() && root["limits"].IsDefined() && root["limits"].IsMap() &&
        (root["limits"]["support_uplift"].IsDefined() || root["limits"]["acceptance"].IsDefined())) {
      YAML::Node l(YAML::NodeType::Map);
      for (auto it = root["limits"].begin(); it != root["limits"].end(); ++it)
        if (it->first.as<std::string>() != "support_uplift" && it->first.as<std::string>() != "acceptance") l[it->first] = it->second;
      merged["limits"] = l;
    }
    auto sub = std::make_shared<optim::Study>(read_study(path, merged, true, operating_lengths));
    sub->name = s.name + " (coarse)";
    if (s.trim) {  // commissioned the same way, on the coarse study's own line, by its own method
      analysis::Trim t = *s.trim;
      t.periodic = sub->method == optim::Study::Method::Periodic;
      if (t.periodic) t.statistics = analysis::Statistics::Raw;
      t.harmonics = sub->harmonics;
      sub->trim = t;
    }
    sub->working_range = s.working_range;
    sub->static_criteria = s.limits.acceptance;  // its static force criterion needs no finite line
    s.refine.starts = 0;
    s.refine.initial_step = 0.25, s.refine.min_step = 0.02, s.refine.max_evaluations = 60;
    // COBYLA by default: on the FE-line study it ended better than the pattern search and BOBYQA
    // (docs/studies.md "Refinement optimisers").
    s.refine_optimiser = numerics::Optimiser::Cobyla;
    if (const YAML::Node r = root["refine"]; r.IsDefined()) read_search(path, r, s, true);
    s.coarse = std::move(sub);
    if (s.all && !s.admittance_degrees.empty())  // each bound would be a search on the fine line
      yaml_fail(path, root["admittance"], "admittance",
                "not with layouts: all and a coarse study (the bound's search would run on the fine line); "
                "run the coarse study alone with admittance:");
  }
  try {
    if (operating_lengths) s.operating_length = optim::operating_lengths(s);
  } catch (const ModelError& e) {
    yaml_fail(path, root["model"], "model", e.what());
  }
  return s;
}
}  // namespace

optim::Study load_study(const std::string& path, bool operating_lengths) {
  try {
    return read_study(path, yaml_load_file(path, "study file"), false, operating_lengths);
  } catch (const YAML::Exception& e) {  // a wrong node type (a map where a layout name belongs, ...)
    throw ModelError(
        fmt::format("{}:{}: {}; expected the study file format of docs/model-format.md", path, e.mark.line + 1, e.msg));
  }
}

}  // namespace inerta::io
