#include "model_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

namespace inerta::io::detail {

void Reader::fail(const YAML::Node& at, const std::string& key, const std::string& what) const {
  std::string where = file_;
  if (at.IsDefined() && at.Mark().line >= 0) where += fmt::format(":{}", at.Mark().line + 1);
  throw ModelError(fmt::format("{}: {}{}", where, key.empty() ? "" : "'" + key + "': ", what));
}

void Reader::fail(const YAML::Node& map, const std::string& what, const InvalidArgument& e) const {
  std::string key = e.parameter();
  if (key.empty()) fail(map, "", fmt::format("{} in {}", e.what(), what));
  // "points[2]": the key and an index into its list.
  int index = -1;
  if (const auto open = key.find('['); open != std::string::npos && key.back() == ']') {
    index = std::stoi(key.substr(open + 1));
    key.resize(open);
  }
  YAML::Node at = map;
  if (map.IsMap()) {
    if (const YAML::Node n = map[key]; n.IsDefined()) {
      at.reset(n);
    } else if (const YAML::Node d = map[key + "_deg"]; d.IsDefined()) {
      at.reset(d);
      key += "_deg";
    }
    if (index >= 0 && at.IsSequence() && static_cast<std::size_t>(index) < at.size()) {
      const YAML::Node item = at[static_cast<std::size_t>(index)];
      at.reset(item);
    }
  }
  fail(at, key, fmt::format("{} in {}", e.problem(), what));
}

void Reader::keys(const YAML::Node& map, const std::string& what, std::initializer_list<const char*> allowed) const {
  keys(map, what, std::vector<std::string>(allowed.begin(), allowed.end()));
}

void Reader::keys(const YAML::Node& map, const std::string& what, const std::vector<std::string>& allowed,
                  const std::string& hint) const {
  if (!map.IsMap()) fail(map, what, "expected a mapping (key: value pairs)");
  std::set<std::string> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (!it->first.IsScalar()) fail(it->first, what, "expected a plain key (a name)");
    std::string k = it->first.Scalar();
    if (!seen.insert(k).second) fail(it->first, k, fmt::format("duplicate key in {}; give each key once", what));
    bool ok = false;
    for (const std::string& a : allowed) ok = ok || k == a;
    if (!ok)
      fail(it->first, k,
           fmt::format("unknown key in {}; expected one of: {}{}", what, fmt::join(allowed, ", "),
                       hint.empty() ? "" : "; " + hint));
  }
}

YAML::Node Reader::need(const YAML::Node& map, const char* key, const std::string& what) const {
  YAML::Node n = map[key];
  if (!n.IsDefined() || n.IsNull()) fail(map, key, fmt::format("missing in {}", what));
  return n;
}

double Reader::number(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a number");
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    fail(n, key, fmt::format("expected a number, got '{}'", n.Scalar()));
  }
  return v;
}
double Reader::number(const YAML::Node& map, const char* key, const std::string& what) const {
  return number(need(map, key, what), key);
}
double Reader::number_or(const YAML::Node& map, const char* key, double fallback) const {
  YAML::Node n = map[key];
  return n.IsDefined() && !n.IsNull() ? number(n, key) : fallback;
}

bool Reader::boolean(const YAML::Node& n, const std::string& key) const {
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    fail(n, key, "expected true or false");
  }
}

std::string Reader::text(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a text value");
  return n.Scalar();
}
std::string Reader::text(const YAML::Node& map, const char* key, const std::string& what) const {
  return text(need(map, key, what), key);
}

// A vector's items: positions, velocities, axes, directions, inertias, gravity, table points. None of
// them may be infinite or NaN (a network value may be .inf, a rigid element: not read here).
double Reader::finite_item(const YAML::Node& n, const std::string& key) const {
  const double v = number(n, key);
  if (!std::isfinite(v)) fail(n, key, fmt::format("expected finite numbers, got '{}'", n.Scalar()));
  return v;
}
mbs::Vec2 Reader::vec2(const YAML::Node& n, const std::string& key) const {
  if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected a list of two numbers [x, y]");
  return {finite_item(n[0], key), finite_item(n[1], key)};
}
mbs::Vec3 Reader::vec3(const YAML::Node& n, const std::string& key) const {
  if (!n.IsSequence() || n.size() != 3) fail(n, key, "expected a list of three numbers [x, y, z] (a 3D model)");
  return {finite_item(n[0], key), finite_item(n[1], key), finite_item(n[2], key)};
}
mbs::Vec3 Reader::unit3(const YAML::Node& n, const std::string& key) const {
  mbs::Vec3 v = vec3(n, key);
  if (!(v.norm() > 0)) fail(n, key, "must be a non-zero vector");
  return v.normalized();
}

void Reader::warning(const YAML::Node& at, const std::string& key, const std::string& what) const {
  if (!notes_) return;
  std::string where = file_;
  if (at.IsDefined() && at.Mark().line >= 0) where += fmt::format(":{}", at.Mark().line + 1);
  notes_->push_back(fmt::format("warning: {}: {}{}", where, key.empty() ? "" : "'" + key + "': ", what));
}

std::string Reader::relative_path(const std::string& path) const {
  const std::filesystem::path p(path), dir = std::filesystem::path(file_).parent_path();
  return p.is_absolute() || dir.empty() ? path : (dir / p).string();
}

double Reader::angle(const YAML::Node& map, const std::string& key, double fallback) const {
  YAML::Node r = map[key], d = map[key + "_deg"];
  if (r.IsDefined() && d.IsDefined())
    fail(d, key + "_deg", fmt::format("give either {} (rad) or {}_deg, not both", key, key));
  if (r.IsDefined()) {
    const double a = finite_item(r, key);
    if (std::abs(a) > 2 * std::numbers::pi)
      warning(r, key,
              fmt::format("{:g} rad is more than 2π in magnitude; {} is in radians (for degrees write {}_deg: {:g})", a,
                          key, key, a));
    return a;
  }
  if (d.IsDefined()) return finite_item(d, key + "_deg") * std::numbers::pi / 180.0;
  return fallback;
}

}  // namespace inerta::io::detail
