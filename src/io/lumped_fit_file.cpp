#include "inerta/io/lumped_fit_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/io/files.hpp"

namespace inerta::io {

namespace {
std::string list(const std::array<double, 4>& a) { return fmt::format("[{:.6g}, {:.6g}, {:.6g}, {:.6g}]", a[0], a[1], a[2], a[3]); }
}  // namespace

void write_lumped_catenary(const std::string& path, const catenary::LumpedFit& fit, const catenary::Contact& contact,
                           const std::string& source) {
  const catenary::LumpedCatenary& c = fit.lumped;
  std::ostringstream f;
  f << fmt::format(
      "# Lumped catenary (spec/05 §5.1, eq. 7.1) fitted to the finite-element catenary {} by `inerta catenary fit`\n"
      "# (catenary/fe_catenary.hpp, fit_lumped): span {} of the line; k_c(x) = 1/e(x) from its static point elasticity,\n"
      "# m_c(x) the mass of the static deflection shape, c_c(x) its Rayleigh damping, each expanded in cos(2π i x/L).\n"
      "# Fit of the elasticity along the span: max {:.1f} % (rms {:.1f} %); averaged over one dropper spacing max {:.1f} %\n"
      "# (rms {:.1f} %) — three harmonics follow the span-scale variation, not the dropper-scale one.\n"
      "# Natural frequency (1/2π) sqrt(k_c0/m_c0) = {:.3f} Hz.\n",
      source, fit.span, 100 * fit.max_elasticity_error, 100 * fit.rms_error, 100 * fit.max_smoothed_error,
      100 * fit.rms_smoothed_error, c.natural_frequency());
  f << fmt::format("name: lumped fit of {}\ntype: lumped\ncatenary:\n  span: {:.6g}\n", source, c.span);
  f << "  kc: " << list(c.k) << "   # N/m: k_c0 .. k_c3\n";
  f << "  mc: " << list(c.m) << "   # kg\n";
  f << "  cc: " << list(c.c) << "   # N·s/m\n";
  f << fmt::format("contact:               # as in the finite-element file\n  type: {}\n  stiffness: {:.6g}\n  damping: {:.6g}\n",
                   catenary::kind_name(contact.kind), contact.stiffness, contact.damping);
  write_text_file(path, f.str());
}

void write_fit_table(const std::string& path, const catenary::LumpedFit& fit) {
  std::ostringstream f;
  f << "x,elasticity_fe,elasticity_fit,mass,damping\n";
  for (std::size_t i = 0; i < fit.x.size(); ++i)
    f << fmt::format("{:.6g},{:.8g},{:.8g},{:.6g},{:.6g}\n", fit.x[i], fit.elasticity[i], fit.fitted_elasticity[i],
                     fit.mass[i], fit.damping[i]);
  write_text_file(path, f.str());
}

}  // namespace inerta::io
