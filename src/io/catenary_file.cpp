#include "inerta/io/catenary_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/io/yaml_errors.hpp"

namespace inerta::io {

namespace {

// Sets one named coefficient; returns false if the key is unknown.
bool set(CatenaryFile& c, const std::string& key, double v) {
  auto coeff = [&](const char* prefix, std::array<double, 4>& a) {
    for (int i = 0; i < 4; ++i)
      if (key == fmt::format("{}{}", prefix, i)) return a[static_cast<std::size_t>(i)] = v, true;
    return false;
  };
  if (key == "span") return c.catenary.span = v, true;
  return coeff("kc", c.catenary.k) || coeff("mc", c.catenary.m) || coeff("cc", c.catenary.c);
}

void check(const CatenaryFile& c, const std::string& where) {
  if (!(c.catenary.span > 0)) throw ModelError(fmt::format("{}: span must be > 0 (m)", where));
  if (!(c.catenary.m[0] > 0)) throw ModelError(fmt::format("{}: mc0 must be > 0 (kg)", where));
  if (!(c.catenary.k[0] > 0)) throw ModelError(fmt::format("{}: kc0 must be > 0 (N/m)", where));
  if (c.catenary.c[0] < 0) throw ModelError(fmt::format("{}: cc0 must be >= 0 (N·s/m)", where));
  // The coefficients must stay positive over a span (|first harmonics| bounded by the mean).
  auto positive = [](const std::array<double, 4>& a) {
    return a[0] > std::abs(a[1]) + std::abs(a[2]) + std::abs(a[3]);
  };
  if (!positive(c.catenary.k))
    throw ModelError(fmt::format("{}: kc0 must exceed |kc1| + |kc2| + |kc3| (stiffness stays positive)", where));
  if (!positive(c.catenary.m))
    throw ModelError(fmt::format("{}: mc0 must exceed |mc1| + |mc2| + |mc3| (mass stays positive)", where));
  if (c.catenary.c[0] + 1e-300 < std::abs(c.catenary.c[1]) + std::abs(c.catenary.c[2]) + std::abs(c.catenary.c[3]))
    throw ModelError(fmt::format("{}: cc0 must be at least |cc1| + |cc2| + |cc3| (damping stays non-negative)", where));
  if (!(c.contact.stiffness > 0) || c.contact.damping < 0)
    throw ModelError(fmt::format("{}: contact stiffness must be > 0 and damping >= 0", where));
}
}  // namespace

namespace {
CatenaryFile read_catenary(const std::string& path, const std::vector<std::string>& overrides) {
  CatenaryFile c;
  YAML::Node loaded;
  try {
    loaded = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ModelError(fmt::format("{}: cannot open the catenary file", path));
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", path, e.mark.line + 1, e.msg));
  }
  const YAML::Node& root = loaded;
  if (!root.IsMap()) yaml_fail(path, root, "", "expected a mapping with 'catenary' and optional 'contact'");
  for (auto it = root.begin(); it != root.end(); ++it) {
    std::string k = it->first.as<std::string>();
    if (k != "name" && k != "catenary" && k != "contact")
      yaml_fail(path, it->first, k, "unknown key; expected name, catenary, contact");
  }
  const YAML::Node cat = root["catenary"];
  if (!cat.IsMap()) yaml_fail(path, root, "catenary", "missing; expected span, kc, mc, cc");
  for (auto it = cat.begin(); it != cat.end(); ++it) {
    std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    if (k == "span") {
      c.catenary.span = yaml_number(path, v, k);
    } else if (k == "kc" || k == "mc" || k == "cc") {
      if (!v.IsSequence() || v.size() != 4) yaml_fail(path, v, k, "expected four coefficients [x0, x1, x2, x3]");
      auto& a = k == "kc" ? c.catenary.k : k == "mc" ? c.catenary.m : c.catenary.c;
      for (std::size_t i = 0; i < 4; ++i) a[i] = yaml_number(path, v[i], k);
    } else {
      yaml_fail(path, it->first, k, "unknown key in catenary; expected span, kc, mc, cc");
    }
  }
  if (const YAML::Node ct = root["contact"]; ct.IsDefined()) {
    for (auto it = ct.begin(); it != ct.end(); ++it) {
      std::string k = it->first.as<std::string>();
      if (k == "type") {
        std::string t = it->second.as<std::string>();
        if (t != "bilateral" && t != "penalty") yaml_fail(path, it->second, k, "expected bilateral or penalty");
        c.contact.kind = t == "bilateral" ? catenary::Contact::Kind::Bilateral : catenary::Contact::Kind::Penalty;
      } else if (k == "stiffness") {
        c.contact.stiffness = yaml_number(path, it->second, k);
      } else if (k == "damping") {
        c.contact.damping = yaml_number(path, it->second, k);
      } else {
        yaml_fail(path, it->first, k, "unknown key in contact; expected type, stiffness, damping");
      }
    }
  }
  check(c, path);
  for (const std::string& o : overrides) {
    auto dot = o.find('.'), eq = o.find('=');
    if (dot == std::string::npos || eq == std::string::npos || eq < dot)
      throw ModelError(fmt::format("--set '{}': expected section.key=value, e.g. catenary.kc0=5000", o));
    std::string section = o.substr(0, dot), key = o.substr(dot + 1, eq - dot - 1), value = o.substr(eq + 1);
    double v = 0;
    bool is_number = true;
    try {
      std::size_t used = 0;
      v = std::stod(value, &used);
      is_number = used == value.size();
    } catch (const std::exception&) {
      is_number = false;
    }
    if (section == "contact" && key == "type") {
      if (value != "bilateral" && value != "penalty")
        throw ModelError(fmt::format("--set '{}': expected contact.type=bilateral or penalty", o));
      c.contact.kind = value == "bilateral" ? catenary::Contact::Kind::Bilateral : catenary::Contact::Kind::Penalty;
      continue;
    }
    if (!is_number) throw ModelError(fmt::format("--set '{}': '{}' is not a number", o, value));
    if (section == "catenary" && set(c, key, v)) continue;
    if (section == "contact" && key == "stiffness") {
      c.contact.stiffness = v;
      continue;
    }
    if (section == "contact" && key == "damping") {
      c.contact.damping = v;
      continue;
    }
    throw ModelError(
        fmt::format("--set '{}': unknown key; expected catenary.kc0..kc3, mc0..mc3, cc0..cc3, span, "
                    "contact.type, contact.stiffness, contact.damping",
                    o));
  }
  check(c, path + " (after --set)");
  return c;
}
}  // namespace

CatenaryFile load_catenary(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    return read_catenary(path, overrides);
  } catch (const YAML::Exception& e) {  // a wrong node type (a list where a name belongs, ...)
    throw ModelError(fmt::format("{}:{}: {}; expected the catenary file format of docs/model-format.md", path,
                                 e.mark.line + 1, e.msg));
  }
}

}  // namespace inerta::io
