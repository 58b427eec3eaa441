#pragma once
// The aerodynamic uplift that brings a pantograph's mean contact force to a target at one speed
// (`inerta pantograph aero-fit`, docs/contact-quality.md "Aerodynamic uplift").
#include <functional>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/pantograph/pantograph.hpp"

namespace inerta::analysis {

struct AeroFit {
  bool reached = false;  ///< a ≥ 0 brings the mean force to the target within the tolerance
  double a = 0;          ///< N·s²/m²: the uplift a v² (b = c = 0) on the contact point's body
  double mean = NAN;     ///< N: the mean contact force at the speed with that a
  double mean_without = NAN;  ///< N: with a = 0 (no aerodynamic uplift)
  double target = 0;     ///< N
  int runs = 0;          ///< speed runs made
};

/// The pantograph with the aerodynamic uplift a v² (b = c = 0) on the body of its contact marker,
/// replacing any it had. InvalidArgument for a < 0 or a contact marker on the ground.
pantograph::Pantograph with_aerodynamic(const pantograph::Pantograph& p, double a);

/// Finds a ≥ 0 for which the mean contact force of the leading pantograph at `speed` (m/s), of the
/// chosen statistics over the line's analysis section, equals `target` (N) within `tolerance` (N):
/// the mean force grows with a (by about a v²), so a secant iteration from a = 0 and
/// a = (target − F(0))/v² converges in a few runs. Not reached (reached = false, a = 0) if the mean
/// force without uplift is already above the target, or after `max_runs` runs.
AeroFit fit_aerodynamic(const pantograph::Pantograph& p, const catenary::Catenary& catenary,
                        const catenary::Contact& contact, double speed, double target, Statistics statistics,
                        const RunOptions& options = {}, double tolerance = 0.05, int max_runs = 10);

/// The same secant iteration on any mean force F(a) at speed v (m/s): e.g. the periodic fast path's.
AeroFit fit_aerodynamic(const std::function<double(double)>& mean_at, double speed, double target,
                        double tolerance = 0.05, int max_runs = 10);

}  // namespace inerta::analysis
