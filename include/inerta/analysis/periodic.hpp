#pragma once
// Fast periodic steady state (issue 5): harmonic balance (Hill's method) on the pantograph
// linearised about its static equilibrium under the mean catenary, coupled with the linear
// time-periodic catenary. With the wire uplift y = y_s + δy (y_s: static uplift), the harmonics
// Δk(t) = Σ k_i cos(iΩt), Δc(t) = Σ c_i cos(iΩt) (Ω = 2π v/L) act on the wire as the force
//   f(t) = −Δk(t) (y_s + δy) − Δc(t) δẏ,
// so the periodic response X(t) = Σ_{|h|≤H} X_h e^{ihΩt} of Ẋ = A X + B f(t) solves one complex
// linear system per speed; the contact force F = F_s + Λ X + Λ_f f follows harmonic by harmonic.
#include <vector>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"

namespace inerta::analysis {

/// Largest number of harmonics H accepted (InvalidArgument above, or below 1).
inline constexpr int max_harmonics = 256;
/// The rule of H (the CLI's --harmonics, Python's harmonics): "harmonics: 0 is out of range; expected 1 … 256".
inline constexpr CountRule harmonics_rule{1, max_harmonics};

/// Contact statistics of the periodic steady state at each speed (m/s), H harmonics of the pumping
/// frequency. The catenary must have a point model (Catenary::point_model: the lumped catenary),
/// without mass harmonics m_c1..m_c3 (ModelError otherwise). The linearisation is done once; speeds
/// are independent solves. A pantograph with an aerodynamic uplift (Pantograph::aero) is
/// linearised at each speed with that speed's uplift (pantograph::at_speed). Each speed's periodic
/// solution is checked for stability (Floquet multipliers, SpeedResult::floquet); an unstable one has
/// NaN statistics.
std::vector<SpeedResult> sweep_periodic(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                                        const catenary::Contact& contact, const std::vector<double>& speeds,
                                        int harmonics = 8);

}  // namespace inerta::analysis
