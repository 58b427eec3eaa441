// Model files: overrides "NAME.KEY=VALUE" applied to the YAML tree before it is read, and
// model_value, which reads the number at such a key (docs/model-format.md#overrides).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <sstream>

#include "inerta/io/files.hpp"
#include "inerta/io/model_file.hpp"
#include "lumped_pantograph_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "model_loader.hpp"

namespace inerta::io {

namespace detail {

namespace {

// Overrides "NAME.KEY=VALUE": a number of a force element, body or joint in the YAML tree (new keys
// only inside `params`, where a network's element values live). A joint's KEY may name a key of its
// `motion` mapping directly (drive.speed = drive.motion.speed); a final KEY[i] is the i-th number
// of a list (drive.amplitudes[1]). yaml-cpp's Node::operator= rebinds shared data, so walking uses
// reset() and only the leaf is assigned.
struct Slot {
  YAML::Node map;   // the mapping (or, with index >= 0, the list) that holds the value
  std::string key;  // its key there
  int index = -1;
  bool exists = false;
  void assign(const std::string& v) {
    if (index >= 0)
      map[static_cast<std::size_t>(index)] = v;
    else
      map[key] = v;
  }
};

const char* const kSections[] = {"forces", "bodies", "joints"};

Slot locate_slot(YAML::Node& root, const std::string& dotted, const std::function<void(const std::string&)>& fail) {
  std::vector<std::string> path;
  std::stringstream ps(dotted);
  for (std::string part; std::getline(ps, part, '.');) path.push_back(part);
  if (path.size() < 2 || std::any_of(path.begin(), path.end(), [](const std::string& p) { return p.empty(); }))
    fail("expected NAME.KEY with NAME a force element, body or joint, e.g. c2.c, head.mass or drive.amplitude");
  // pantograph.aerodynamic.{a,b,c}: the pantograph section's aerodynamic uplift (created if absent).
  if (path[0] == "pantograph") {
    const YAML::Node p = static_cast<const YAML::Node&>(root)["pantograph"];
    if (!p.IsDefined() || !p.IsMap()) fail("the model has no 'pantograph:' section");
    if (path.size() != 3 || path[1] != "aerodynamic" || (path[2] != "a" && path[2] != "b" && path[2] != "c"))
      fail("expected pantograph.aerodynamic.a, .b or .c (the uplift a v² + b v + c, N, v in m/s)");
    YAML::Node sec;
    sec.reset(p);
    if (!p["aerodynamic"].IsDefined()) sec["aerodynamic"] = YAML::Node(YAML::NodeType::Map);
    YAML::Node aero;
    aero.reset(static_cast<const YAML::Node&>(sec)["aerodynamic"]);
    if (!aero.IsMap()) fail("'aerodynamic' is not a mapping in the file");
    return Slot{aero, path[2], -1, true};
  }
  YAML::Node cur;
  bool found = false, joint = false;
  std::string names;
  std::vector<std::string> kinds;  // every kind the name is, to refuse an ambiguous one (issue 38)
  for (const char* section : kSections) {
    const YAML::Node list = static_cast<const YAML::Node&>(root)[section];
    if (!list.IsDefined() || !list.IsSequence()) continue;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node item = list[i];
      if (!item.IsMap() || !item["name"].IsScalar()) continue;
      if (!found) names += (names.empty() ? "" : ", ") + item["name"].Scalar();
      if (item["name"].Scalar() != path[0]) continue;
      kinds.push_back(std::string(section) == "forces" ? "a force element" : std::string(section) == "bodies" ? "a body" : "a joint");
      if (!found) cur.reset(item), found = true, joint = std::string(section) == "joints";
    }
  }
  if (kinds.size() > 1)
    fail(fmt::format("'{}' names {} and {}: the override cannot tell which; give them different names", path[0],
                     kinds[0], kinds[1]));
  if (!found) fail(fmt::format("no force element, body or joint named '{}'; names: {}", path[0], names));
  // drive.KEY → drive.motion.KEY when the joint has no KEY of its own.
  std::string leaf_key = path.back();
  int index = -1;
  if (const auto open = leaf_key.find('['); open != std::string::npos && leaf_key.back() == ']') {
    const std::string digits = leaf_key.substr(open + 1, leaf_key.size() - open - 2);
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), digit))
      fail(fmt::format("'{}': expected KEY[i] with i a list position (0-based)", leaf_key));
    index = std::stoi(digits);
    leaf_key.resize(open);
  }
  if (joint && path.size() == 2 && !static_cast<const YAML::Node&>(cur)[leaf_key].IsDefined()) {
    const YAML::Node motion = static_cast<const YAML::Node&>(cur)["motion"];
    if (motion.IsDefined() && motion.IsMap()) path.insert(path.begin() + 1, "motion");
  }
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const YAML::Node next = static_cast<const YAML::Node&>(cur)[path[i]];
    if (next.IsDefined() && next.IsMap()) {
      cur.reset(next);
    } else if (path[i] == "params" && !next.IsDefined()) {
      cur[path[i]] = YAML::Node(YAML::NodeType::Map);  // a network strut without params yet
      cur.reset(static_cast<const YAML::Node&>(cur)[path[i]]);
    } else {
      fail(fmt::format("'{}' has no mapping '{}'", path[i - 1], path[i]));
    }
  }
  if (leaf_key == "name" || leaf_key == "type") fail(fmt::format("'{}' is not a number", leaf_key));
  const YAML::Node leaf = static_cast<const YAML::Node&>(cur)[leaf_key];
  if (index >= 0) {
    const bool list = leaf.IsDefined() && leaf.IsSequence();
    if (!list || static_cast<std::size_t>(index) >= leaf.size() || !leaf[static_cast<std::size_t>(index)].IsScalar())
      fail(fmt::format("'{}' is not a list of numbers with an item {}{}", leaf_key, index,
                       list ? fmt::format(" (it has {})", leaf.size()) : ""));
    Slot s{leaf, leaf_key, index, true};
    s.map.reset(leaf);
    return s;
  }
  Slot s{cur, leaf_key, -1, leaf.IsDefined() && leaf.IsScalar()};
  const bool in_params = path.size() >= 3 && path[path.size() - 2] == "params";
  if (!s.exists && !in_params) {
    std::string keys;
    for (auto it = cur.begin(); it != cur.end(); ++it)
      if (it->second.IsScalar() && it->first.Scalar() != "name" && it->first.Scalar() != "type")
        keys += (keys.empty() ? "" : ", ") + it->first.Scalar();
    fail(fmt::format("'{}' has no value '{}'; its values: {}", path[path.size() - 2], leaf_key, keys));
  }
  return s;
}

}  // namespace

