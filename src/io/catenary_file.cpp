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
#include "inerta/catenary/fe_schema.hpp"
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
// Every key from the schema (catenary/fe_schema.hpp): reading, --set, ranges, messages.
using catenary::FeKey;
using catenary::FeKeyError;
using catenary::FeLocation;
using catenary::FeRef;

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  for (std::size_t at = 0;;) {
    const std::size_t dot = path.find('.', at);
    parts.push_back(path.substr(at, dot - at));
    if (dot == std::string::npos) return parts;
    at = dot + 1;
  }
}

// The node at `parts` below `n`, as deep as the file goes; `full`: all of them there.
YAML::Node walk(const YAML::Node& n, const std::vector<std::string>& parts, bool& full) {
  YAML::Node at;
  at.reset(n);
  full = true;
  for (const std::string& p : parts) {
    if (!at.IsMap() || !at[p].IsDefined()) return full = false, at;
    const YAML::Node next = at[p];
    at.reset(next);
  }
  return at;
}

// The names a map of the file may hold at `prefix` (a section, or stitch.droppers), from the schema.
std::vector<std::string> children(const std::string& prefix, bool in_section = false) {
  std::vector<std::string> out;
  for (const FeKey& k : catenary::fe_keys()) {
    if (k.path.rfind(prefix + ".", 0) != 0 || (in_section && !k.in_sections)) continue;
    const std::string rest = k.path.substr(prefix.size() + 1), first = rest.substr(0, rest.find('.'));
    if (std::find(out.begin(), out.end(), first) == out.end()) out.push_back(first);
  }
  return out;
}

std::string expected_text(const FeKey& k) {
  using T = FeKey::Type;
  const std::string u = k.unit.empty() ? "" : " (" + k.unit + ")";
  switch (k.type) {
    case T::Number: return "a number" + u;
    case T::Whole: return "a whole number" + u;
    case T::Bool: return "true or false";
    case T::Choice: {
      std::string s;
      for (const std::string& c : k.choices) s += (s.empty() ? "" : " or ") + c;
      return s;
    }
    case T::Numbers: return "a list of numbers" + u + ": " + k.doc;
    case T::Csv: return "the path of a CSV file: " + k.doc;
    case T::SpanRange: return "[first, last]: " + k.doc;
    case T::PointMasses: return k.doc;
  }
  return "";
}

// A CSV profile (x and one value column, relative to the file or to the working directory for --set).
void read_csv_profile(const std::string& csv, const catenary::FeCsvRef& r) {
  const CsvTable t = CsvTable::read(csv);
  if (t.column("x").size() < 2)  // only a header (or one point) would run as the perfect line
    throw ModelError(fmt::format("{}: {} data row(s); expected x (m) and {} at 2 or more points covering the line", csv,
                                 t.column("x").size(), r.column));
  *r.file = csv;
  *r.x = t.column("x");
  *r.value = t.column(r.column);
}

