// Lumped n-mass pantograph files (docs/model-format.md#lumped-pantograph-files):
//
//   name: DSA 380 (3 masses)            # optional
//   lumped_pantograph:
//     masses: [7.12, 6.0, 5.8]          # kg, head first
//     stiffness: [9430, 14100, 0.1]     # N/m: k_i from mass i to i+1, the last to the ground
//     damping: [0, 0, 70]               # N·s/m, at the same places
//     static_uplift: 70                 # N, on the lowest mass
//     aerodynamic: {a: 0, b: 0, c: 0}   # optional: a v² + b v + c on the head, N (v in m/s)
//   options: {t_end: 10, sample: 0.001} # optional
#include "lumped_pantograph_file.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <sstream>

#include "inerta/error.hpp"
#include "model_reader.hpp"

namespace inerta::io::detail {

namespace {

constexpr const char* kSection = "lumped_pantograph";
const std::vector<std::string> kKeys{"masses", "stiffness", "damping", "static_uplift", "aerodynamic"};
constexpr const char* kOverrideKeys =
    "lumped_pantograph.static_uplift, lumped_pantograph.masses[i], lumped_pantograph.stiffness[i], "
    "lumped_pantograph.damping[i] (i from 0, the head), lumped_pantograph.aerodynamic.a, .b, .c";

std::vector<double> numbers(const Reader& rd, const YAML::Node& n, const std::string& key, const char* unit) {
  if (!n.IsSequence() || n.size() == 0)
    rd.fail(n, key, fmt::format("expected a list of numbers ({}), head first, e.g. [7.12, 6.0, 5.8]", unit));
  std::vector<double> v;
  for (const auto& item : n) v.push_back(rd.number(item, key));
  return v;
}

// The node an override or a --fit key names, by the key's path; `fail` does not return.
struct Target {
  YAML::Node parent;  // the mapping or list holding the value
  std::string key;    // its key in a mapping
  long index = -1;    // or its index in a list
};

template <class Fail>
Target locate(YAML::Node& root, const std::string& dotted, const Fail& fail) {
  const std::string prefix = std::string(kSection) + ".";
  if (dotted.rfind(prefix, 0) != 0) fail(fmt::format("expected {}.KEY, one of: {}", kSection, kOverrideKeys));
  std::string rest = dotted.substr(prefix.size());
  YAML::Node sec;
  sec.reset(root[kSection]);
  if (!sec.IsMap()) fail(fmt::format("the file has no '{}' mapping", kSection));
  if (rest.rfind("aerodynamic.", 0) == 0) {
    const std::string k = rest.substr(12);
    if (k != "a" && k != "b" && k != "c") fail(fmt::format("unknown key; expected {}", kOverrideKeys));
    if (!sec["aerodynamic"].IsDefined()) sec["aerodynamic"] = YAML::Node(YAML::NodeType::Map);
    YAML::Node aero;
    aero.reset(sec["aerodynamic"]);
    if (!aero.IsMap()) fail("'aerodynamic' is not a mapping in the file");
    return {aero, k, -1};
  }
  if (rest == "static_uplift") return {sec, rest, -1};
  const auto open = rest.find('[');
  if (open != std::string::npos && rest.back() == ']') {
    const std::string list = rest.substr(0, open), idx = rest.substr(open + 1, rest.size() - open - 2);
    if (list == "masses" || list == "stiffness" || list == "damping") {
      long i = -1;
      if (!idx.empty() && idx.find_first_not_of("0123456789") == std::string::npos) i = std::stol(idx);
      YAML::Node l;
      l.reset(sec[list]);
      if (!l.IsSequence()) fail(fmt::format("'{}' is not a list in the file", list));
      if (i < 0 || i >= static_cast<long>(l.size()))
        fail(fmt::format("'{}' has {} value(s): index 0 (the head) to {}; got [{}]", list, l.size(), l.size() - 1, idx));
      return {l, "", i};
    }
  }
  fail(fmt::format("unknown key; expected {}", kOverrideKeys));
  return {};
}

}  // namespace

bool is_lumped_pantograph(const YAML::Node& root) { return root.IsMap() && root[kSection].IsDefined(); }

pantograph::LumpedPantographData read_lumped_pantograph_data(const YAML::Node& root, const std::string& source) {
  const Reader rd(source);
  const YAML::Node lp = rd.need(root, kSection, "a lumped pantograph file");
  rd.keys(lp, kSection, kKeys);
  pantograph::LumpedPantographData d;
  d.mass = numbers(rd, rd.need(lp, "masses", kSection), "masses", "kg");
  d.stiffness = numbers(rd, rd.need(lp, "stiffness", kSection), "stiffness", "N/m");
  d.damping = numbers(rd, rd.need(lp, "damping", kSection), "damping", "N·s/m");
  d.static_uplift = rd.number(lp, "static_uplift", kSection);
  const YAML::Node aero = lp["aerodynamic"];
  if (aero.IsDefined()) {
    rd.keys(aero, "aerodynamic", {"a", "b", "c"});
    d.aero_a = rd.number_or(aero, "a", 0.0);
    d.aero_b = rd.number_or(aero, "b", 0.0);
    d.aero_c = rd.number_or(aero, "c", 0.0);
  }
  try {
    d.validate();
  } catch (const InvalidArgument& e) {
    const std::string& p = e.parameter();
    if (p.rfind("aerodynamic.", 0) == 0)
      rd.fail(aero, "lumped pantograph's aerodynamic uplift", InvalidArgument("", p.substr(12), e.problem()));
    if (const auto open = p.find('['); open != std::string::npos) {  // "masses[1]": at the item, named with its index
      const YAML::Node list = lp[p.substr(0, open)];
      const auto i = std::stoul(p.substr(open + 1));
      if (list.IsSequence() && i < list.size()) rd.fail(list[i], p, fmt::format("{} in lumped pantograph", e.problem()));
    }
    rd.fail(lp, "lumped pantograph", e);
  }
  return d;
}

pantograph::Pantograph read_lumped_pantograph(const YAML::Node& root, const std::string& source) {
  const Reader rd(source);
  rd.keys(root, "a lumped pantograph file", std::vector<std::string>{"name", kSection, "options"},
          "a lumped pantograph file has no bodies, joints or forces (those belong to a model file)");
  pantograph::Pantograph p = pantograph::make_lumped_pantograph(read_lumped_pantograph_data(root, source));
  mbs::Model& m = p.model;
  m.source = source;
  m.name = root["name"].IsDefined() ? rd.text(root["name"], "name") : source;
  if (const YAML::Node o = root["options"]; o.IsDefined()) {
    rd.keys(o, "options", std::vector<std::string>{"t_end", "sample"},
            "a lumped pantograph has no gravity: its static uplift is net of the weight");
    m.options.t_end = rd.number_or(o, "t_end", m.options.t_end);
    m.options.sample = rd.number_or(o, "sample", m.options.sample);
    if (!(m.options.t_end > 0) || !std::isfinite(m.options.t_end)) rd.fail(o["t_end"], "t_end", "must be > 0 (s)");
    if (!(m.options.sample > 0) || !std::isfinite(m.options.sample)) rd.fail(o["sample"], "sample", "must be > 0 (s)");
  }
  return p;
}

void apply_lumped_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& source) {
  for (const std::string& o : overrides) {
    auto fail = [&](const std::string& what) {
      throw ModelError(fmt::format("{}: override '{}': {}", source, o, what));
    };
    const std::size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) fail("expected KEY=VALUE, e.g. lumped_pantograph.static_uplift=90");
    const std::string v = o.substr(eq + 1);
    std::istringstream vs(v);
    double value = 0;
    if (!(vs >> value) || !(vs >> std::ws).eof() || !std::isfinite(value)) fail("'" + v + "' is not a number");
    Target t = locate(root, o.substr(0, eq), fail);
    const std::string text = fmt::format("{:.17g}", value);
    if (t.index >= 0)
      t.parent[static_cast<std::size_t>(t.index)] = text;
    else
      t.parent[t.key] = text;
  }
}

std::optional<double> lumped_value(const YAML::Node& root, const std::string& source, const std::string& key) {
  YAML::Node tree = YAML::Clone(root);
  const Target t = locate(tree, key, [&](const std::string& what) {
    throw ModelError(fmt::format("{}: parameter '{}': {}", source, key, what));
  });
  const YAML::Node leaf = t.index >= 0 ? static_cast<const YAML::Node&>(t.parent)[static_cast<std::size_t>(t.index)]
                                       : static_cast<const YAML::Node&>(t.parent)[t.key];
  if (!leaf.IsDefined()) return std::nullopt;
  try {
    return leaf.as<double>();
  } catch (const YAML::Exception&) {
    throw ModelError(fmt::format("{}:{}: '{}': expected a number", source, leaf.Mark().line + 1, key));
  }
}

}  // namespace inerta::io::detail
