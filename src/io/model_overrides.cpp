// Model files: overrides "NAME.KEY=VALUE" applied to the YAML tree before it is read, and
// model_value, which reads the number at such a key (docs/model-format.md#overrides).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <sstream>

#include "inerta/io/model_file.hpp"
#include "lumped_pantograph_file.hpp"
#include "model_loader.hpp"

namespace inerta::io {

namespace detail {

namespace {

// Overrides "NAME.KEY=VALUE": a number of a force element or body in the YAML tree (new keys only
// inside `params`, where a network's element values live). yaml-cpp's Node::operator= rebinds
// shared data, so walking uses reset() and only the leaf is assigned.
struct Slot {
  YAML::Node map;   // the mapping that holds the value
  std::string key;  // its key there
  bool exists = false;
};

Slot locate(YAML::Node& root, const std::string& dotted, const std::function<void(const std::string&)>& fail) {
  std::vector<std::string> path;
  std::stringstream ps(dotted);
  for (std::string part; std::getline(ps, part, '.');) path.push_back(part);
  if (path.size() < 2 || std::any_of(path.begin(), path.end(), [](const std::string& p) { return p.empty(); }))
    fail("expected NAME.KEY with NAME a force element or body, e.g. c2.c or head.mass");
  YAML::Node cur;
  bool found = false;
  std::string names;
  for (const char* section : {"forces", "bodies"}) {
    const YAML::Node list = static_cast<const YAML::Node&>(root)[section];
    if (!list.IsSequence()) continue;
    for (std::size_t i = 0; i < list.size() && !found; ++i) {
      const YAML::Node item = list[i];
      if (!item.IsMap() || !item["name"].IsScalar()) continue;
      names += (names.empty() ? "" : ", ") + item["name"].Scalar();
      if (item["name"].Scalar() == path[0]) cur.reset(item), found = true;
    }
  }
  if (!found) fail(fmt::format("no force element or body named '{}'; names: {}", path[0], names));
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
  if (path.back() == "name" || path.back() == "type") fail(fmt::format("'{}' is not a number", path.back()));
  const YAML::Node leaf = static_cast<const YAML::Node&>(cur)[path.back()];
  Slot s{cur, path.back(), leaf.IsDefined() && leaf.IsScalar()};
  const bool in_params = path.size() >= 3 && path[path.size() - 2] == "params";
  if (!s.exists && !in_params) {
    std::string keys;
    for (auto it = cur.begin(); it != cur.end(); ++it)
      if (it->second.IsScalar() && it->first.Scalar() != "name" && it->first.Scalar() != "type")
        keys += (keys.empty() ? "" : ", ") + it->first.Scalar();
    fail(fmt::format("'{}' has no value '{}'; its values: {}", path[path.size() - 2], path.back(), keys));
  }
  return s;
}

}  // namespace

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
    Slot s = locate(root, o.substr(0, eq), fail);
    s.map[s.key] = std::isinf(value) ? std::string(".inf") : fmt::format("{:.17g}", value);
  }
}

}  // namespace detail

std::optional<double> model_value(const std::string& text, const std::string& source, const std::string& key) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", source, e.mark.line + 1, e.msg));
  }
  if (detail::is_lumped_pantograph(root)) return detail::lumped_value(root, source, key);
  detail::Slot s = detail::locate(root, key, [&](const std::string& what) {
    throw ModelError(fmt::format("{}: parameter '{}': {}", source, key, what));
  });
  if (!s.exists) return std::nullopt;
  const YAML::Node leaf = static_cast<const YAML::Node&>(s.map)[s.key];
  try {
    return leaf.as<double>();
  } catch (const YAML::Exception&) {
    throw ModelError(
        fmt::format("{}:{}: '{}': expected a number, got '{}'", source, leaf.Mark().line + 1, key, leaf.Scalar()));
  }
}

}  // namespace inerta::io