// One key's value from its node `n`, checked against its range, into d.
// `section`: a tension section's (tension_sections[k]), whose keys are named in full.
void read_key(const detail::Reader& rd, const FeKey& k, const YAML::Node& n, catenary::FeCatenaryData& d,
              const std::string& section = "") {
  using T = FeKey::Type;
  const FeRef r = k.ref(d);
  const std::string name = section.empty() ? k.name() : section + "." + k.path;
  auto in_range = [&](double v) {
    if (const std::string e = k.check(v); !e.empty())
      rd.fail(n, name, (section.empty() ? e + " in " + k.section() : e) + (k.note.empty() ? "" : "; " + k.note));
    return v;
  };
  switch (k.type) {
    case T::Number:
      *std::get<double*>(r) = in_range(rd.number(n, name));
      return;
    case T::Whole: {
      const double v = rd.number(n, name);
      if (!(std::abs(v) < 1e16) || v != std::floor(v)) rd.fail(n, name, fmt::format("expected a whole number, got {}", v));
      in_range(v);
      if (auto p = std::get_if<int*>(&r)) **p = static_cast<int>(v);
      else *std::get<std::uint64_t*>(r) = static_cast<std::uint64_t>(v);
      return;
    }
    case T::Bool:
      *std::get<bool*>(r) = rd.boolean(n, name);
      return;
    case T::Choice: {
      const std::string v = n.IsScalar() ? n.Scalar() : "";
      if (std::find(k.choices.begin(), k.choices.end(), v) == k.choices.end())
        rd.fail(n, name, fmt::format("expected {}, got '{}'", expected_text(k), v));
      *std::get<catenary::FeCatenaryData::Solver*>(r) =
          v == "modal" ? catenary::FeCatenaryData::Solver::Modal : catenary::FeCatenaryData::Solver::Direct;
      return;
    }
    case T::Numbers: {
      if (!n.IsSequence()) rd.fail(n, name, "expected " + expected_text(k));
      std::vector<double>& v = *std::get<std::vector<double>*>(r);
      v.clear();
      for (const auto& item : n) v.push_back(rd.number(item, name));
      return;
    }
    case T::Csv:
      if (!n.IsScalar()) rd.fail(n, name, "expected " + expected_text(k));
      try {
        read_csv_profile(rd.relative_path(n.Scalar()), std::get<catenary::FeCsvRef>(r));
      } catch (const ModelError& e) {
        rd.fail(n, name, e.what());
      }
      return;
    case T::SpanRange: {
      if (!n.IsSequence() || n.size() != 2) rd.fail(n, name, "expected [first, last]: the spans of the analysis section (1-based)");
      const catenary::FeSpanRef s = std::get<catenary::FeSpanRef>(r);
      for (auto [i, out] : {std::pair{0u, s.first}, std::pair{1u, s.last}}) {
        const double v = rd.number(n[i], name);
        if (!(std::abs(v) < 1e9) || v != std::floor(v)) rd.fail(n[i], name, fmt::format("expected a whole number, got {}", v));
        *out = static_cast<int>(v);
      }
      return;
    }
    case T::PointMasses: {
      if (!n.IsSequence()) rd.fail(n, name, "expected a list of {x, mass}: x along the line (m), mass (kg)");
      auto& v = *std::get<std::vector<catenary::FeIrregularity::PointMass>*>(r);
      v.clear();
      for (const auto& item : n) {
        rd.keys(item, name, {"x", "mass"});
        v.push_back({rd.number(rd.need(item, "x", name), "x"), rd.number(rd.need(item, "mass", name), "mass")});
      }
      return;
    }
  }
}

// Every key of the schema under `map` (the file's top level, or a tension section's over the line's:
// `over`, then only keys a section may give, none required; `section` names it). `prefix` limits it to
// one section; `skip` a key not read. The values first, then what is missing.
void read_keys(const detail::Reader& rd, const YAML::Node& map, catenary::FeCatenaryData& d, const std::string& prefix,
               bool over, const std::string& skip = "", const std::string& section = "") {
  std::vector<const FeKey*> missing;
  for (const FeKey& k : catenary::fe_keys()) {
    if (k.path.rfind(prefix + ".", 0) != 0 || (over && !k.in_sections) || k.path == skip) continue;
    bool full = false;
    const YAML::Node n = walk(map, split_path(k.path), full);
    if (full && !n.IsNull()) read_key(rd, k, n, d, section);
    else if (k.required && !over) missing.push_back(&k);
  }
  for (const FeKey* k : missing) {  // at its map if that is given, else at the nearest map the file has
    std::vector<std::string> parts = split_path(k->path);
    parts.pop_back();
    bool parent = false;
    const YAML::Node at = walk(map, parts, parent);
    if (!parent)
      rd.fail(at, parts.back(), fmt::format("missing in {}; expected {}: {{{}}}", parts.front(), parts.back(),
                                            fmt::join(children(k->section()), ", ")));
    rd.fail(at, k->name(), fmt::format("missing in {}; expected {}", k->section(), expected_text(*k)));
  }
}

// The keys of a map of the file at `prefix` and its sub-maps (stitch.droppers) are all in the schema.
void check_keys(const detail::Reader& rd, const YAML::Node& map, const std::string& prefix, bool in_section) {
  rd.keys(map, prefix, children(prefix, in_section));
  for (const std::string& c : children(prefix, in_section))
    if (const YAML::Node sub = map[c]; sub.IsDefined() && sub.IsMap() && !catenary::find_fe_key(prefix + "." + c))
      check_keys(rd, sub, prefix + "." + c, in_section);
}

