// The keys of a finite-element line file, declared once (catenary/fe_schema.hpp).
#include "inerta/catenary/fe_schema.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace inerta::catenary {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
std::string element_of(const FeLocation& at) {
  const auto dot = at.key.rfind('.');
  return "finite-element catenary: " + (dot == std::string::npos ? at.key : at.key.substr(0, dot));
}
std::string parameter_of(const FeLocation& at) {
  const auto dot = at.key.rfind('.');
  const std::string leaf = dot == std::string::npos ? at.key : at.key.substr(dot + 1);
  return at.index >= 0 ? fmt::format("{}[{}]", leaf, at.index) : leaf;
}
}  // namespace

FeKeyError::FeKeyError(FeLocation where, const std::string& problem)
    : InvalidArgument(element_of(where), parameter_of(where), problem), at(std::move(where)) {}

std::string FeKey::section() const { return path.substr(0, path.rfind('.')); }
std::string FeKey::name() const { return path.substr(path.rfind('.') + 1); }

std::string FeKey::range_text() const {
  if (type != Type::Number && type != Type::Whole) return "—";
  auto num = [](double v) { return v == std::floor(v) && std::abs(v) < 1e17 ? fmt::format("{:.0f}", v) : fmt::format("{:g}", v); };
  if (max == kInf) return fmt::format("{} {}", min_open ? ">" : ">=", num(min));
  return fmt::format("{}{} … {}", min_open ? "> " : "", num(min), num(max));
}

std::string FeKey::check(double v) const {
  const std::string u = unit.empty() ? "" : " (" + unit + ")";
  std::string e;
  const bool low = min_open ? !(v > min) : !(v >= min);
  if (low || (max == kInf && !std::isfinite(v))) e = fmt::format("must be {} {:g}{}, got {}", min_open ? ">" : ">=", min, u, v);
  else if (!(v <= max)) e = fmt::format("must be <= {:g}{}, got {}", max, u, v);
  return e;
}

std::string FeKey::value_text(const FeCatenaryData& d) const {
  const FeRef r = ref(const_cast<FeCatenaryData&>(d));  // read only
  const std::string u = unit.empty() ? unit : " " + unit;
  if (auto p = std::get_if<double*>(&r)) return std::isnan(**p) ? "none" : fmt::format("{:g}{}", **p, u);
  if (auto p = std::get_if<int*>(&r)) return fmt::format("{}", **p);
  if (auto p = std::get_if<bool*>(&r)) return **p ? "true" : "false";
  if (auto p = std::get_if<std::uint64_t*>(&r)) return fmt::format("{}", **p);
  if (auto p = std::get_if<std::vector<double>*>(&r)) return (*p)->empty() ? "none" : fmt::format("[{}]{}", fmt::join(**p, ", "), u);
  if (auto p = std::get_if<FeCatenaryData::Solver*>(&r)) return **p == FeCatenaryData::Solver::Modal ? "modal" : "direct";
  if (auto p = std::get_if<FeCsvRef>(&r)) return p->x->empty() ? "none" : fmt::format("{} ({} points)", *p->file, p->x->size());
  if (auto p = std::get_if<FeSpanRef>(&r)) return *p->first < 0 ? "the default" : fmt::format("{}:{}", *p->first, *p->last);
  if (auto p = std::get_if<std::vector<FeIrregularity::PointMass>*>(&r)) return fmt::format("{}", (*p)->size());
  return "";
}

#define INERTA_REF(member) [](FeCatenaryData& d) -> FeRef { return &d.member; }

