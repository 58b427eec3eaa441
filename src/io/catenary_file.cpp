#include "inerta/io/catenary_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>

#include "inerta/catenary/lumped.hpp"
#include "inerta/catenary/wire_profile.hpp"
#include "inerta/error.hpp"
#include "inerta/io/csv_table.hpp"
#include "inerta/io/yaml_errors.hpp"

namespace inerta::io {

namespace {

enum class Type { Lumped, WireProfile };

// What a catenary file holds before the catenary object is made (overrides change it).
struct Parsed {
  Type type = Type::Lumped;
  std::string name;
  catenary::LumpedCatenary lumped;
  catenary::WireProfile profile;
  catenary::Contact contact;
};

// Sets one named coefficient of the lumped catenary; returns false if the key is unknown.
bool set_lumped(catenary::LumpedCatenary& c, const std::string& key, double v) {
  auto coeff = [&](const char* prefix, std::array<double, 4>& a) {
    for (int i = 0; i < 4; ++i)
      if (key == fmt::format("{}{}", prefix, i)) return a[static_cast<std::size_t>(i)] = v, true;
    return false;
  };
  if (key == "span") return c.span = v, true;
  return coeff("kc", c.k) || coeff("mc", c.m) || coeff("cc", c.c);
}

// The catenary object; its constructor's InvalidArgument becomes a ModelError naming `where`.
std::shared_ptr<const catenary::Catenary> make(const Parsed& p, const std::string& where) {
  try {
    p.contact.validate();
    if (p.type == Type::Lumped) return std::make_shared<catenary::Lumped>(p.lumped);
    return std::make_shared<catenary::WireProfileCatenary>(p.profile);
  } catch (const InvalidArgument& e) {
    throw ModelError(fmt::format("{}: {}", where, e.what()));
  }
}

void read_lumped(const std::string& path, const YAML::Node& cat, Parsed& c) {
  if (!cat.IsMap()) yaml_fail(path, cat, "catenary", "missing; expected span, kc, mc, cc");
  for (auto it = cat.begin(); it != cat.end(); ++it) {
    std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    if (k == "span") {
      c.lumped.span = yaml_number(path, v, k);
    } else if (k == "kc" || k == "mc" || k == "cc") {
      if (!v.IsSequence() || v.size() != 4) yaml_fail(path, v, k, "expected four coefficients [x0, x1, x2, x3]");
      auto& a = k == "kc" ? c.lumped.k : k == "mc" ? c.lumped.m : c.lumped.c;
      for (std::size_t i = 0; i < 4; ++i) a[i] = yaml_number(path, v[i], k);
    } else {
      yaml_fail(path, it->first, k, "unknown key in catenary; expected span, kc, mc, cc");
    }
  }
}

void read_profile(const std::string& path, const YAML::Node& pr, Parsed& c) {
  if (!pr.IsMap()) yaml_fail(path, pr, "profile", "missing; expected heights (or file), periodic, span");
  bool have = false;
  YAML::Node source;  // the heights (or the file key), for the checks of the whole table
  for (auto it = pr.begin(); it != pr.end(); ++it) {
    std::string k = it->first.as<std::string>();
    const YAML::Node v = it->second;
    if (k == "span") {
      c.profile.span = yaml_number(path, v, k);
    } else if (k == "periodic") {
      if (!v.IsScalar() || (v.Scalar() != "true" && v.Scalar() != "false"))
        yaml_fail(path, v, k, "expected true or false");
      c.profile.periodic = v.Scalar() == "true";
    } else if (k == "heights") {
      if (have) yaml_fail(path, it->first, k, "give either heights or file, not both");
      have = true;
      source = v;
      if (!v.IsSequence() || v.size() < 2) yaml_fail(path, v, k, "expected a list of [x, height] pairs (m), at least 2");
      for (const auto& row : v) {
        if (!row.IsSequence() || row.size() != 2) yaml_fail(path, row, k, "expected [x, height] in m");
        const double x = yaml_number(path, row[0], k);
        if (!c.profile.x.empty() && !(x > c.profile.x.back()))
          yaml_fail(path, row, k, fmt::format("x must increase strictly ({:g} m after {:g} m)", x, c.profile.x.back()));
        c.profile.x.push_back(x);
        c.profile.h.push_back(yaml_number(path, row[1], k));
      }
    } else if (k == "file") {
      if (have) yaml_fail(path, it->first, k, "give either heights or file, not both");
      have = true;
      source = v;
      if (!v.IsScalar()) yaml_fail(path, v, k, "expected the path of a CSV file with columns x and height (m)");
      const std::string csv = (std::filesystem::path(path).parent_path() / v.Scalar()).string();
      const CsvTable t = CsvTable::read(csv);
      t.require_rows(2, "a wire profile");
      c.profile.x = t.column("x");
      c.profile.h = t.column("height");
      for (std::size_t r = 1; r < t.rows(); ++r)
        if (!(c.profile.x[r] > c.profile.x[r - 1]))
          throw ModelError(fmt::format("{}:{}: column 'x': x must increase strictly ({:g} m after {:g} m)", csv,
                                       t.line(r), c.profile.x[r], c.profile.x[r - 1]));
    } else {
      yaml_fail(path, it->first, k, "unknown key in profile; expected heights, file, periodic, span");
    }
  }
  if (!have) yaml_fail(path, pr, "profile", "expected heights: [[x, height], ...] or file: heights.csv");
  const std::string key = pr["heights"].IsDefined() ? "heights" : "file";
  if (c.profile.periodic && c.profile.h.back() != c.profile.h.front())
    yaml_fail(path, source, key,
              fmt::format("a periodic profile must end with its first height ({:g} m), got {:g} m; close it, or set "
                          "periodic: false and a span",
                          c.profile.h.front(), c.profile.h.back()));
  if (!c.profile.periodic && !pr["span"].IsDefined())
    yaml_fail(path, pr, "span", "missing; a profile that does not repeat needs its span (m) for the statistics windows");
}

void read_contact(const std::string& path, const YAML::Node& ct, catenary::Contact& contact) {
  if (!ct.IsMap()) yaml_fail(path, ct, "contact", "expected type, stiffness, damping");
  for (auto it = ct.begin(); it != ct.end(); ++it) {
    std::string k = it->first.as<std::string>();
    if (k == "type") {
      std::string t = it->second.as<std::string>();
      if (t != "bilateral" && t != "penalty") yaml_fail(path, it->second, k, "expected bilateral or penalty");
      contact.kind = t == "bilateral" ? catenary::Contact::Kind::Bilateral : catenary::Contact::Kind::Penalty;
    } else if (k == "stiffness") {
      contact.stiffness = yaml_number(path, it->second, k);
    } else if (k == "damping") {
      contact.damping = yaml_number(path, it->second, k);
    } else {
      yaml_fail(path, it->first, k, "unknown key in contact; expected type, stiffness, damping");
    }
  }
}

void apply_override(Parsed& c, const std::string& o) {
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
    return;
  }
  if (!is_number) throw ModelError(fmt::format("--set '{}': '{}' is not a number", o, value));
  if (c.type == Type::Lumped && section == "catenary" && set_lumped(c.lumped, key, v)) return;
  if (c.type == Type::WireProfile && section == "profile" && key == "span") {
    c.profile.span = v;
    return;
  }
  if (section == "contact" && key == "stiffness") {
    c.contact.stiffness = v;
    return;
  }
  if (section == "contact" && key == "damping") {
    c.contact.damping = v;
    return;
  }
  throw ModelError(fmt::format("--set '{}': unknown key; expected {}contact.type, contact.stiffness, contact.damping", o,
                               c.type == Type::Lumped ? "catenary.kc0..kc3, mc0..mc3, cc0..cc3, span, "
                                                      : "profile.span, "));
}

CatenaryFile read_catenary(const std::string& path, const std::vector<std::string>& overrides) {
  const YAML::Node loaded = yaml_load_file(path, "catenary file");
  const YAML::Node& root = loaded;
  if (!root.IsMap()) yaml_fail(path, root, "", "expected a mapping with 'catenary' (or 'profile') and optional 'contact'");
  Parsed c;
  if (const YAML::Node t = root["type"]; t.IsDefined()) {
    const std::string type = t.IsScalar() ? t.Scalar() : "";
    if (type == "wire_profile")
      c.type = Type::WireProfile;
    else if (type != "lumped")
      yaml_fail(path, t, "type", "expected lumped (the lumped catenary, eq. 7.1) or wire_profile");
  }
  const char* body = c.type == Type::Lumped ? "catenary" : "profile";
  for (auto it = root.begin(); it != root.end(); ++it) {
    std::string k = it->first.as<std::string>();
    if (k != "name" && k != "type" && k != body && k != "contact")
      yaml_fail(path, it->first, k, fmt::format("unknown key; expected name, type, {}, contact", body));
  }
  c.name = root["name"].IsDefined() ? root["name"].as<std::string>() : path;
  if (c.type == Type::Lumped)
    read_lumped(path, root["catenary"], c);
  else
    read_profile(path, root["profile"], c);
  if (const YAML::Node ct = root["contact"]; ct.IsDefined()) read_contact(path, ct, c.contact);
  make(c, path);  // the file's own values are valid
  for (const std::string& o : overrides) apply_override(c, o);
  return {c.name, make(c, overrides.empty() ? path : path + " (after --set)"), c.contact};
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
