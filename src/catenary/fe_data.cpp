// FeCatenaryData checks (catenary/fe_catenary.hpp); file readers turn them into file:line errors.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/catenary/fe_data.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/random.hpp"

namespace inerta::catenary {

double FeWire::wave_speed() const { return std::sqrt(tension / mass_per_length); }

namespace {
void positive(const char* what, const char* key, double v, const char* unit) {
  if (!(v > 0) || !std::isfinite(v))
    throw InvalidArgument(fmt::format("finite-element catenary: {}", what), key,
                          fmt::format("must be > 0 ({}), got {}", unit, v));
}
void non_negative(const char* what, const char* key, double v, const char* unit) {
  if (!(v >= 0) || !std::isfinite(v))
    throw InvalidArgument(fmt::format("finite-element catenary: {}", what), key,
                          fmt::format("must be >= 0 ({}), got {}", unit, v));
}
// Ranges far beyond any line (tensions 10–40 kN, 0.5–2 kg/m, waves 100–600 m/s; issue 52: 1e300 N gave
// a 150-digit wave speed and singular matrices), so that a typo is an error, not a run.
void wire(const char* which, const FeWire& w) {
  positive(which, "tension", w.tension, "N");
  positive(which, "mass_per_length", w.mass_per_length, "kg/m");
  non_negative(which, "EI", w.EI, "N·m²");
  if (w.tension > 1e7)
    throw InvalidArgument(fmt::format("finite-element catenary: {}", which), "tension",
                          fmt::format("{:g} N is above the 1e7 N (10 MN) accepted; real lines run at 10–40 kN", w.tension));
  if (w.wave_speed() > 1e4)
    throw InvalidArgument(fmt::format("finite-element catenary: {}", which), "mass_per_length",
                          fmt::format("the wave speed sqrt(tension / mass_per_length) = {:.4g} m/s is above 10 000 m/s (real "
                                      "wires: 100–600 m/s); check tension ({:g} N) and mass_per_length ({:g} kg/m)",
                                      w.wave_speed(), w.tension, w.mass_per_length));
}
}  // namespace

std::vector<double> dropper_length_errors(const FeIrregularity& irr, std::size_t count) {
  std::vector<double> e(count, 0.0);
  if (!(irr.dropper_length_std > 0)) return e;
  numerics::Xoshiro256 rng(irr.seed);
  for (double& v : e) v = irr.dropper_length_std * rng.truncated_normal(4.0);
  return e;
}

int FeCatenaryData::line_spans() const {
  if (!sectioned()) return spans;
  int n = 0;
  for (const FeCatenaryData& s : tension_sections) n += s.spans;
  return n - overlap_spans * static_cast<int>(tension_sections.size() - 1);
}

double FeCatenaryData::height_at(double x) const {
  if (height_x.size() >= 2) {
    const auto it = std::upper_bound(height_x.begin() + 1, height_x.end() - 1, x);
    const std::size_t i = static_cast<std::size_t>(it - height_x.begin());
    const double t = (x - height_x[i - 1]) / (height_x[i] - height_x[i - 1]);
    return height_z[i - 1] * (1 - t) + height_z[i] * t;
  }
  if (mast_height.empty()) return 0;
  const int i = std::clamp(static_cast<int>(std::floor(x / span)), 0, spans - 1);
  const double t = (x - i * span) / span;
  return mast_height[static_cast<std::size_t>(i)] * (1 - t) + mast_height[static_cast<std::size_t>(i) + 1] * t;
}

void FeCatenaryData::validate() const {
  if (sectioned()) {
    for (std::size_t k = 0; k < tension_sections.size(); ++k) {
      try {
        tension_sections[k].validate();
      } catch (const InvalidArgument& e) {  // key [k].<its section>.<its key>, e.g. [1].anchors.stiffness
        const std::string what = e.what(), prefix = "finite-element catenary: ";
        std::string inner;
        if (what.rfind(prefix, 0) == 0) inner = what.substr(prefix.size(), what.find(": ", prefix.size()) - prefix.size());
        throw InvalidArgument("finite-element catenary: tension_sections",
                              fmt::format("[{}].{}{}", k, inner.empty() ? "" : inner + ".", e.parameter()),
                              fmt::format("section {}: {}", k + 1, e.problem()));
      }
      if (tension_sections[k].spans + tension_sections[k].first_span > spans || tension_sections[k].line_start < 0)
        throw InvalidArgument("finite-element catenary: tension_sections", fmt::format("[{}]", k),
                              "the sections are not linked into a line (FeCatenaryData::link_sections)");
    }
    if (irregularity.any())
      throw InvalidArgument("finite-element catenary: irregularity", "irregularity",
                            "irregularities on a line of tension sections are not modelled yet; give them on a "
                            "single-section line");
  }
  if (!height_x.empty()) {
    const double len = spans * span;
    if (height_z.size() != height_x.size() || height_x.size() < 2 || std::abs(height_x.front()) > 1e-9 ||
        std::abs(height_x.back() - len) > 1e-6 * len)
      throw InvalidArgument("finite-element catenary: line", "height_x",
                            fmt::format("needs as many heights (height_z: {}) as points, at least two, from 0 to the "
                                        "section's length {:g} m (got {} points)",
                                        height_z.size(), len, height_x.size()));
    for (std::size_t i = 0; i < height_x.size(); ++i) {
      if (!std::isfinite(height_x[i]) || (i > 0 && !(height_x[i] > height_x[i - 1])))
        throw InvalidArgument("finite-element catenary: line", fmt::format("height_x[{}]", i),
                              fmt::format("must be finite and strictly increasing, got {} m", height_x[i]));
      if (!std::isfinite(height_z[i]) || std::abs(height_z[i]) >= encumbrance)
        throw InvalidArgument("finite-element catenary: line", fmt::format("height_z[{}]", i),
                              fmt::format("must be finite and smaller than the encumbrance, got {} m", height_z[i]));
    }
  }
  if (!mast_height.empty()) {
    if (mast_height.size() != static_cast<std::size_t>(spans) + 1)
      throw InvalidArgument("finite-element catenary: line", "mast_height",
                            fmt::format("needs spans + 1 = {} heights, got {}", spans + 1, mast_height.size()));
    for (double h : mast_height)
      if (!std::isfinite(h) || std::abs(h) >= encumbrance)
        throw InvalidArgument("finite-element catenary: line", "mast_height",
                              fmt::format("must be finite and smaller than the encumbrance, got {} m", h));
  }
  if (!anchor.pinned) {
    positive("anchors", "stiffness", anchor.stiffness, "N/m");
    non_negative("anchors", "mass", anchor.mass, "kg");
    if (anchor.stiffness > 1e12)  // beyond it the stiffness only spoils K's conditioning
      throw InvalidArgument("finite-element catenary: anchors", "stiffness",
                            fmt::format("must be at most 1e12 (N/m), got {}; a stiffer anchor is a pinned one (anchors: pinned)", anchor.stiffness));
    if (anchor.mass > 1e5)
      throw InvalidArgument("finite-element catenary: anchors", "mass", fmt::format("must be at most 1e5 (kg), got {}", anchor.mass));
  }
  positive("line", "span", span, "m");
  if (sectioned() && spans > 1000)  // no `line.spans` in such a file: its sections give the spans
    throw InvalidArgument("finite-element catenary", "tension_sections",
                          fmt::format("the sections make a line of {} spans (their spans less the overlaps'); at most 1000", spans));
  if (spans < 1 || spans > 1000)
    throw InvalidArgument("finite-element catenary: line", "spans", fmt::format("must be 1 … 1000, got {}", spans));
  positive("line", "encumbrance", encumbrance, "m");
  wire("messenger", messenger);
  wire("contact_wire", contact_wire);
  if (dropper_x.empty())
    throw InvalidArgument("finite-element catenary: droppers", "x", "at least one dropper a span is needed");
  for (std::size_t i = 0; i < dropper_x.size(); ++i) {
    const double x = dropper_x[i];
    if (!(x > 0 && x < span) || (i > 0 && !(x > dropper_x[i - 1])))
      throw InvalidArgument("finite-element catenary: droppers", fmt::format("x[{}]", i),
                            fmt::format("must increase strictly inside (0, span = {} m), got {} m", span, x));
  }
  if (presag.size() != dropper_x.size())
    throw InvalidArgument("finite-element catenary: droppers", "presag",
                          fmt::format("needs one value per dropper ({}), got {}", dropper_x.size(), presag.size()));
  for (std::size_t i = 0; i < presag.size(); ++i)
    if (!std::isfinite(presag[i]) || std::abs(presag[i]) >= encumbrance)
      throw InvalidArgument("finite-element catenary: droppers", fmt::format("presag[{}]", i),
                            fmt::format("must be finite and smaller than the encumbrance ({} m), got {} m",
                                        encumbrance, presag[i]));
  if (!nominal_dropper_length.empty() && nominal_dropper_length.size() != dropper_x.size())
    throw InvalidArgument("finite-element catenary: droppers", "nominal_length",
                          fmt::format("needs one value per dropper ({}), got {}", dropper_x.size(),
                                      nominal_dropper_length.size()));
  for (std::size_t i = 0; i < nominal_dropper_length.size(); ++i)  // issue 38: .nan was accepted
    if (!(std::isfinite(nominal_dropper_length[i]) && nominal_dropper_length[i] > 0))
      throw InvalidArgument("finite-element catenary: droppers", fmt::format("nominal_length[{}]", i),
                            fmt::format("must be a finite length > 0 (m), got {}", nominal_dropper_length[i]));
  positive("droppers", "EA", dropper_EA, "N");
  non_negative("droppers", "mass_per_length", dropper_mass_per_length, "kg/m");
  non_negative("droppers", "clamp_mass_messenger", clamp_mass_messenger, "kg");
  non_negative("droppers", "clamp_mass_contact", clamp_mass_contact, "kg");
  positive("supports", "stiffness", support_stiffness, "N/m");
  non_negative("supports", "mass", support_mass, "kg");
  positive("registration", "stiffness", registration_stiffness, "N/m");
  non_negative("registration", "mass", registration_mass, "kg");
  if (!std::isnan(registration_uplift_limit) && !(registration_uplift_limit > 0 && registration_uplift_limit <= 10))
    throw InvalidArgument("finite-element catenary: registration", "uplift_limit",
                          fmt::format("expected > 0 and at most 10 m, got {} m", registration_uplift_limit));
  positive("mesh", "element_length", element_length, "m");
  if (element_length < 1e-3 || span / element_length > 1e5)
    throw InvalidArgument("finite-element catenary: mesh", "element_length",
                          fmt::format("must be between 1 mm and span/100000, got {} m", element_length));
  non_negative("damping", "mass", rayleigh_mass, "1/s");
  non_negative("damping", "stiffness", rayleigh_stiffness, "s");
  non_negative("line", "gravity", gravity, "m/s²");
  positive("integration", "time_step", time_step, "s");
  if (time_step < 1e-5)  // issue 38: 1e-7 s ended in the multibody integrator's "the model is stiff"
    throw InvalidArgument("finite-element catenary: integration", "time_step",
                          fmt::format("must be >= 1e-5 s (each pantograph is stepped with the line: a smaller step "
                                      "holds its integrator below its own limit; 1e-3 s is the bundled value, and "
                                      "halving it changes sigma by < 0.1 %), got {} s",
                                      time_step));
  if (time_step > 0.01)
    throw InvalidArgument("finite-element catenary: integration", "time_step",
                          fmt::format("must be <= 0.01 s (a wire carries waves of tens of hertz), got {} s", time_step));
  if (!(hht_alpha >= -1.0 / 3.0 && hht_alpha <= 0))
    throw InvalidArgument("finite-element catenary: integration", "alpha",
                          fmt::format("HHT-α needs −1/3 <= α <= 0, got {}", hht_alpha));
  positive("solver", "cutoff", modal_cutoff, "Hz");
  if (modal_cutoff > 2000)
    throw InvalidArgument("finite-element catenary: solver", "cutoff",
                          fmt::format("must be <= 2000 Hz (the modes are for the contact-force band), got {} Hz", modal_cutoff));
  if (window_behind < -1 || window_behind > 1000)
    throw InvalidArgument("finite-element catenary: solver", "window_behind",
                          fmt::format("must be a number of spans >= 0, or −1 for the whole line, got {}", window_behind));
  if (window_ahead < -1 || window_ahead > 1000)
    throw InvalidArgument("finite-element catenary: solver", "window_ahead",
                          fmt::format("must be a number of spans >= 0, or −1 for the whole line, got {}", window_ahead));
  if (stitch.present) {
    const FeStitch& st = stitch;
    positive("stitch", "length", st.length, "m");
    if (!(st.length < span))
      throw InvalidArgument("finite-element catenary: stitch", "length",
                            fmt::format("must be shorter than the span ({} m): the stitch wires of two masts would "
                                        "overlap, got {} m",
                                        span, st.length));
    wire("stitch", st.wire);
    non_negative("stitch", "clamp_mass", st.clamp_mass, "kg");
    positive("stitch", "droppers.EA", st.dropper_EA, "N");
    non_negative("stitch", "droppers.mass_per_length", st.dropper_mass_per_length, "kg/m");
    non_negative("stitch", "droppers.clamp_mass_stitch", st.clamp_mass_stitch, "kg");
    non_negative("stitch", "droppers.clamp_mass_contact", st.clamp_mass_contact, "kg");
    if (st.dropper_x.empty())
      throw InvalidArgument("finite-element catenary: stitch", "droppers.x",
                            "at least one stitch dropper is needed (signed positions from the mast, m)");
    for (std::size_t i = 0; i < st.dropper_x.size(); ++i) {
      const double x = st.dropper_x[i];
      if (!(std::abs(x) < 0.5 * st.length && x != 0) || (i > 0 && !(x > st.dropper_x[i - 1])))
        throw InvalidArgument("finite-element catenary: stitch", fmt::format("droppers.x[{}]", i),
                              fmt::format("must increase strictly, be non-zero and lie inside the stitch wire "
                                          "(|x| < length/2 = {} m from the mast), got {} m",
                                          0.5 * st.length, x));
    }
    if (!st.dropper_presag.empty() && st.dropper_presag.size() != st.dropper_x.size())
      throw InvalidArgument("finite-element catenary: stitch", "droppers.presag",
                            fmt::format("needs one value per stitch dropper ({}), got {}", st.dropper_x.size(),
                                        st.dropper_presag.size()));
    for (std::size_t i = 0; i < st.dropper_presag.size(); ++i)
      if (!std::isfinite(st.dropper_presag[i]) || std::abs(st.dropper_presag[i]) >= encumbrance)
        throw InvalidArgument("finite-element catenary: stitch", fmt::format("droppers.presag[{}]", i),
                              fmt::format("must be finite and smaller than the encumbrance ({} m), got {} m",
                                          encumbrance, st.dropper_presag[i]));
    for (std::size_t i = 0; i < dropper_x.size(); ++i)
      if (dropper_x[i] <= 0.5 * st.length || dropper_x[i] >= span - 0.5 * st.length)
        throw InvalidArgument("finite-element catenary: droppers", fmt::format("x[{}]", i),
                              fmt::format("{} m lies within the stitch wire (stitch.length/2 = {} m from a mast): "
                                          "droppers.x holds only the droppers outside the stitch; a dropper near the "
                                          "mast goes in stitch.droppers.x (signed, from the mast)",
                                          dropper_x[i], 0.5 * st.length));
  }
  {
    const FeIrregularity& irr = irregularity;
    non_negative("irregularity", "dropper_length_std", irr.dropper_length_std, "m");
    if (irr.dropper_length_std > 0.1)
      throw InvalidArgument("finite-element catenary: irregularity", "dropper_length_std",
                            fmt::format("must be <= 0.1 m (dropper-length errors are millimetres), got {} m",
                                        irr.dropper_length_std));
    const std::size_t count = static_cast<std::size_t>(spans) *
                              (dropper_x.size() + (stitch.present ? stitch.dropper_x.size() : 0));
    if (!irr.dropper_length_errors.empty() && irr.dropper_length_errors.size() != count)
      throw InvalidArgument("finite-element catenary: irregularity", "dropper_length_errors",
                            fmt::format("needs one value per dropper of the line in line order ({} = {} spans × {} "
                                        "droppers a span, stitch droppers included), got {}",
                                        count, spans, count / static_cast<std::size_t>(spans),
                                        irr.dropper_length_errors.size()));
    for (std::size_t i = 0; i < irr.dropper_length_errors.size(); ++i)
      if (!std::isfinite(irr.dropper_length_errors[i]) || std::abs(irr.dropper_length_errors[i]) > 0.5)
        throw InvalidArgument("finite-element catenary: irregularity", fmt::format("dropper_length_errors[{}]", i),
                              fmt::format("must be finite and at most 0.5 m in size, got {} m",
                                          irr.dropper_length_errors[i]));
    const std::vector<double>& hx = irr.height_error_x;
    if (hx.size() != irr.height_error_dz.size())
      throw InvalidArgument("finite-element catenary: irregularity", "height_errors",
                            "x and dz columns differ in length");
    if (!hx.empty()) {
      for (std::size_t i = 0; i < hx.size(); ++i) {
        if (!std::isfinite(hx[i]) || !std::isfinite(irr.height_error_dz[i]))
          throw InvalidArgument("finite-element catenary: irregularity", "height_errors",
                                fmt::format("{}: row {} is not a finite number", irr.height_errors_file, i + 1));
        if (i > 0 && !(hx[i] > hx[i - 1]))
          throw InvalidArgument("finite-element catenary: irregularity", "height_errors",
                                fmt::format("{}: x must increase strictly, got {} m after {} m (row {})",
                                            irr.height_errors_file, hx[i], hx[i - 1], i + 1));
        if (!(std::abs(irr.height_error_dz[i]) < encumbrance))
          throw InvalidArgument("finite-element catenary: irregularity", "height_errors",
                                fmt::format("{}: Δz = {} m at x = {} m is not smaller than the encumbrance",
                                            irr.height_errors_file, irr.height_error_dz[i], hx[i]));
      }
      if (hx.size() < 2 || hx.front() > 0 || hx.back() < span * spans)
        throw InvalidArgument("finite-element catenary: irregularity", "height_errors",
                              fmt::format("{}: the profile must cover the line [0, {} m] (at least two rows), it covers "
                                          "[{}, {}] m",
                                          irr.height_errors_file, span * spans, hx.front(), hx.back()));
    }
    for (std::size_t i = 0; i < irr.point_masses.size(); ++i) {
      const FeIrregularity::PointMass& pm = irr.point_masses[i];
      if (!(pm.x >= 0 && pm.x <= span * spans))
        throw InvalidArgument("finite-element catenary: irregularity", fmt::format("point_masses[{}]", i),
                              fmt::format("x = {} m is off the line [0, {} m]", pm.x, span * spans));
      if (!(pm.mass >= 0) || !std::isfinite(pm.mass))
        throw InvalidArgument("finite-element catenary: irregularity", fmt::format("point_masses[{}]", i),
                              fmt::format("mass must be >= 0 (kg), got {}", pm.mass));
    }
  }
  if (section_first != -1 || section_last != -1)
    if (section_first < 1 || section_last < section_first || section_last > spans)
      throw InvalidArgument("finite-element catenary: section", "spans",
                            fmt::format("must be [first, last] with 1 <= first <= last <= {}, got [{}, {}]", spans,
                                        section_first, section_last));
}

}  // namespace inerta::catenary
