#include "inerta/analysis/aero_fit.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"

namespace inerta::analysis {

pantograph::Pantograph with_aerodynamic(const pantograph::Pantograph& p, double a) {
  if (!(a >= 0) || !std::isfinite(a)) throw InvalidArgument(fmt::format("aerodynamic uplift: a = {}: expected a finite a >= 0", a));
  pantograph::Pantograph q = p;
  q.aero = {};
  q.aero.body = q.contact().body;
  if (q.aero.body < 0) throw InvalidArgument("aerodynamic uplift: the contact marker is on the ground; it needs a body");
  q.aero.a = a;
  return q;
}

AeroFit fit_aerodynamic(const pantograph::Pantograph& p, const catenary::Catenary& cat, const catenary::Contact& contact,
                        double v, double target, Statistics statistics, const RunOptions& o, double tol, int max_runs) {
  auto mean_at = [&](double a) {
    const SpeedResult r = sweep(with_aerodynamic(p, a), cat, contact, {v}, o).front();
    if (statistics == Statistics::Filtered && !r.filtered.empty()) return r.filtered.front().mean;
    return r.stats.mean;
  };
  return fit_aerodynamic(mean_at, v, target, tol, max_runs);
}

AeroFit fit_aerodynamic(const std::function<double(double)>& mean_of, double v, double target, double tol, int max_runs) {
  if (!(v > 0) || !std::isfinite(v)) throw InvalidArgument(fmt::format("aero-fit: speed {} m/s: expected > 0", v));
  if (!std::isfinite(target)) throw InvalidArgument(fmt::format("aero-fit: target {} N: expected a finite force", target));
  AeroFit fit;
  fit.target = target;
  auto mean_at = [&](double a) {
    ++fit.runs;
    const double m = mean_of(a);
    if (!std::isfinite(m))  // e.g. no stable periodic solution: no mean force to fit
      throw NumericalError(fmt::format("aero-fit: the mean contact force at {:.4g} km/h with a = {:.6g} N·s²/m² is {} "
                                       "(no steady state)", v * 3.6, a, m));
    return m;
  };
  double a0 = 0, f0 = mean_at(0);
  fit.mean_without = f0;
  if (f0 > target + tol) return fit;  // uplift only adds force
  if (std::abs(f0 - target) <= tol) return fit.reached = true, fit.mean = f0, fit;
  double a1 = (target - f0) / (v * v), f1 = mean_at(a1);
  while (std::abs(f1 - target) > tol && fit.runs < max_runs) {
    if (f1 == f0) break;
    const double a2 = std::max(0.0, a1 + (target - f1) * (a1 - a0) / (f1 - f0));  // secant
    if (!std::isfinite(a2)) break;
    a0 = a1, f0 = f1, a1 = a2, f1 = mean_at(a1);
  }
  fit.a = a1, fit.mean = f1;
  fit.reached = std::abs(f1 - target) <= tol;
  return fit;
}

}  // namespace inerta::analysis