const std::vector<FeKey>& fe_keys() {
  using T = FeKey::Type;
  static const std::vector<FeKey> keys{
      // path, type, unit, min, max, min_open, required, default, doc, in_sections, ref[, note, choices]
      {"line.span", T::Number, "m", 0, kInf, true, true, "", "distance between masts", false, INERTA_REF(span)},
      {"line.spans", T::Whole, "", 1, 1000, false, true, "", "number of spans (a line of tension_sections: from its sections)", false, INERTA_REF(spans)},
      {"line.encumbrance", T::Number, "m", 0, kInf, true, true, "", "messenger height above the contact wire at the masts", false, INERTA_REF(encumbrance)},
      {"line.gravity", T::Number, "m/s²", 0, kInf, false, false, "9.81", "gravitational acceleration", false, INERTA_REF(gravity)},
      {"messenger.tension", T::Number, "N", 0, 1e7, true, true, "", "messenger tension", true, INERTA_REF(messenger.tension), "real lines run at 10–40 kN"},
      {"messenger.mass_per_length", T::Number, "kg/m", 0, kInf, true, true, "", "messenger mass per length", true, INERTA_REF(messenger.mass_per_length)},
      {"messenger.EI", T::Number, "N·m²", 0, kInf, false, false, "0", "messenger bending stiffness", true, INERTA_REF(messenger.EI)},
      {"contact_wire.tension", T::Number, "N", 0, 1e7, true, true, "", "contact-wire tension", true, INERTA_REF(contact_wire.tension), "real lines run at 10–40 kN"},
      {"contact_wire.mass_per_length", T::Number, "kg/m", 0, kInf, true, true, "", "contact-wire mass per length (new wire)", true, INERTA_REF(contact_wire.mass_per_length)},
      {"contact_wire.EI", T::Number, "N·m²", 0, kInf, false, false, "0", "contact-wire bending stiffness (new wire)", true, INERTA_REF(contact_wire.EI)},
      {"droppers.x", T::Numbers, "m", -kInf, kInf, false, true, "", "dropper positions from the span's first mast", true, INERTA_REF(dropper_x)},
      {"droppers.presag", T::Numbers, "m", -kInf, kInf, false, true, "", "contact-wire pre-sag at each dropper (positive down)", true, INERTA_REF(presag)},
      {"droppers.nominal_length", T::Numbers, "m", -kInf, kInf, false, false, "none", "design dropper lengths, compared with the form-finding's", false, INERTA_REF(nominal_dropper_length)},
      {"droppers.EA", T::Number, "N", 0, 1e9, true, true, "", "dropper axial stiffness", true, INERTA_REF(dropper_EA), "real droppers: 1e5–3e5 N; beyond 1e9 N only the matrices' conditioning changes"},
      {"droppers.mass_per_length", T::Number, "kg/m", 0, kInf, false, false, "0", "dropper mass per length", true, INERTA_REF(dropper_mass_per_length)},
      {"droppers.clamp_mass_messenger", T::Number, "kg", 0, kInf, false, false, "0", "clamp mass at each dropper's messenger end", true, INERTA_REF(clamp_mass_messenger)},
      {"droppers.clamp_mass_contact", T::Number, "kg", 0, kInf, false, false, "0", "clamp mass at each dropper's contact-wire end", true, INERTA_REF(clamp_mass_contact)},
      {"supports.stiffness", T::Number, "N/m", 0, kInf, true, true, "", "messenger support stiffness at each mast", true, INERTA_REF(support_stiffness)},
      {"supports.mass", T::Number, "kg", 0, kInf, false, false, "0", "mass at each messenger support", true, INERTA_REF(support_mass)},
      {"registration.stiffness", T::Number, "N/m", 0, kInf, true, true, "", "registration (steady arm) stiffness at each mast", true, INERTA_REF(registration_stiffness)},
      {"registration.mass", T::Number, "kg", 0, kInf, false, false, "0", "mass at each registration", true, INERTA_REF(registration_mass)},
      {"registration.uplift_limit", T::Number, "m", 0, 10, true, false, "none", "design limit of the uplift at a registration (criterion support_uplift)", true, INERTA_REF(registration_uplift_limit)},
      {"registration.uplift_limited", T::Bool, "", -kInf, kInf, false, false, "false", "a stop limits the uplift (criterion's limited_clearance_factor)", false, INERTA_REF(registration_uplift_limited)},
      {"mesh.element_length", T::Number, "m", 1e-3, kInf, false, false, "0.25", "largest element; nodes at every dropper and mast", false, INERTA_REF(element_length)},
      {"damping.rayleigh_mass", T::Number, "1/s", 0, kInf, false, false, "0.0125", "Rayleigh a (C = a M + b K)", false, INERTA_REF(rayleigh_mass)},
      {"damping.rayleigh_stiffness", T::Number, "s", 0, kInf, false, false, "0.0001", "Rayleigh b", false, INERTA_REF(rayleigh_stiffness)},
      {"integration.time_step", T::Number, "s", 1e-5, 0.01, false, false, "0.001", "structural (and coupling) step", false, INERTA_REF(time_step),
       "a wire carries waves of tens of hertz, and each pantograph is stepped with the line: 1e-3 s is the bundled value, and halving it changes sigma by < 0.1 %"},
      {"integration.alpha", T::Number, "", -1.0 / 3.0, 0, false, false, "0", "HHT-α, −1/3 … 0 (0: no numerical dissipation)", false, INERTA_REF(hht_alpha)},
      {"solver.type", T::Choice, "", -kInf, kInf, false, true, "direct", "modal (a window of spans around the pantographs) or direct (the whole line)", false, INERTA_REF(solver), "", {"modal", "direct"}},
      {"solver.cutoff", T::Number, "Hz", 0, 2000, true, false, "100", "highest natural frequency kept by the modal solve", false, INERTA_REF(modal_cutoff), "the modes are for the contact-force band"},
      {"solver.window_behind", T::Whole, "spans", -1, 1000, false, false, "2", "spans of the window behind the rearmost pantograph's span (−1: the whole line)", false, INERTA_REF(window_behind)},
      {"solver.window_ahead", T::Whole, "spans", -1, 1000, false, false, "3", "spans ahead of the leading pantograph's span (−1: the whole line)", false, INERTA_REF(window_ahead)},
      {"section.spans", T::SpanRange, "", -kInf, kInf, false, true, "the middle spans", "analysis section [first, last] (1-based; --set section.spans=FIRST:LAST)", false,
       [](FeCatenaryData& d) -> FeRef { return FeSpanRef{&d.section_first, &d.section_last}; }},
      {"stitch.enabled", T::Bool, "", -kInf, kInf, false, false, "true", "false: the same line, every stitch dropper on the messenger", true, INERTA_REF(stitch.enabled)},
      {"stitch.length", T::Number, "m", 0, kInf, true, true, "", "stitch wire length, centred on each interior mast", true, INERTA_REF(stitch.length)},
      {"stitch.tension", T::Number, "N", 0, 1e7, true, true, "", "stitch wire tension", true, INERTA_REF(stitch.wire.tension), "real lines run at 10–40 kN"},
      {"stitch.mass_per_length", T::Number, "kg/m", 0, kInf, true, true, "", "stitch wire mass per length", true, INERTA_REF(stitch.wire.mass_per_length)},
      {"stitch.EI", T::Number, "N·m²", 0, kInf, false, false, "0", "stitch wire bending stiffness", true, INERTA_REF(stitch.wire.EI)},
      {"stitch.clamp_mass", T::Number, "kg", 0, kInf, false, false, "0", "mass at each of its two clamps on the messenger", true, INERTA_REF(stitch.clamp_mass)},
      {"stitch.droppers.x", T::Numbers, "m", -kInf, kInf, false, true, "", "stitch dropper positions, signed from the mast (|x| < length/2)", true, INERTA_REF(stitch.dropper_x)},
      {"stitch.droppers.presag", T::Numbers, "m", -kInf, kInf, false, false, "0", "contact-wire pre-sag at each stitch dropper", true, INERTA_REF(stitch.dropper_presag)},
      {"stitch.droppers.EA", T::Number, "N", 0, 1e9, true, true, "", "stitch dropper axial stiffness", true, INERTA_REF(stitch.dropper_EA), "real droppers: 1e5–3e5 N; beyond 1e9 N only the matrices' conditioning changes"},
      {"stitch.droppers.mass_per_length", T::Number, "kg/m", 0, kInf, false, false, "0", "stitch dropper mass per length", true, INERTA_REF(stitch.dropper_mass_per_length)},
      {"stitch.droppers.clamp_mass_stitch", T::Number, "kg", 0, kInf, false, false, "0", "clamp mass at each stitch dropper's upper end", true, INERTA_REF(stitch.clamp_mass_stitch)},
      {"stitch.droppers.clamp_mass_contact", T::Number, "kg", 0, kInf, false, false, "0", "clamp mass at each stitch dropper's contact-wire end", true, INERTA_REF(stitch.clamp_mass_contact)},
      {"irregularity.dropper_length_std", T::Number, "m", 0, 0.1, false, false, "0", "random dropper-length errors (normal, truncated at ±4 std)", false, INERTA_REF(irregularity.dropper_length_std), "dropper-length errors are millimetres"},
      {"irregularity.seed", T::Whole, "", 0, 9007199254740991.0, false, false, "1", "seed of the random errors", false, INERTA_REF(irregularity.seed), "a whole number from 0 to 2^53 − 1 = 9007199254740991 (exact as a number)"},
      {"irregularity.dropper_length_errors", T::Numbers, "m", -kInf, kInf, false, false, "none", "explicit length errors, one per dropper of the line in line order", false, INERTA_REF(irregularity.dropper_length_errors)},
      {"irregularity.height_errors", T::Csv, "m", -kInf, kInf, false, false, "none", "CSV of x and dz (m): contact-wire height errors along the line", false,
       [](FeCatenaryData& d) -> FeRef { return FeCsvRef{&d.irregularity.height_errors_file, &d.irregularity.height_error_x, &d.irregularity.height_error_dz, "dz"}; }},
      {"irregularity.point_masses", T::PointMasses, "", -kInf, kInf, false, false, "none", "[{x: m, mass: kg}, …]: hard spots on the contact wire", false, INERTA_REF(irregularity.point_masses)},
      {"irregularity.exact_dropper_dynamics", T::Bool, "", -kInf, kInf, false, false, "false", "the dynamics with each dropper's own stiffness", false, INERTA_REF(irregularity.exact_dropper_dynamics)},
      {"wear.uniform", T::Number, "%", 0, 100, true, false, "100", "contact-wire cross-section remaining over the whole line", true, INERTA_REF(wear.uniform)},
      {"wear.profile", T::Csv, "%", -kInf, kInf, false, false, "none", "CSV of x (m) and percent: cross-section remaining along the line", false,
       [](FeCatenaryData& d) -> FeRef { return FeCsvRef{&d.wear.file, &d.wear.x, &d.wear.percent, "percent"}; }},
  };
  return keys;
}
#undef INERTA_REF