// The node of a located key: a tension section's own value where it gives one, else the line's.
YAML::Node locate(const YAML::Node& root, const FeLocation& l) {
  const std::vector<std::string> parts = l.key.empty() ? std::vector<std::string>{} : split_path(l.key);
  bool full = false;
  YAML::Node at = walk(root, parts, full);
  if (const YAML::Node list = root["tension_sections"]; l.section >= 0 && list.IsSequence() && static_cast<std::size_t>(l.section) < list.size()) {
    const YAML::Node sec = list[static_cast<std::size_t>(l.section)];
    bool own = false;
    const YAML::Node mine = walk(sec, parts, own);
    if (own || parts.empty() || (sec.IsMap() && sec[parts.front()].IsDefined())) at.reset(mine);
    else if (!full) at.reset(sec);
    full = own || full;
  }
  if (full && l.index >= 0 && at.IsSequence() && static_cast<std::size_t>(l.index) < at.size()) {
    const YAML::Node item = at[static_cast<std::size_t>(l.index)];
    at.reset(item);
  }
  return at;
}

// A located complaint (FeCatenaryData::validate, join_sections) at the line of its key.
[[noreturn]] void fe_fail(const detail::Reader& rd, const YAML::Node& root, const FeKeyError& e) {
  const FeLocation& l = e.at;
  const YAML::Node at = locate(root, l);
  const std::string index = l.index >= 0 ? fmt::format("[{}]", l.index) : "";
  if (l.section >= 0) rd.fail(at, fmt::format("tension_sections[{}]{}{}{}", l.section, l.key.empty() ? "" : ".", l.key, index), e.problem());
  const auto dot = l.key.rfind('.');
  if (dot == std::string::npos || l.key.rfind("overlap.", 0) == 0) rd.fail(at, l.key + index, e.problem());
  rd.fail(at, l.key.substr(dot + 1) + index, fmt::format("{} in {}", e.problem(), l.key.substr(0, dot)));
}

int fe_whole(const detail::Reader& rd, const YAML::Node& n, const std::string& key, double v) {
  if (!(std::abs(v) < 1e9) || v != std::floor(v)) rd.fail(n, key, fmt::format("expected a whole number, got {}", v));
  return static_cast<int>(v);
}

void read_fe_sections(const detail::Reader& rd, const YAML::Node& root, catenary::FeCatenaryData& d);

