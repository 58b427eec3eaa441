#include "network_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/io/yaml_errors.hpp"

namespace inerta::io {

std::optional<network::EnumerationOptions> read_all_layouts(const std::string& path, const YAML::Node& root) {
  const YAML::Node ls = root["layouts"], nw = root["networks"];
  const bool all = ls.IsDefined() && ls.IsScalar() && ls.Scalar() == "all";
  if (!all) {
    if (nw.IsDefined()) yaml_fail(path, nw, "networks", "only with layouts: all (the networks to enumerate)");
    return std::nullopt;
  }
  if (!nw.IsDefined() || !nw.IsMap())
    yaml_fail(path, nw.IsDefined() ? nw : ls, "networks",
              "layouts: all needs networks: {max_elements: N, ...} (and optionally elements: [k, c, b], max_springs, "
              "max_dampers, max_inerters, static_load: any | required | excluded)");
  network::EnumerationOptions o;
  bool have_max = false;
  for (auto it = nw.begin(); it != nw.end(); ++it) {
    const std::string k = it->first.Scalar();
    const YAML::Node v = it->second;
    if (k == "max_elements") {
      o.max_elements = yaml_whole(path, v, k, 1, network::max_enumerated_elements), have_max = true;
    } else if (k == "max_springs" || k == "max_dampers" || k == "max_inerters") {
      (k == "max_springs" ? o.max_springs : k == "max_dampers" ? o.max_dampers : o.max_inerters) =
          yaml_whole(path, v, k, 0, network::max_enumerated_elements);
    } else if (k == "elements") {
      if (!v.IsSequence() || v.size() == 0) yaml_fail(path, v, k, "expected a list of element types, e.g. [k, c, b]");
      o.springs = o.dampers = o.inerters = false;
      for (const auto& t : v) {
        const std::string s = t.IsScalar() ? t.Scalar() : "";
        if (s == "k") o.springs = true;
        else if (s == "c") o.dampers = true;
        else if (s == "b") o.inerters = true;
        else yaml_fail(path, t, k, fmt::format("'{}' is not an element type; expected k (spring), c (damper) or b (inerter)", s));
      }
    } else if (k == "static_load") {
      const std::string s = v.IsScalar() ? v.Scalar() : "";
      if (s == "any") o.static_load = network::StaticLoad::Any;
      else if (s == "required") o.static_load = network::StaticLoad::Required;
      else if (s == "excluded") o.static_load = network::StaticLoad::Excluded;
      else yaml_fail(path, v, k, fmt::format("expected any, required (a spring path between the terminals) or excluded, got '{}'", s));
    } else {
      yaml_fail(path, it->first, k,
                "unknown key in networks; expected max_elements, elements, max_springs, max_dampers, max_inerters, static_load");
    }
  }
  if (!have_max) yaml_fail(path, nw, "networks", "missing max_elements (the largest number of elements)");
  return o;
}

std::vector<int> read_admittance_degrees(const std::string& path, const YAML::Node& root) {
  const YAML::Node a = root["admittance"];
  std::vector<int> out;
  if (!a.IsDefined()) return out;
  if (!a.IsSequence() || a.size() == 0)
    yaml_fail(path, a, "admittance", "expected a list of degrees, e.g. [2, 3] (biquadratic, bicubic)");
  for (const auto& d : a) {
    const int n = yaml_whole(path, d, "admittance", 1, 4);
    if (std::find(out.begin(), out.end(), n) != out.end()) yaml_fail(path, d, "admittance", fmt::format("degree {} is given twice", n));
    out.push_back(n);
  }
  return out;
}

}  // namespace inerta::io