const FeKey* find_fe_key(const std::string& path) {
  for (const FeKey& k : fe_keys())
    if (k.path == path) return &k;
  return nullptr;
}

const std::vector<FeSection>& fe_sections() {
  static const std::vector<FeSection> s{
      {"line", true, "the spans and the encumbrance"},
      {"messenger", true, "the messenger wire"},
      {"contact_wire", true, "the contact wire"},
      {"droppers", true, "the droppers of a span"},
      {"supports", true, "the messenger supports at the masts"},
      {"registration", true, "the contact-wire registrations at the masts"},
      {"mesh", false, "the finite elements"},
      {"damping", false, "Rayleigh damping"},
      {"integration", false, "HHT-α time stepping"},
      {"solver", false, "modal or direct (solver: modal, or a section)"},
      {"section", false, "the analysis section"},
      {"stitch", false, "a stitch wire at every interior mast", [](FeCatenaryData& d) { return &d.stitch.present; }},
      {"irregularity", false, "dropper-length errors, height errors, point masses"},
      {"wear", false, "contact-wire wear"},
  };
  return s;
}

void check_fe_ranges(const FeCatenaryData& d) {
  for (const FeKey& k : fe_keys()) {
    if (k.path.rfind("stitch.", 0) == 0 && !d.stitch.present) continue;
    const FeRef r = k.ref(const_cast<FeCatenaryData&>(d));  // read only
    double v = 0;
    if (auto p = std::get_if<double*>(&r)) v = **p;
    else if (auto q = std::get_if<int*>(&r)) v = **q;
    else if (auto s = std::get_if<std::uint64_t*>(&r)) v = static_cast<double>(**s);
    else continue;
    if (k.default_text == "none" && std::isnan(v)) continue;
    if (const std::string e = k.check(v); !e.empty()) throw FeKeyError({-1, k.path, -1}, k.note.empty() ? e : e + "; " + k.note);
  }
}

}  // namespace inerta::catenary