void read_fe(const std::string& path, const YAML::Node& root, Parsed& c) {
  const detail::Reader rd(path);
  std::vector<std::string> top{"name", "type", "contact", "tension_sections", "overlap"};
  for (const catenary::FeSection& s : catenary::fe_sections()) top.push_back(s.name);
  rd.keys(root, "a finite-element catenary file", top);
  const bool sectioned = root["tension_sections"].IsDefined();
  if (root["overlap"].IsDefined() && !sectioned)
    rd.fail(root["overlap"], "overlap", "an overlap joins tension sections; give tension_sections too (docs/model-format.md)");
  catenary::FeCatenaryData& d = c.fe;
  // Masses the file does not give are absent (not the benchmark's values, FeCatenaryData's defaults).
  d.dropper_mass_per_length = d.clamp_mass_messenger = d.clamp_mass_contact = 0;
  d.support_mass = d.registration_mass = 0;
  d.messenger.EI = d.contact_wire.EI = 0;
  for (const catenary::FeSection& s : catenary::fe_sections()) {  // every section's presence and keys first
    const YAML::Node sec = root[s.name];
    if (!sec.IsDefined() || sec.IsNull()) {
      if (s.required)
        rd.fail(root, s.name, fmt::format("missing in a finite-element catenary file; expected {}: {{{}}}", s.name,
                                          fmt::join(children(s.name), ", ")));
      continue;
    }
    if (s.name == "solver" && sec.IsScalar()) continue;  // `solver: modal`, the type alone
    check_keys(rd, sec, s.name, false);
  }
  for (const catenary::FeSection& s : catenary::fe_sections()) {
    const YAML::Node sec = root[s.name];
    if (!sec.IsDefined() || sec.IsNull()) continue;
    if (s.name == "solver" && sec.IsScalar()) {
      const FeKey& type = *catenary::find_fe_key("solver.type");
      if (std::find(type.choices.begin(), type.choices.end(), sec.Scalar()) == type.choices.end())
        rd.fail(sec, "solver", fmt::format("expected {}, got '{}'", expected_text(type), sec.Scalar()));
      read_key(rd, type, sec, d);
      continue;
    }
    if (s.present) *s.present(d) = true;
    if (s.name == "line" && sectioned)
      if (const YAML::Node n = sec["spans"]; n.IsDefined())
        rd.fail(n, "spans", "a line of tension_sections takes its spans from its sections (tension_sections[k].spans); remove line.spans");
    if (s.name == "wear" && sec["uniform"].IsDefined() && sec["profile"].IsDefined())
      rd.fail(sec["profile"], "profile", "give either wear.uniform or wear.profile, not both");
    read_keys(rd, root, d, s.name, false, sectioned ? "line.spans" : "");
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
  } catch (const FeKeyError& e) {
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
  static const std::vector<std::string> own{"messenger", "contact_wire", "droppers", "supports", "registration", "stitch"};
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node sn = list[k];
    const std::string where = fmt::format("tension_sections[{}]", k);
    if (!sn.IsMap()) rd.fail(sn, where, "expected a section: {spans, anchors, and optionally span, messenger, contact_wire, droppers, stitch, supports, registration}");
    std::vector<std::string> allowed{"spans", "span", "anchors"};
    allowed.insert(allowed.end(), own.begin(), own.end());
    rd.keys(sn, where, allowed);
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
      if (!o.IsDefined()) continue;
      if (sec == "stitch" && o.IsNull()) {  // null: no stitch in this section
        s.stitch = catenary::FeStitch{};
        continue;
      }
      if (o.IsNull()) continue;
      check_keys(rd, o, sec, true);
      if (sec == "stitch" && !s.stitch.present) {  // a stitch of its own: the whole section, as the line's
        s.stitch.present = true;
        read_keys(rd, sn, s, sec, false, "", where);
        continue;
      }
      read_keys(rd, sn, s, sec, true, "", where);
    }
    d.tension_sections.push_back(std::move(s));
  }
  try {
    d.join_sections();
  } catch (const FeKeyError& e) {
    fe_fail(rd, root, e);
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

// "path=value" (path: a schema key, a list's item as path[i]) on a finite-element catenary; false if no
// key has that path.
bool set_fe(catenary::FeCatenaryData& d, std::string path, const std::string& value, const std::string& o) {
  using T = FeKey::Type;
  int index = -1;
  if (const auto open = path.find('['); open != std::string::npos && path.back() == ']') {
    const std::string idx = path.substr(open + 1, path.size() - open - 2);
    path.resize(open);
    if (idx.empty() || idx.size() > 9 || idx.find_first_not_of("0123456789") != std::string::npos)
      throw ModelError(fmt::format("--set '{}': expected {}[i]=value with i a whole number >= 0", o, path));
    index = std::stoi(idx);
  }
  const FeKey* key = catenary::find_fe_key(path);
  if (!key) return false;
  const FeKey& k = *key;
  if (k.path.rfind("stitch.", 0) == 0 && !d.stitch.present)
    throw ModelError(fmt::format("--set '{}': the file has no stitch section (give one in the file: length, tension, "
                                 "mass_per_length, droppers)", o));
  if ((k.type == T::Numbers) != (index >= 0))
    throw ModelError(index >= 0 ? fmt::format("--set '{}': {} is not a list", o, k.path)
                                : fmt::format("--set '{}': {} is a list; set one value as {}[i]=value", o, k.path, k.path));
  auto number = [&]() {
    double v = 0;
    if (!override_number(value, v))
      throw ModelError(fmt::format("--set '{}': '{}' is not a number (a decimal number such as 16000 or 1.5e4)", o, value));
    if (const std::string e = k.check(v); !e.empty() && k.type != T::Numbers)
      throw ModelError(fmt::format("--set '{}': finite-element catenary: {}: {}: {}{}", o, k.section(), k.name(), e,
                                   k.note.empty() ? "" : "; " + k.note));
    return v;
  };
  const FeRef r = k.ref(d);
  switch (k.type) {
    case T::Number:
      *std::get<double*>(r) = number();
      return true;
    case T::Whole: {
      const double v = number();
      if (v != std::floor(v)) throw ModelError(fmt::format("--set '{}': expected a whole number, got {}", o, value));
      if (auto p = std::get_if<int*>(&r)) **p = static_cast<int>(v);
      else *std::get<std::uint64_t*>(r) = static_cast<std::uint64_t>(v);
      return true;
    }
    case T::Bool:
      if (value != "true" && value != "false") throw ModelError(fmt::format("--set '{}': expected {}=true or false", o, k.path));
      *std::get<bool*>(r) = value == "true";
      return true;
    case T::Choice:
      if (std::find(k.choices.begin(), k.choices.end(), value) == k.choices.end())
        throw ModelError(fmt::format("--set '{}': expected {}={}", o, k.path, expected_text(k)));
      *std::get<catenary::FeCatenaryData::Solver*>(r) =
          value == "modal" ? catenary::FeCatenaryData::Solver::Modal : catenary::FeCatenaryData::Solver::Direct;
      return true;
    case T::Numbers: {
      std::vector<double>& list = *std::get<std::vector<double>*>(r);
      if (static_cast<std::size_t>(index) >= list.size())
        throw ModelError(fmt::format("--set '{}': {} has {} value(s), index 0 to {}", o, k.path, list.size(),
                                     static_cast<long>(list.size()) - 1));
      list[static_cast<std::size_t>(index)] = number();
      return true;
    }
    case T::Csv:
      try {
        read_csv_profile(value, std::get<catenary::FeCsvRef>(r));
      } catch (const ModelError& e) {
        throw ModelError(fmt::format("--set '{}': {}", o, e.what()));
      }
      return true;
    case T::SpanRange: {
      const auto colon = value.find(':');
      auto parse = [&](const std::string& t) {
        std::size_t used = 0;
        int v = 0;
        try {
          v = std::stoi(t, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != t.size())
          throw ModelError(fmt::format("--set '{}': expected {}=FIRST:LAST with whole numbers, e.g. section.spans=4:7", o, k.path));
        return v;
      };
      if (colon == std::string::npos) throw ModelError(fmt::format("--set '{}': expected {}=FIRST:LAST, e.g. section.spans=4:7", o, k.path));
      const catenary::FeSpanRef s = std::get<catenary::FeSpanRef>(r);
      *s.first = parse(value.substr(0, colon));
      *s.last = parse(value.substr(colon + 1));
      return true;
    }
    case T::PointMasses:
      throw ModelError(fmt::format("--set '{}': {} is a list of {{x, mass}}; give it in the file", o, k.path));
  }
  return false;
}

std::string fe_override_help() {
  std::string s;
  for (const FeKey& k : catenary::fe_keys()) {
    if (k.type == FeKey::Type::PointMasses) continue;
    s += k.path;
    if (k.type == FeKey::Type::Numbers) s += "[i]";
    if (k.type == FeKey::Type::Choice) s += "=" + expected_text(k);
    if (k.type == FeKey::Type::SpanRange) s += "=FIRST:LAST";
    if (k.type == FeKey::Type::Bool) s += "=true|false";
    if (k.type == FeKey::Type::Csv) s += "=CSV";
    s += ", ";
  }
  return s;
}

void apply_override(Parsed& c, const std::string& o) {
  auto dot = o.find('.'), eq = o.find('=');
  if (dot == std::string::npos || eq == std::string::npos || eq < dot)
    throw ModelError(fmt::format("--set '{}': expected section.key=value, e.g. catenary.kc0=5000", o));
  std::string section = o.substr(0, dot), key = o.substr(dot + 1, eq - dot - 1), value = o.substr(eq + 1);
  double v = 0;
  const bool is_number = override_number(value, v);
  if (c.type == Type::FiniteElement && section != "contact") {
    if (!set_fe(c.fe, section + "." + key, value, o))
      throw ModelError(fmt::format("--set '{}': unknown key; expected {}contact.type, contact.stiffness, contact.damping",
                                   o, fe_override_help()));
    if (c.fe.sectioned() && section != "section") {  // a line of tension sections: every section
      if (section == "line" && key == "spans")
        throw ModelError(fmt::format("--set '{}': a line of tension sections takes its spans from its sections", o));
      for (catenary::FeCatenaryData& s : c.fe.tension_sections) set_fe(s, section + "." + key, value, o);
      try {
        c.fe.join_sections();
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
      const auto& sections = catenary::fe_sections();
      const bool fe_section = std::any_of(sections.begin(), sections.end(), [&](const catenary::FeSection& s) { return s.name == k; });
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
