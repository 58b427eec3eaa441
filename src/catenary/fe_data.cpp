// FeCatenaryData checks (catenary/fe_catenary.hpp); file readers turn them into file:line errors.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/catenary/fe_data.hpp"
#include "inerta/catenary/fe_schema.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/random.hpp"

namespace inerta::catenary {

double FeWire::wave_speed() const { return std::sqrt(tension / mass_per_length); }

namespace {
[[noreturn]] void fail(const std::string& key, const std::string& problem, int index = -1) {
  throw FeKeyError({-1, key, index}, problem);
}
}  // namespace

double FeWear::at(double x) const {
  if (this->x.empty()) return uniform;
  if (x <= this->x.front()) return percent.front();
  if (x >= this->x.back()) return percent.back();
  const auto it = std::upper_bound(this->x.begin(), this->x.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - this->x.begin());
  const double t = (x - this->x[i - 1]) / (this->x[i] - this->x[i - 1]);
  return percent[i - 1] + t * (percent[i] - percent[i - 1]);
}

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

// Each key's range from the schema (check_fe_ranges); here what relates keys to each other.
void FeCatenaryData::validate() const {
  if (sectioned()) {
    const std::vector<FeLinkedSection> linked = link_sections(*this);
    for (std::size_t k = 0; k < linked.size(); ++k) {
      try {
        linked[k].line.validate();
      } catch (const FeKeyError& e) {  // at the section's own key (tension_sections[k].<key>)
        throw FeKeyError({static_cast<int>(k), e.at.key, e.at.index}, fmt::format("section {}: {}", k + 1, e.problem()));
      }
    }
    if (spans != line_spans())
      fail("line.spans", fmt::format("a line of tension sections has its sections' spans ({}), got {}: join_sections sets them",
                                     line_spans(), spans));
    if (irregularity.any())
      fail("irregularity", "irregularities on a line of tension sections are not modelled yet; give them on a single-section line");
    if (!wear.x.empty())
      fail("wear.profile", "a wear profile on a line of tension sections is not modelled yet; give wear.uniform, or the profile on a single-section line");
    if (spans > 1000)  // no `line.spans` in such a file: its sections give the spans
      fail("tension_sections", fmt::format("the sections make a line of {} spans (their spans less the overlaps'); at most 1000", spans));
  }
  if (!height_x.empty()) {
    const double len = spans * span;
    if (height_z.size() != height_x.size() || height_x.size() < 2 || std::abs(height_x.front()) > 1e-9 ||
        std::abs(height_x.back() - len) > 1e-6 * len)
      fail("line.height_x", fmt::format("needs as many heights (height_z: {}) as points, at least two, from 0 to the "
                                        "section's length {:g} m (got {} points)",
                                        height_z.size(), len, height_x.size()));
    for (std::size_t i = 0; i < height_x.size(); ++i) {
      if (!std::isfinite(height_x[i]) || (i > 0 && !(height_x[i] > height_x[i - 1])))
        fail("line.height_x", fmt::format("must be finite and strictly increasing, got {} m", height_x[i]), static_cast<int>(i));
      if (!std::isfinite(height_z[i]) || std::abs(height_z[i]) >= encumbrance)
        fail("line.height_z", fmt::format("must be finite and smaller than the encumbrance, got {} m", height_z[i]), static_cast<int>(i));
    }
  }
  if (!mast_height.empty()) {
    if (mast_height.size() != static_cast<std::size_t>(spans) + 1)
      fail("line.mast_height", fmt::format("needs spans + 1 = {} heights, got {}", spans + 1, mast_height.size()));
    for (double h : mast_height)
      if (!std::isfinite(h) || std::abs(h) >= encumbrance)
        fail("line.mast_height", fmt::format("must be finite and smaller than the encumbrance, got {} m", h));
  }
  if (!anchor.pinned) {
    if (!(anchor.stiffness > 0 && anchor.stiffness <= 1e12))  // beyond it the stiffness only spoils K's conditioning
      fail("anchors.stiffness", fmt::format("must be > 0 and at most 1e12 (N/m), got {}; a stiffer anchor is a pinned one (anchors: pinned)", anchor.stiffness));
    if (!(anchor.mass >= 0 && anchor.mass <= 1e5))
      fail("anchors.mass", fmt::format("must be >= 0 and at most 1e5 (kg), got {}", anchor.mass));
  }
  check_fe_ranges(*this);
  if (span / element_length > 1e5)
    fail("mesh.element_length", fmt::format("must be between 1 mm and span/100000, got {} m", element_length));
  for (const auto& [which, w] : {std::pair{"messenger", &messenger}, std::pair{"contact_wire", &contact_wire},
                                 std::pair{"stitch", stitch.present ? &stitch.wire : nullptr}})
    if (w && w->wave_speed() > 1e4)  // issue 52: 1e300 N gave a 150-digit wave speed and singular matrices
      fail(std::string(which) + ".mass_per_length",
           fmt::format("the wave speed sqrt(tension / mass_per_length) = {:.4g} m/s is above 10 000 m/s (real "
                       "wires: 100–600 m/s); check tension ({:g} N) and mass_per_length ({:g} kg/m)",
                       w->wave_speed(), w->tension, w->mass_per_length));
  if (dropper_x.empty()) fail("droppers.x", "at least one dropper a span is needed");
  for (std::size_t i = 0; i < dropper_x.size(); ++i) {
    const double x = dropper_x[i];
    if (!(x > 0 && x < span) || (i > 0 && !(x > dropper_x[i - 1])))
      fail("droppers.x", fmt::format("must increase strictly inside (0, span = {} m), got {} m", span, x), static_cast<int>(i));
  }
  if (presag.size() != dropper_x.size())
    fail("droppers.presag", fmt::format("needs one value per dropper ({}), got {}", dropper_x.size(), presag.size()));
  for (std::size_t i = 0; i < presag.size(); ++i)
    if (!std::isfinite(presag[i]) || std::abs(presag[i]) >= encumbrance)
      fail("droppers.presag", fmt::format("must be finite and smaller than the encumbrance ({} m), got {} m", encumbrance, presag[i]),
           static_cast<int>(i));
  if (!nominal_dropper_length.empty() && nominal_dropper_length.size() != dropper_x.size())
    fail("droppers.nominal_length",
         fmt::format("needs one value per dropper ({}), got {}", dropper_x.size(), nominal_dropper_length.size()));
  for (std::size_t i = 0; i < nominal_dropper_length.size(); ++i)  // issue 38: .nan was accepted
    if (!(std::isfinite(nominal_dropper_length[i]) && nominal_dropper_length[i] > 0))
      fail("droppers.nominal_length", fmt::format("must be a finite length > 0 (m), got {}", nominal_dropper_length[i]),
           static_cast<int>(i));
  if (stitch.present) {
    const FeStitch& st = stitch;
    if (!(st.length < span))
      fail("stitch.length", fmt::format("must be shorter than the span ({} m): the stitch wires of two masts would overlap, got {} m",
                                        span, st.length));
    if (st.dropper_x.empty()) fail("stitch.droppers.x", "at least one stitch dropper is needed (signed positions from the mast, m)");
    for (std::size_t i = 0; i < st.dropper_x.size(); ++i) {
      const double x = st.dropper_x[i];
      if (!(std::abs(x) < 0.5 * st.length && x != 0) || (i > 0 && !(x > st.dropper_x[i - 1])))
        fail("stitch.droppers.x",
             fmt::format("must increase strictly, be non-zero and lie inside the stitch wire (|x| < length/2 = {} m from "
                         "the mast), got {} m",
                         0.5 * st.length, x),
             static_cast<int>(i));
    }
    if (!st.dropper_presag.empty() && st.dropper_presag.size() != st.dropper_x.size())
      fail("stitch.droppers.presag",
           fmt::format("needs one value per stitch dropper ({}), got {}", st.dropper_x.size(), st.dropper_presag.size()));
    for (std::size_t i = 0; i < st.dropper_presag.size(); ++i)
      if (!std::isfinite(st.dropper_presag[i]) || std::abs(st.dropper_presag[i]) >= encumbrance)
        fail("stitch.droppers.presag",
             fmt::format("must be finite and smaller than the encumbrance ({} m), got {} m", encumbrance, st.dropper_presag[i]),
             static_cast<int>(i));
    for (std::size_t i = 0; i < dropper_x.size(); ++i)
      if (dropper_x[i] <= 0.5 * st.length || dropper_x[i] >= span - 0.5 * st.length)
        fail("droppers.x",
             fmt::format("{} m lies within the stitch wire (stitch.length/2 = {} m from a mast): droppers.x holds only the "
                         "droppers outside the stitch; a dropper near the mast goes in stitch.droppers.x (signed, from the mast)",
                         dropper_x[i], 0.5 * st.length),
             static_cast<int>(i));
  }
  {
    const FeIrregularity& irr = irregularity;
    const std::size_t count = static_cast<std::size_t>(spans) * (dropper_x.size() + (stitch.present ? stitch.dropper_x.size() : 0));
    if (!irr.dropper_length_errors.empty() && irr.dropper_length_errors.size() != count)
      fail("irregularity.dropper_length_errors",
           fmt::format("needs one value per dropper of the line in line order ({} = {} spans × {} droppers a span, stitch "
                       "droppers included), got {}",
                       count, spans, count / static_cast<std::size_t>(spans), irr.dropper_length_errors.size()));
    for (std::size_t i = 0; i < irr.dropper_length_errors.size(); ++i)
      if (!std::isfinite(irr.dropper_length_errors[i]) || std::abs(irr.dropper_length_errors[i]) > 0.5)
        fail("irregularity.dropper_length_errors",
             fmt::format("must be finite and at most 0.5 m in size, got {} m", irr.dropper_length_errors[i]), static_cast<int>(i));
    const std::vector<double>& hx = irr.height_error_x;
    if (hx.size() != irr.height_error_dz.size()) fail("irregularity.height_errors", "x and dz columns differ in length");
    if (!hx.empty()) {
      for (std::size_t i = 0; i < hx.size(); ++i) {
        if (!std::isfinite(hx[i]) || !std::isfinite(irr.height_error_dz[i]))
          fail("irregularity.height_errors", fmt::format("{}: row {} is not a finite number", irr.height_errors_file, i + 1));
        if (i > 0 && !(hx[i] > hx[i - 1]))
          fail("irregularity.height_errors", fmt::format("{}: x must increase strictly, got {} m after {} m (row {})",
                                                         irr.height_errors_file, hx[i], hx[i - 1], i + 1));
        if (!(std::abs(irr.height_error_dz[i]) < encumbrance))
          fail("irregularity.height_errors", fmt::format("{}: Δz = {} m at x = {} m is not smaller than the encumbrance",
                                                         irr.height_errors_file, irr.height_error_dz[i], hx[i]));
      }
      if (hx.size() < 2 || hx.front() > 0 || hx.back() < span * spans)
        fail("irregularity.height_errors",
             fmt::format("{}: the profile must cover the line [0, {} m] (at least two rows), it covers [{}, {}] m",
                         irr.height_errors_file, span * spans, hx.front(), hx.back()));
    }
    for (std::size_t i = 0; i < irr.point_masses.size(); ++i) {
      const FeIrregularity::PointMass& pm = irr.point_masses[i];
      if (!(pm.x >= 0 && pm.x <= span * spans))
        fail("irregularity.point_masses", fmt::format("x = {} m is off the line [0, {} m]", pm.x, span * spans), static_cast<int>(i));
      if (!(pm.mass >= 0) || !std::isfinite(pm.mass))
        fail("irregularity.point_masses", fmt::format("mass must be >= 0 (kg), got {}", pm.mass), static_cast<int>(i));
    }
  }
  if (!wear.x.empty()) {  // a profile (wear.uniform: the schema's range)
    if (wear.x.size() < 2 || wear.percent.size() != wear.x.size())
      fail("wear.profile", fmt::format("{}: expected x (m) and percent at 2 or more points, got {}", wear.file, wear.x.size()));
    for (std::size_t i = 0; i < wear.x.size(); ++i) {
      if (!std::isfinite(wear.x[i]) || (i > 0 && !(wear.x[i] > wear.x[i - 1])))
        fail("wear.profile", fmt::format("{}: x must be finite and increase strictly, got {} m (row {})", wear.file, wear.x[i], i + 1));
      if (!(wear.percent[i] > 0 && wear.percent[i] <= 100))
        fail("wear.profile", fmt::format("{}: percent must be > 0 and at most 100, got {} at x = {} m (row {})", wear.file,
                                         wear.percent[i], wear.x[i], i + 1));
    }
  }
  if (section_first != -1 || section_last != -1)
    if (section_first < 1 || section_last < section_first || section_last > spans)
      fail("section.spans", fmt::format("must be [first, last] with 1 <= first <= last <= {}, got [{}, {}]", spans,
                                        section_first, section_last));
}

}  // namespace inerta::catenary