bool names_model_item(const YAML::Node& root, const std::string& name, const std::string& key) {
  if (is_lumped_pantograph(root)) return name == "lumped_pantograph";
  if (name == "pantograph") return root["pantograph"].IsDefined();
  for (const char* section : kSections) {
    const YAML::Node list = root[section];
    if (!list.IsDefined() || !list.IsSequence()) continue;
    for (const auto& item : list) {
      if (!item.IsMap() || !item["name"].IsScalar() || item["name"].Scalar() != name) continue;
      if (std::string(section) != "joints") return true;
      // A joint's numbers are its motion's: a name shared with a catenary section (a pantograph's
      // rig joint `contact` and contact.type=penalty) stays the catenary's otherwise.
      const std::string first = key.substr(0, std::min(key.find('.'), key.find('[')));
      const YAML::Node motion = item["motion"];
      return first == "motion" || (motion.IsDefined() && motion.IsMap() && motion[first].IsDefined());
    }
  }
  return false;
}

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& source) {
  for (const std::string& o : overrides) {
    auto fail = [&](const std::string& what) {
      throw ModelError(fmt::format("{}: override '{}': {}", source, o, what));
    };
    const std::size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) fail("expected NAME.KEY=VALUE, e.g. c2.c=70");
    std::string v = o.substr(eq + 1), lower = v;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    double value = 0;
    if (lower == "inf" || lower == ".inf") {
      value = INFINITY;
    } else {
      std::istringstream vs(v);
      if (!(vs >> value) || !(vs >> std::ws).eof() || !std::isfinite(value)) fail("'" + v + "' is not a number");
    }
    Slot s = locate_slot(root, o.substr(0, eq), fail);
    s.assign(std::isinf(value) ? std::string(".inf") : fmt::format("{:.17g}", value));
  }
}

}  // namespace detail

std::optional<double> model_value(const std::string& text, const std::string& source, const std::string& key) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    yaml_syntax_error(source, e);
  }
  if (detail::is_lumped_pantograph(root)) return detail::lumped_value(root, source, key);
  detail::Slot s = detail::locate_slot(root, key, [&](const std::string& what) {
    throw ModelError(fmt::format("{}: parameter '{}': {}", source, key, what));
  });
  if (!s.exists) return std::nullopt;
  const YAML::Node leaf =
      s.index >= 0 ? static_cast<const YAML::Node&>(s.map)[static_cast<std::size_t>(s.index)]
                   : static_cast<const YAML::Node&>(s.map)[s.key];
  try {
    return leaf.as<double>();
  } catch (const YAML::Exception&) {
    throw ModelError(
        fmt::format("{}:{}: '{}': expected a number, got '{}'", source, leaf.Mark().line + 1, key, leaf.Scalar()));
  }
}

std::pair<std::vector<std::string>, std::vector<std::string>> split_overrides(const std::string& path,
                                                                              const std::vector<std::string>& overrides) {
  std::pair<std::vector<std::string>, std::vector<std::string>> out;
  if (overrides.empty()) return out;
  YAML::Node root;
  const std::string text = read_input_text(path, "model file");
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    yaml_syntax_error(path, e);
  }
  for (const std::string& o : overrides) {
    const std::size_t dot = std::min(o.find('.'), o.find('=')), eq = o.find('=');
    const std::string name = o.substr(0, dot);
    const std::string key = dot < eq && eq != std::string::npos ? o.substr(dot + 1, eq - dot - 1) : std::string();
    (detail::names_model_item(root, name, key) ? out.first : out.second).push_back(o);
  }
  return out;
}

}  // namespace inerta::io
