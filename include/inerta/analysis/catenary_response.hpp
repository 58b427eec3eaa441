#pragma once
// The lumped catenary alone under a constant upward force (spec/06 §6.3, thesis Fig. 7.7): the
// steady-state acceleration amplitude of the contact point against the pumping frequency f_p = v/L.
#include <vector>

#include "inerta/error.hpp"

#include "inerta/catenary/lumped.hpp"

namespace inerta::analysis {

struct CatenaryResponse {
  double fp = 0, speed = 0;   ///< Hz, m/s
  double acc_amplitude = 0;   ///< (max − min)/2 of ÿ over the analysed periods, m/s²
  double disp_amplitude = 0;  ///< (max − min)/2 of the uplift, m
  double mean_uplift = 0;     ///< m
  double growth = 1;          ///< displacement amplitude, 2nd half / 1st half of the analysed periods
  bool stable() const { return growth < 1.02; }  ///< false: parametric resonance (Mathieu instability)
};

/// The rules of the arguments (the CLI's `catenary-response --force`; Python's catenary_response).
inline constexpr NumberRule force_rule{-1e9, 1e9, "a force in N"};
inline constexpr NumberRule settle_rule{0, 1e7, ">= 0 s"};
inline constexpr CountRule periods_rule{1, 100000};

/// For each f_p: from the static uplift F/k_c(0) at t = 0, simulate until the transient has decayed
/// (at least `settle` seconds) and analyse the next `periods` pumping periods (in parallel).
/// InvalidArgument "force: …", "settle: …", "periods: …" for an argument that breaks its rule.
std::vector<CatenaryResponse> catenary_response(const catenary::LumpedCatenary& cat, double force,
                                                const std::vector<double>& fp, double settle = 60.0, int periods = 10);

}  // namespace inerta::analysis
