#pragma once
// `inerta catenary fit`: the lumped catenary of eq. 7.1 fitted to a finite-element catenary
// (catenary::fit_lumped), written as a lumped catenary file, and the fit along the span as a CSV.
#include <string>

#include "inerta/catenary/contact.hpp"
#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::io {

/// A lumped catenary file (docs/model-format.md#catenary-files) holding fit.lumped and `contact`, with
/// a header saying where it came from (`source`) and how well it fits.
void write_lumped_catenary(const std::string& path, const catenary::LumpedFit& fit, const catenary::Contact& contact,
                           const std::string& source);
/// x, the FE elasticity, the fitted one, the equivalent mass and damping along the fitted span.
void write_fit_table(const std::string& path, const catenary::LumpedFit& fit);

}  // namespace inerta::io
