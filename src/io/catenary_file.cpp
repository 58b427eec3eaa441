#include "inerta/io/catenary_file.hpp"

#include <fmt/format.h>

#include <charconv>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "inerta/catenary/lumped.hpp"
#include "inerta/catenary/wire_profile.hpp"
#include "inerta/error.hpp"
#include "inerta/io/csv_table.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/numerics/phase_times.hpp"
#include "model_reader.hpp"

namespace inerta::io {

namespace {

enum class Type { Lumped, WireProfile, FiniteElement };

// What a catenary file holds before the catenary object is made (overrides change it).
struct Parsed {
  Type type = Type::Lumped;
  std::string name;
  catenary::LumpedCatenary lumped;
  catenary::WireProfile profile;
  catenary::FeCatenaryData fe;
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
// The finite-element catenary is made only if `fe` (its data are checked by read_fe).
std::shared_ptr<const catenary::Catenary> make(const Parsed& p, const std::string& where, bool fe = false) {
  try {
    p.contact.validate();
    if (p.type == Type::Lumped) return std::make_shared<catenary::Lumped>(p.lumped);
    if (p.type == Type::WireProfile) return std::make_shared<catenary::WireProfileCatenary>(p.profile);
    return fe ? std::make_shared<catenary::FeCatenary>(p.fe) : nullptr;
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
  for (const char* k : {"span", "kc", "mc", "cc"})  // no silent defaults (issue 15)
    if (!cat[k].IsDefined())
      yaml_fail(path, cat, k,
                std::string("missing in catenary; the lumped catenary needs span (m), kc (N/m), mc (kg) and cc (N·s/m)") +
                    ", each as four coefficients [x0, x1, x2, x3] (span: one number)");
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

// Finite-element catenary (type: finite_element) -----------------------------------------------
// One table drives the reading of every number, the overrides and the messages: section, key,
// unit, required (in its section), whole number, and where the value goes.
struct FeField {
  const char* section;
  const char* key;
  const char* unit;
  bool required;
  bool integer;
  void (*set)(catenary::FeCatenaryData&, double);
};

#define INERTA_FE_FIELD(sec, key, unit, req, integer, member) \
  FeField {                                                     \
    sec, key, unit, req, integer,                               \
        [](catenary::FeCatenaryData& d, double v) { d.member = static_cast<decltype(d.member)>(v); } \
  }
const std::vector<FeField>& fe_fields() {
  static const std::vector<FeField> f{
      INERTA_FE_FIELD("line", "span", "m", true, false, span),
      INERTA_FE_FIELD("line", "spans", "a whole number", true, true, spans),
      INERTA_FE_FIELD("line", "encumbrance", "m", true, false, encumbrance),
      INERTA_FE_FIELD("line", "gravity", "m/s²", false, false, gravity),
      INERTA_FE_FIELD("messenger", "tension", "N", true, false, messenger.tension),
      INERTA_FE_FIELD("messenger", "mass_per_length", "kg/m", true, false, messenger.mass_per_length),
      INERTA_FE_FIELD("messenger", "EI", "N·m²", false, false, messenger.EI),
      INERTA_FE_FIELD("contact_wire", "tension", "N", true, false, contact_wire.tension),
      INERTA_FE_FIELD("contact_wire", "mass_per_length", "kg/m", true, false, contact_wire.mass_per_length),
      INERTA_FE_FIELD("contact_wire", "EI", "N·m²", false, false, contact_wire.EI),
      INERTA_FE_FIELD("droppers", "EA", "N", true, false, dropper_EA),
      INERTA_FE_FIELD("droppers", "mass_per_length", "kg/m", false, false, dropper_mass_per_length),
      INERTA_FE_FIELD("droppers", "clamp_mass_messenger", "kg", false, false, clamp_mass_messenger),
      INERTA_FE_FIELD("droppers", "clamp_mass_contact", "kg", false, false, clamp_mass_contact),
      INERTA_FE_FIELD("supports", "stiffness", "N/m", true, false, support_stiffness),
      INERTA_FE_FIELD("supports", "mass", "kg", false, false, support_mass),
      INERTA_FE_FIELD("registration", "stiffness", "N/m", true, false, registration_stiffness),
      INERTA_FE_FIELD("registration", "mass", "kg", false, false, registration_mass),
      INERTA_FE_FIELD("registration", "uplift_limit", "m", false, false, registration_uplift_limit),
      INERTA_FE_FIELD("mesh", "element_length", "m", false, false, element_length),
      INERTA_FE_FIELD("damping", "rayleigh_mass", "1/s", false, false, rayleigh_mass),
      INERTA_FE_FIELD("damping", "rayleigh_stiffness", "s", false, false, rayleigh_stiffness),
      INERTA_FE_FIELD("integration", "time_step", "s", false, false, time_step),
      INERTA_FE_FIELD("integration", "alpha", "HHT-α, −1/3 … 0", false, false, hht_alpha),
      INERTA_FE_FIELD("solver", "cutoff", "Hz", false, false, modal_cutoff),
      INERTA_FE_FIELD("solver", "window_behind", "spans, −1: the whole line", false, true, window_behind),
      INERTA_FE_FIELD("solver", "window_ahead", "spans, −1: the whole line", false, true, window_ahead),
  };
  return f;
}
#undef INERTA_FE_FIELD

// The lists of the droppers section: x, presag, nominal_length (m).
std::vector<double>* fe_list(catenary::FeCatenaryData& d, const std::string& key) {
  if (key == "x") return &d.dropper_x;
  if (key == "presag") return &d.presag;
  if (key == "nominal_length") return &d.nominal_dropper_length;
  return nullptr;
}

const std::vector<std::string> kFeSections{"line",         "messenger", "contact_wire", "droppers",
                                           "supports",     "registration", "mesh",      "damping",
                                           "integration",  "section",   "contact",      "solver",
                                           "stitch",       "irregularity"};
const std::set<std::string> kFeRequired{"line", "messenger", "contact_wire", "droppers", "supports", "registration"};

std::vector<std::string> fe_keys(const std::string& section) {
  std::vector<std::string> k;
  if (section == "droppers") k = {"x", "presag", "nominal_length"};
  if (section == "section") k = {"spans"};
  if (section == "solver") k = {"type"};
  if (section == "registration") k = {"uplift_limited"};
  if (section == "stitch") k = {"enabled", "length", "tension", "mass_per_length", "EI", "clamp_mass", "droppers"};
  if (section == "irregularity")
    k = {"dropper_length_std", "seed", "dropper_length_errors", "height_errors", "point_masses", "exact_dropper_dynamics"};
  for (const FeField& f : fe_fields())
    if (section == f.section) k.emplace_back(f.key);
  return k;
}

// What the file's sections hold, for the message of a missing key.
std::string fe_section_help(const std::string& section) {
  std::string s;
  for (const std::string& k : fe_keys(section)) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// A complaint of FeCatenaryData::validate() ("finite-element catenary: <section>: <parameter>: …")
// at the line of the key it names; `root` is the file's top level.
[[noreturn]] void fe_fail(const detail::Reader& rd, const YAML::Node& root, const InvalidArgument& e) {
  const std::string prefix = "finite-element catenary: ", what = e.what();
  std::string section;
  if (what.rfind(prefix, 0) == 0) section = what.substr(prefix.size(), what.find(": ", prefix.size()) - prefix.size());
  std::string key = e.parameter();
  if (section == "tension_sections" && key.size() > 1 && key[0] == '[') {  // [k].<section>.<key>
    // At the section's own value where it gives one, else at the file's value every section takes.
    const std::size_t k = std::stoul(key.substr(1)), close = key.find(']');
    const std::string rest = close + 2 <= key.size() ? key.substr(close + 2) : std::string();
    const std::string inner = rest.substr(0, rest.find('.')), leaf = rest.find('.') == std::string::npos ? "" : rest.substr(rest.find('.') + 1);
    YAML::Node at = root["tension_sections"];
    if (at.IsSequence() && k < at.size()) {
      const YAML::Node sec = at[k];
      at.reset(sec);
      if (const YAML::Node own = sec.IsMap() ? sec[inner] : YAML::Node(); !inner.empty() && own.IsDefined()) {
        at.reset(own);
        if (const YAML::Node n = own.IsMap() && !leaf.empty() ? own[leaf] : YAML::Node(); n.IsDefined()) at.reset(n);
      } else if (const YAML::Node top = inner.empty() ? YAML::Node() : root[inner]; top.IsDefined() && top.IsMap()) {
        at.reset(top);
        if (const YAML::Node n = leaf.empty() ? YAML::Node() : top[leaf]; n.IsDefined()) at.reset(n);
      }
    }
    rd.fail(at, "tension_sections" + key, e.problem());
  }
  if (section == "damping" && (key == "mass" || key == "stiffness")) key = "rayleigh_" + key;
  long index = -1;
  std::string shown = key;
  if (const auto open = key.find('['); open != std::string::npos && key.back() == ']') {
    index = std::stol(key.substr(open + 1));
    key.resize(open);
  }
  YAML::Node at = root;
  if (const YAML::Node s = root[section]; !section.empty() && s.IsDefined()) {
    at.reset(s);
    std::string leaf = key;
    YAML::Node parent = s;
    if (const auto dot = key.find('.'); dot != std::string::npos && s.IsMap()) {  // stitch: droppers.x
      if (const YAML::Node sub = s[key.substr(0, dot)]; sub.IsDefined() && sub.IsMap()) {
        parent.reset(sub);
        at.reset(sub);
        leaf = key.substr(dot + 1);
      }
    }
    if (const YAML::Node k = parent.IsMap() ? parent[leaf] : YAML::Node(); k.IsDefined()) {
      at.reset(k);
      if (index >= 0 && k.IsSequence() && static_cast<std::size_t>(index) < k.size()) {
        const YAML::Node item = k[static_cast<std::size_t>(index)];
        at.reset(item);
      }
    }
  }
  rd.fail(at, shown.empty() ? section : shown,
          fmt::format("{}{}", e.problem(), section.empty() ? "" : " in " + section));
}

std::vector<double> fe_numbers(const detail::Reader& rd, const YAML::Node& n, const std::string& key) {
  if (!n.IsSequence()) rd.fail(n, key, "expected a list of numbers (m), one per dropper of a span");
  std::vector<double> v;
  for (const auto& item : n) v.push_back(rd.number(item, key));
  return v;
}

int fe_whole(const detail::Reader& rd, const YAML::Node& n, const std::string& key, double v) {
  if (!(std::abs(v) < 1e9) || v != std::floor(v)) rd.fail(n, key, fmt::format("expected a whole number, got {}", v));
  return static_cast<int>(v);
}

// stitch: {enabled, length, tension, mass_per_length, EI, clamp_mass, droppers: {x, presag, EA,
// mass_per_length, clamp_mass_stitch, clamp_mass_contact}} (docs/model-format.md). With `s` already a
// stitch (a tension section over the line's), every key is optional and replaces the line's value.
void read_fe_stitch(const detail::Reader& rd, const YAML::Node& st, catenary::FeStitch& s) {
  if (!st.IsMap()) rd.fail(st, "stitch", "expected a section: {length, tension, mass_per_length, EI, clamp_mass, droppers}");
  const bool over = s.present;
  s.present = true;
  auto value = [&](const YAML::Node& map, const char* key, const char* where, double& v) {
    if (over) v = rd.number_or(map, key, v);
    else v = rd.number(rd.need(map, key, where), key);
  };
  if (const YAML::Node n = st["enabled"]; n.IsDefined()) s.enabled = rd.boolean(n, "enabled");
  value(st, "length", "stitch", s.length);
  value(st, "tension", "stitch", s.wire.tension);
  value(st, "mass_per_length", "stitch", s.wire.mass_per_length);
  s.wire.EI = rd.number_or(st, "EI", over ? s.wire.EI : 0.0);
  s.clamp_mass = rd.number_or(st, "clamp_mass", over ? s.clamp_mass : 0.0);
  const YAML::Node dr = over ? st["droppers"] : rd.need(st, "droppers", "stitch");
  if (over && (!dr.IsDefined() || dr.IsNull())) return;
  rd.keys(dr, "stitch.droppers", {"x", "presag", "EA", "mass_per_length", "clamp_mass_stitch", "clamp_mass_contact"});
  if (const YAML::Node x = over ? dr["x"] : rd.need(dr, "x", "stitch.droppers"); x.IsDefined()) {
    if (!x.IsSequence()) rd.fail(x, "x", "expected a list of signed positions from the mast (m), e.g. [-7, -2, 2, 7]");
    s.dropper_x.clear();
    for (const auto& item : x) s.dropper_x.push_back(rd.number(item, "x"));
    if (over && !dr["presag"].IsDefined()) s.dropper_presag.clear();  // new positions: the line's pre-sags no longer fit
  }
  if (const YAML::Node p = dr["presag"]; p.IsDefined()) {
    if (!p.IsSequence()) rd.fail(p, "presag", "expected a list of contact-wire pre-sags (m, positive down), one per stitch dropper");
    s.dropper_presag.clear();
    for (const auto& item : p) s.dropper_presag.push_back(rd.number(item, "presag"));
  }
  value(dr, "EA", "stitch.droppers", s.dropper_EA);
  s.dropper_mass_per_length = rd.number_or(dr, "mass_per_length", over ? s.dropper_mass_per_length : 0.0);
  s.clamp_mass_stitch = rd.number_or(dr, "clamp_mass_stitch", over ? s.clamp_mass_stitch : 0.0);
  s.clamp_mass_contact = rd.number_or(dr, "clamp_mass_contact", over ? s.clamp_mass_contact : 0.0);
}

// The height-error profile: a CSV with columns x and dz (m), relative to the catenary file.
void read_height_errors(const std::string& csv, catenary::FeIrregularity& irr) {
  const CsvTable t = CsvTable::read(csv);
  if (t.column("x").size() < 2)  // only a header (or one point) would run as the perfect line
    throw ModelError(fmt::format("{}: {} data row(s); expected the height errors x, dz (m) at 2 or more points covering the line",
                                 csv, t.column("x").size()));
  irr.height_errors_file = csv;
  irr.height_error_x = t.column("x");
  irr.height_error_dz = t.column("dz");
}

// irregularity: {dropper_length_std, seed, dropper_length_errors, height_errors, point_masses,
// exact_dropper_dynamics}.
void read_fe_irregularity(const detail::Reader& rd, const YAML::Node& ir, catenary::FeCatenaryData& d) {
  catenary::FeIrregularity& irr = d.irregularity;
  if (!ir.IsMap()) rd.fail(ir, "irregularity", "expected a section: {dropper_length_std, seed, dropper_length_errors, height_errors, point_masses, exact_dropper_dynamics}");
  irr.dropper_length_std = rd.number_or(ir, "dropper_length_std", 0.0);
  if (const YAML::Node n = ir["seed"]; n.IsDefined()) {
    const double v = rd.number(n, "seed");
    if (!(v >= 0 && v < 9007199254740992.0) || v != std::floor(v)) rd.fail(n, "seed", fmt::format("expected a whole number from 0 to 2^53 − 1 = 9007199254740991 (exact as a number), got {:.17g}", v));
    irr.seed = static_cast<std::uint64_t>(v);
  }
  if (const YAML::Node n = ir["dropper_length_errors"]; n.IsDefined()) {
    if (!n.IsSequence()) rd.fail(n, "dropper_length_errors", "expected a list of length errors (m), one per dropper of the line in line order");
    for (const auto& item : n) irr.dropper_length_errors.push_back(rd.number(item, "dropper_length_errors"));
  }
  if (const YAML::Node n = ir["height_errors"]; n.IsDefined()) {
    if (!n.IsScalar()) rd.fail(n, "height_errors", "expected the path of a CSV file with columns x and dz (m)");
    try {
      read_height_errors(rd.relative_path(n.Scalar()), irr);
    } catch (const ModelError& e) {
      rd.fail(n, "height_errors", e.what());
    }
  }
  if (const YAML::Node n = ir["exact_dropper_dynamics"]; n.IsDefined()) irr.exact_dropper_dynamics = rd.boolean(n, "exact_dropper_dynamics");
  if (const YAML::Node n = ir["point_masses"]; n.IsDefined()) {
    if (!n.IsSequence()) rd.fail(n, "point_masses", "expected a list of {x, mass}: x along the line (m), mass (kg)");
    for (const auto& item : n) {
      rd.keys(item, "point_masses", {"x", "mass"});
      irr.point_masses.push_back({rd.number(rd.need(item, "x", "point_masses"), "x"),
                                  rd.number(rd.need(item, "mass", "point_masses"), "mass")});
    }
  }
}

void read_fe_sections(const detail::Reader& rd, const YAML::Node& root, catenary::FeCatenaryData& d);

void read_fe(const std::string& path, const YAML::Node& root, Parsed& c) {
  const detail::Reader rd(path);
  std::vector<std::string> top{"name", "type"};
  top.insert(top.end(), kFeSections.begin(), kFeSections.end());
  top.insert(top.end(), {"tension_sections", "overlap"});
  rd.keys(root, "a finite-element catenary file", top);
  const bool sectioned = root["tension_sections"].IsDefined();
  if (root["overlap"].IsDefined() && !sectioned)
    rd.fail(root["overlap"], "overlap", "an overlap joins tension sections; give tension_sections too (docs/model-format.md)");
  catenary::FeCatenaryData& d = c.fe;
  // Masses the file does not give are absent (not the benchmark's values, FeCatenaryData's defaults).
  d.dropper_mass_per_length = d.clamp_mass_messenger = d.clamp_mass_contact = 0;
  d.support_mass = d.registration_mass = 0;
  d.messenger.EI = d.contact_wire.EI = 0;
  for (const std::string& s : kFeSections) {
    const YAML::Node sec = root[s];
    if (!sec.IsDefined() || sec.IsNull()) {
      if (kFeRequired.count(s))
        rd.fail(root, s, fmt::format("missing in a finite-element catenary file; expected {}: {{{}}}", s,
                                     fe_section_help(s)));
      continue;
    }
    if (s == "contact") continue;  // read_contact
    if (s == "solver" && sec.IsScalar()) continue;  // `solver: modal`, the type alone
    rd.keys(sec, s, fe_keys(s));
  }
  for (const FeField& f : fe_fields()) {
    const YAML::Node sec = root[f.section];
    if (!sec.IsDefined() || sec.IsNull() || !sec.IsMap()) continue;
    const YAML::Node n = sec[f.key];
    const bool section_spans = std::string(f.section) == "line" && std::string(f.key) == "spans";
    if (sectioned && section_spans) {
      if (n.IsDefined())
        rd.fail(n, "spans", "a line of tension_sections takes its spans from its sections (tension_sections[k].spans); remove line.spans");
      continue;
    }
    if (!n.IsDefined() || n.IsNull()) {
      if (f.required) rd.fail(sec, f.key, fmt::format("missing in {}; expected a number ({})", f.section, f.unit));
      continue;
    }
    const double v = rd.number(n, f.key);
    f.set(d, f.integer ? fe_whole(rd, n, f.key, v) : v);
  }
  if (const YAML::Node sv = root["solver"]; sv.IsDefined() && sv.IsMap() && !sv["type"].IsDefined())
    rd.fail(sv, "type",
            "missing in solver; expected modal or direct (without it the line would be solved directly and the "
            "section's modal keys — cutoff, window_behind, window_ahead — used for nothing)");
  if (const YAML::Node sv = root["solver"]; sv.IsDefined() && (sv.IsScalar() || (sv.IsMap() && sv["type"].IsDefined()))) {
    const YAML::Node tn = sv.IsScalar() ? sv : sv["type"];
    const std::string t = tn.IsScalar() ? tn.Scalar() : "";
    if (t != "modal" && t != "direct")
      rd.fail(tn, sv.IsScalar() ? "solver" : "type", fmt::format("expected modal or direct, got '{}'", t));
    d.solver = t == "modal" ? catenary::FeCatenaryData::Solver::Modal : catenary::FeCatenaryData::Solver::Direct;
  }
  const YAML::Node drop = root["droppers"];
  for (const char* k : {"x", "presag", "nominal_length"}) {
    const YAML::Node n = drop[k];
    if (!n.IsDefined() || n.IsNull()) {
      if (std::string(k) != "nominal_length")
        rd.fail(drop, k,
                fmt::format("missing in droppers; expected a list of {} (m), one per dropper of a span",
                            std::string(k) == "x" ? "positions from the span's first mast" : "contact-wire pre-sags, positive down"));
      continue;
    }
    *fe_list(d, k) = fe_numbers(rd, n, k);
  }
  if (const YAML::Node rg = root["registration"]; rg.IsMap() && rg["uplift_limited"].IsDefined())  // a stop (issue 53)
    d.registration_uplift_limited = rd.boolean(rg["uplift_limited"], "uplift_limited");
  if (const YAML::Node st = root["stitch"]; st.IsDefined() && !st.IsNull()) read_fe_stitch(rd, st, d.stitch);
  if (const YAML::Node ir = root["irregularity"]; ir.IsDefined() && !ir.IsNull()) read_fe_irregularity(rd, ir, d);
  if (const YAML::Node sec = root["section"]; sec.IsDefined() && !sec.IsNull()) {
    const YAML::Node n = rd.need(sec, "spans", "section");
    if (!n.IsSequence() || n.size() != 2) rd.fail(n, "spans", "expected [first, last]: the spans of the analysis section (1-based)");
    d.section_first = fe_whole(rd, n[0], "spans", rd.number(n[0], "spans"));
    d.section_last = fe_whole(rd, n[1], "spans", rd.number(n[1], "spans"));
  }
  if (sectioned) read_fe_sections(rd, root, d);
  c.contact = catenary::Contact{catenary::Contact::Kind::Penalty, 50e3, 0.0};
  if (const YAML::Node ct = root["contact"]; ct.IsDefined()) {
    rd.keys(ct, "contact", {"type", "stiffness", "damping"});
    read_contact(path, ct, c.contact);
    if (c.contact.kind != catenary::Contact::Kind::Penalty)
      rd.fail(ct["type"], "type",
              "the finite-element catenary takes a penalty contact (unilateral: the head may leave the wire); "
              "expected penalty");
  }
  try {
    d.validate();
  } catch (const InvalidArgument& e) {
    fe_fail(rd, root, e);
  }
}

// tension_sections: [{spans, anchors, span?, messenger?, contact_wire?, droppers?, stitch?, supports?,
// registration?}, …] and overlap: {spans, outgoing, incoming} (docs/model-format.md "Tension sections").
// Each section is the file's line with its own keys over it; `d` the whole line (its spans set here).
void read_fe_sections(const detail::Reader& rd, const YAML::Node& root, catenary::FeCatenaryData& d) {
  const YAML::Node list = root["tension_sections"];
  if (!list.IsSequence() || list.size() == 0)
    rd.fail(list, "tension_sections", "expected a list of sections: - {spans: 12, anchors: pinned}, one per tension section");
  const YAML::Node ov = root["overlap"];
  if (!ov.IsDefined() || !ov.IsMap())
    rd.fail(ov.IsDefined() ? ov : root, "overlap",
            "missing: a line of tension sections needs overlap: {spans: N, outgoing: [N+1 heights, m], incoming: [N+1 heights, m]}");
  rd.keys(ov, "overlap", {"spans", "outgoing", "incoming"});
  const YAML::Node on = rd.need(ov, "spans", "overlap");
  d.overlap_spans = fe_whole(rd, on, "spans", rd.number(on, "spans"));
  for (const char* k : {"outgoing", "incoming"}) {
    const YAML::Node h = rd.need(ov, k, "overlap");
    const bool out = std::string(k) == "outgoing";
    std::vector<double>& v = out ? d.overlap_outgoing : d.overlap_incoming;
    if (h.IsMap()) {  // a profile: {x: [m from the overlap's first support], z: [heights, m]}
      const std::string where = fmt::format("overlap.{}", k);
      rd.keys(h, where, {"x", "z"});
      std::vector<double>& xs = out ? d.overlap_outgoing_x : d.overlap_incoming_x;
      for (const char* c : {"x", "z"}) {
        const YAML::Node l = rd.need(h, c, where);
        if (!l.IsSequence())
          rd.fail(l, fmt::format("{}.{}", k, c),
                  std::string(c) == "x" ? "expected a list of positions (m) from the overlap's first support, 0 … overlap.spans spans"
                                        : "expected a list of contact-wire heights (m, up), one per position in x");
        for (const auto& item : l) (std::string(c) == "x" ? xs : v).push_back(rd.number(item, fmt::format("{}.{}", k, c)));
      }
      continue;
    }
    if (!h.IsSequence())
      rd.fail(h, k, "expected a list of contact-wire heights (m, up), one per overlap support (overlap.spans + 1), in line "
                    "order, or a profile {x: [m from the overlap's first support], z: [m]}");
    for (const auto& item : h) v.push_back(rd.number(item, k));
  }
  static const std::vector<std::string> own{"messenger", "contact_wire", "droppers", "supports", "registration"};
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node sn = list[k];
    const std::string where = fmt::format("tension_sections[{}]", k);
    if (!sn.IsMap()) rd.fail(sn, where, "expected a section: {spans, anchors, and optionally span, messenger, contact_wire, droppers, stitch, supports, registration}");
    rd.keys(sn, where, {"spans", "span", "anchors", "messenger", "contact_wire", "droppers", "stitch", "supports", "registration"});
    catenary::FeCatenaryData s = d;
    s.tension_sections.clear();
    s.section_first = s.section_last = -1;  // the analysis section is the whole line's (its spans), as --set's
    s.overlap_outgoing.clear(), s.overlap_incoming.clear(), s.overlap_outgoing_x.clear(), s.overlap_incoming_x.clear();
    s.overlap_spans = 0;
    const YAML::Node spans = rd.need(sn, "spans", where);
    s.spans = fe_whole(rd, spans, "spans", rd.number(spans, "spans"));
    if (const YAML::Node n = sn["span"]; n.IsDefined()) s.span = rd.number(n, "span");
    const YAML::Node an = sn["anchors"];
    if (!an.IsDefined() || an.IsNull())
      rd.fail(sn, "anchors", fmt::format("missing in {}: each section ends at anchors; expected anchors: pinned, or "
                                         "anchors: {{stiffness: N/m, mass: kg}} of a tensioning device", where));
    if (an.IsScalar()) {
      if (an.Scalar() != "pinned") rd.fail(an, "anchors", fmt::format("expected pinned or {{stiffness, mass}}, got '{}'", an.Scalar()));
    } else {
      rd.keys(an, where + ".anchors", {"stiffness", "mass"});
      s.anchor.pinned = false;
      s.anchor.stiffness = rd.number(rd.need(an, "stiffness", where + ".anchors"), "stiffness");
      s.anchor.mass = rd.number_or(an, "mass", 0.0);
    }
    for (const std::string& sec : own) {  // the section's own values over the line's, key by key
      const YAML::Node o = sn[sec];
      if (!o.IsDefined() || o.IsNull()) continue;
      std::vector<std::string> allowed;
      for (const FeField& f : fe_fields())
        if (sec == f.section) allowed.emplace_back(f.key);
      if (sec == "droppers") allowed.insert(allowed.end(), {"x", "presag"});
      rd.keys(o, where + "." + sec, allowed);
      for (const FeField& f : fe_fields())
        if (sec == f.section)
          if (const YAML::Node n = o[f.key]; n.IsDefined()) {
            const double v = rd.number(n, f.key);
            f.set(s, f.integer ? fe_whole(rd, n, f.key, v) : v);
          }
      if (sec == "droppers")
        for (const char* l : {"x", "presag"})
          if (const YAML::Node n = o[l]; n.IsDefined()) *fe_list(s, l) = fe_numbers(rd, n, l);
    }
    if (const YAML::Node st = sn["stitch"]; st.IsDefined()) {  // the line's stitch key by key; null: none here
      if (st.IsNull()) s.stitch = catenary::FeStitch{};
      else read_fe_stitch(rd, st, s.stitch);
    }
    d.tension_sections.push_back(std::move(s));
  }
  try {
    d.link_sections();
  } catch (const InvalidArgument& e) {
    // "tension_sections" + "[k].key", or "overlap" + "key[j]": at that node.
    const std::string what = e.what(), key = e.parameter();
    YAML::Node at = root;
    if (what.find(": overlap:") != std::string::npos || what.rfind("finite-element catenary: overlap", 0) == 0) {
      at.reset(ov);
      std::string base = key.substr(0, key.find('['));
      if (const auto dot = base.find('.'); dot != std::string::npos) {  // a profile's list: outgoing.x, incoming.z
        if (const YAML::Node w = ov[base.substr(0, dot)]; w.IsMap()) at.reset(w);
        base = base.substr(dot + 1);
      }
      if (const YAML::Node n = at.IsMap() ? at[base] : YAML::Node(); n.IsDefined()) {
        at.reset(n);
        if (const auto open = key.find('['); open != std::string::npos && n.IsSequence()) {
          const std::size_t j = std::stoul(key.substr(open + 1));
          if (j < n.size()) at.reset(n[j]);
        }
      }
      rd.fail(at, "overlap." + key, e.problem());
    }
    at.reset(list);
    if (key.size() > 1 && key[0] == '[') {
      const std::size_t k = std::stoul(key.substr(1));
      const std::string leaf = key.substr(key.find(']') + 2 <= key.size() ? key.find(']') + 2 : key.size());
      if (k < list.size()) {
        at.reset(list[k]);
        if (const YAML::Node n = list[k][leaf]; !leaf.empty() && n.IsDefined()) at.reset(n);
      }
    }
    rd.fail(at, "tension_sections" + (key == "tension_sections" ? std::string() : key), e.problem());
  }
}

// The number of an override, strictly (issue 38): a decimal number, the whole text — no leading or
// trailing space, no hexadecimal (std::stod read "0x10" as 16 and " 5" as 5); a leading '+' is allowed.
bool override_number(const std::string& text, double& v) {
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+' && b + 1 != e && *(b + 1) != '-' && *(b + 1) != '+') ++b;
  if (b == e) return false;
  const auto r = std::from_chars(b, e, v, std::chars_format::general);
  return r.ec == std::errc() && r.ptr == e;
}

// "section.key=value" on a finite-element catenary; returns false if no field has that name.
bool set_fe(catenary::FeCatenaryData& d, const std::string& section, std::string key, const std::string& value,
            const std::string& o) {
  auto number = [&]() {
    double v = 0;
    if (!override_number(value, v))
      throw ModelError(fmt::format("--set '{}': '{}' is not a number (a decimal number such as 16000 or 1.5e4)", o, value));
    return v;
  };
  auto whole = [&](double v) {
    if (!(std::abs(v) < 1e9) || v != std::floor(v))
      throw ModelError(fmt::format("--set '{}': expected a whole number, got {}", o, value));
    return static_cast<int>(v);
  };
  if (section == "section" && key == "spans") {
    const auto colon = value.find(':');
    if (colon == std::string::npos)
      throw ModelError(fmt::format("--set '{}': expected section.spans=FIRST:LAST, e.g. section.spans=4:7", o));
    const std::string all = value;
    const std::string first = all.substr(0, colon), last = all.substr(colon + 1);
    auto parse = [&](const std::string& t) {
      std::size_t used = 0;
      int v = 0;
      try {
        v = std::stoi(t, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != t.size())
        throw ModelError(fmt::format("--set '{}': expected section.spans=FIRST:LAST with whole numbers", o));
      return v;
    };
    d.section_first = parse(first);
    d.section_last = parse(last);
    return true;
  }
  if (section == "solver" && key == "type") {
    if (value != "modal" && value != "direct") throw ModelError(fmt::format("--set '{}': expected solver.type=modal or direct", o));
    d.solver = value == "modal" ? catenary::FeCatenaryData::Solver::Modal : catenary::FeCatenaryData::Solver::Direct;
    return true;
  }
  if (section == "registration" && key == "uplift_limited") {
    if (value != "true" && value != "false")
      throw ModelError(fmt::format("--set '{}': expected registration.uplift_limited=true or false", o));
    d.registration_uplift_limited = value == "true";
    return true;
  }
  if (section == "stitch") {
    catenary::FeStitch& st = d.stitch;
    if (key == "enabled") {
      if (value != "true" && value != "false") throw ModelError(fmt::format("--set '{}': expected stitch.enabled=true or false", o));
      if (!st.present) throw ModelError(fmt::format("--set '{}': the file has no stitch section", o));
      st.enabled = value == "true";
      return true;
    }
    double* target = key == "length" ? &st.length : key == "tension" ? &st.wire.tension
                   : key == "mass_per_length" ? &st.wire.mass_per_length : key == "EI" ? &st.wire.EI
                   : key == "clamp_mass" ? &st.clamp_mass : key == "droppers.EA" ? &st.dropper_EA
                   : key == "droppers.mass_per_length" ? &st.dropper_mass_per_length
                   : key == "droppers.clamp_mass_stitch" ? &st.clamp_mass_stitch
                   : key == "droppers.clamp_mass_contact" ? &st.clamp_mass_contact : nullptr;
    if (!target) return false;
    if (!st.present) throw ModelError(fmt::format("--set '{}': the file has no stitch section (give one in the file: length, tension, mass_per_length, droppers)", o));
    *target = number();
    return true;
  }
  if (section == "irregularity") {
    catenary::FeIrregularity& irr = d.irregularity;
    if (key == "dropper_length_std") {
      irr.dropper_length_std = number();
      return true;
    }
    if (key == "seed") {
      const double v = number();
      if (!(v >= 0 && v < 9007199254740992.0) || v != std::floor(v))
        throw ModelError(fmt::format("--set '{}': expected a whole number from 0 to 2^53 − 1 = 9007199254740991 (exact as a number)", o));
      irr.seed = static_cast<std::uint64_t>(v);
      return true;
    }
    if (key == "height_errors") {
      read_height_errors(value, irr);
      return true;
    }
    if (key == "exact_dropper_dynamics") {
      if (value != "true" && value != "false")
        throw ModelError(fmt::format("--set '{}': expected irregularity.exact_dropper_dynamics=true or false", o));
      irr.exact_dropper_dynamics = value == "true";
      return true;
    }
    return false;
  }
  if (section == "droppers") {
    if (const auto open = key.find('['); open != std::string::npos && key.back() == ']') {
      const std::string idx = key.substr(open + 1, key.size() - open - 2);
      std::vector<double>* list = fe_list(d, key.substr(0, open));
      if (!list) return false;
      if (idx.empty() || idx.find_first_not_of("0123456789") != std::string::npos || std::stoul(idx) >= list->size())
        throw ModelError(fmt::format("--set '{}': droppers.{} has {} value(s), index 0 to {}", o, key.substr(0, open),
                                     list->size(), static_cast<long>(list->size()) - 1));
      (*list)[std::stoul(idx)] = number();
      return true;
    }
  }
  for (const FeField& f : fe_fields())
    if (section == f.section && key == f.key) {
      const double v = number();
      f.set(d, f.integer ? whole(v) : v);
      return true;
    }
  return false;
}

std::string fe_override_help() {
  std::string s;
  for (const FeField& f : fe_fields()) s += fmt::format("{}.{}, ", f.section, f.key);
  return s + "droppers.x[i], droppers.presag[i], droppers.nominal_length[i], section.spans=FIRST:LAST, solver.type=modal|direct, "
             "stitch.enabled=true|false, stitch.length, stitch.tension, stitch.mass_per_length, stitch.EI, stitch.clamp_mass, "
             "stitch.droppers.EA, irregularity.dropper_length_std, irregularity.seed, irregularity.height_errors=CSV, "
             "irregularity.exact_dropper_dynamics=true|false, registration.uplift_limited=true|false, ";
}

void apply_override(Parsed& c, const std::string& o) {
  auto dot = o.find('.'), eq = o.find('=');
  if (dot == std::string::npos || eq == std::string::npos || eq < dot)
    throw ModelError(fmt::format("--set '{}': expected section.key=value, e.g. catenary.kc0=5000", o));
  std::string section = o.substr(0, dot), key = o.substr(dot + 1, eq - dot - 1), value = o.substr(eq + 1);
  double v = 0;
  const bool is_number = override_number(value, v);
  if (c.type == Type::FiniteElement && section != "contact") {
    if (!set_fe(c.fe, section, key, value, o))
      throw ModelError(fmt::format("--set '{}': unknown key; expected {}contact.type, contact.stiffness, contact.damping",
                                   o, fe_override_help()));
    if (c.fe.sectioned() && section != "section") {  // a line of tension sections: every section
      if (section == "line" && key == "spans")
        throw ModelError(fmt::format("--set '{}': a line of tension sections takes its spans from its sections", o));
      for (catenary::FeCatenaryData& s : c.fe.tension_sections) set_fe(s, section, key, value, o);
      try {
        c.fe.link_sections();
      } catch (const InvalidArgument& e) {
        throw ModelError(fmt::format("--set '{}': {}", o, e.what()));
      }
    }
    try {
      c.fe.validate();
    } catch (const InvalidArgument& e) {
      throw ModelError(fmt::format("--set '{}': {}", o, e.what()));
    }
    return;
  }
  if (section == "contact" && key == "type") {
    if (value != "bilateral" && value != "penalty")
      throw ModelError(fmt::format("--set '{}': expected contact.type=bilateral or penalty", o));
    if (c.type == Type::FiniteElement && value == "bilateral")
      throw ModelError(fmt::format("--set '{}': the finite-element catenary takes a penalty contact (unilateral: the "
                                   "head may leave the wire); expected contact.type=penalty",
                                   o));
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

CatenaryFile read_catenary(const std::string& path, const std::vector<std::string>& overrides, bool make_fe) {
  const YAML::Node loaded = yaml_load_file(path, "catenary file");
  const YAML::Node& root = loaded;
  if (!root.IsMap())
    yaml_fail(path, root, "", "expected a mapping with 'catenary' (or 'profile', or type: finite_element) and optional 'contact'");
  Parsed c;
  if (const YAML::Node t = root["type"]; t.IsDefined()) {
    const std::string type = t.IsScalar() ? t.Scalar() : "";
    if (type == "wire_profile")
      c.type = Type::WireProfile;
    else if (type == "finite_element")
      c.type = Type::FiniteElement;
    else if (type != "lumped")
      yaml_fail(path, t, "type",
                "expected lumped (the lumped catenary, eq. 7.1), wire_profile (a rigid wire of given heights) or "
                "finite_element (messenger, contact wire and droppers)");
  }
  c.name = root["name"].IsDefined() ? root["name"].as<std::string>() : path;
  if (c.type == Type::FiniteElement) {
    read_fe(path, root, c);
  } else {
    const char* body = c.type == Type::Lumped ? "catenary" : "profile";
    std::set<std::string> seen;
    for (auto it = root.begin(); it != root.end(); ++it) {
      std::string k = it->first.as<std::string>();
      if (!seen.insert(k).second) yaml_fail(path, it->first, k, "duplicate key; give each key once");
      const bool fe_section = std::find(kFeSections.begin(), kFeSections.end(), k) != kFeSections.end() && k != "contact";
      if (k != "name" && k != "type" && k != body && k != "contact")
        yaml_fail(path, it->first, k,
                  fmt::format("unknown key; expected name, type, {}, contact{}", body,
                              fe_section ? " (a finite-element catenary needs type: finite_element)" : ""));
    }
    if (c.type == Type::Lumped)
      read_lumped(path, root["catenary"], c);
    else
      read_profile(path, root["profile"], c);
    if (const YAML::Node ct = root["contact"]; ct.IsDefined()) read_contact(path, ct, c.contact);
    make(c, path);  // the file's own values are valid
  }
  for (const std::string& o : overrides) apply_override(c, o);
  CatenaryFile f{c.name, make(c, overrides.empty() ? path : path + " (after --set)", make_fe), c.contact, std::nullopt, {}, {}};
  if (c.type == Type::FiniteElement) f.fe = c.fe;
  return f;
}

CatenaryFile guarded(const std::string& path, const std::vector<std::string>& overrides, bool make_fe) {
  try {
    return read_catenary(path, overrides, make_fe);
  } catch (const YAML::Exception& e) {  // a wrong node type (a list where a name belongs, ...)
    throw ModelError(fmt::format("{}:{}: {}; expected the catenary file format of docs/model-format.md", path,
                                 e.mark.line + 1, e.msg));
  }
}
}  // namespace

CatenaryFile load_catenary(const std::string& path, const std::vector<std::string>& overrides) {
  const numerics::PhaseTimer timer("load: catenary file");
  CatenaryFile f = guarded(path, overrides, true);
  f.path = path, f.overrides = overrides;
  return f;
}

CatenaryFile read_catenary_file(const std::string& path, const std::vector<std::string>& overrides) {
  return guarded(path, overrides, false);
}

catenary::FeCatenaryData read_fe_catenary_data(const std::string& path, const std::vector<std::string>& overrides) {
  CatenaryFile f = read_catenary_file(path, overrides);
  if (!f.fe)
    throw ModelError(fmt::format("{}: not a finite-element catenary file (expected type: finite_element); it is a {}",
                                 path, f.catenary->describe()));
  return *f.fe;
}

}  // namespace inerta::io
