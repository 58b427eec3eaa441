// Commissioning a pantograph design (analysis/commission.hpp, issue 49).
#include "inerta/analysis/commission.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/analysis/aero_fit.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/network/realisation.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::analysis {

namespace {
// The height (y) of the pantograph's contact marker in state x of `model`.
double contact_height(const pantograph::Pantograph& p, const mbs::Model& model, const mbs::State& x) {
  const mbs::Marker& m = model.markers[static_cast<std::size_t>(p.contact_marker)];
  if (m.body < 0) return m.u.y();
  const mbs::Vec3 q = model.q_of(x, m.body);
  return q.y() + std::sin(q.z()) * m.u.x() + std::cos(q.z()) * m.u.y();
}

// The pantograph at standstill: no aerodynamic uplift.
pantograph::Pantograph standstill(pantograph::Pantograph p) {
  p.aero = {};
  return p;
}
}  // namespace

double Commissioning::range_min() const {
  return range_force.empty() ? NAN : *std::min_element(range_force.begin(), range_force.end());
}
double Commissioning::range_max() const {
  return range_force.empty() ? NAN : *std::max_element(range_force.begin(), range_force.end());
}

double operating_length(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                        const catenary::Contact& contact) {
  const int act = pantograph::suspension_index(pantograph.model);
  auto sys = catenary.couple(pantograph, contact, 1.0);
  sys->equilibrate();
  const catenary::ContactId c = sys->contact(0);
  return sys->model(c).forces[static_cast<std::size_t>(act)]->length(sys->model(c), sys->state(c));
}

double static_force_at(const pantograph::Pantograph& p, double offset) {
  const int j = p.rig_joint;
  if (j < 0) throw ModelError(fmt::format("{}: no rig joint (pantograph: rig_joint): the static force needs the head held", p.model.source));
  if (!std::isfinite(offset)) throw InvalidArgument(fmt::format("static force: head offset {} m: expected a finite height", offset));
  mbs::Model m = p.model;
  m.joints[static_cast<std::size_t>(j)].motion = mbs::TimeFunction::constant(offset);  // value0 + offset
  m.finalize();
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  mbs::Workspace ws(m);
  mbs::accelerations(m, 0.0, x, ws);
  return -mbs::joint_reaction(m, j, 0.0, x, ws.lambda).y();  // compression positive
}

Commissioned commission(const pantograph::Pantograph& pantograph, const network::Network* suspension,
                        const catenary::Catenary& reference, const catenary::Contact& contact, const Trim& trim,
                        const WorkingRange* range) {
  Commissioned out;
  Commissioning& rec = out.record;
  const pantograph::Pantograph still = standstill(pantograph);
  pantograph::Pantograph p = pantograph;
  // 1. Relaxation at standstill on the reference line: with the model's own suspension in place the
  // pantograph settles at the operating length, where the new network carries no static load.
  if (suspension) {
    rec.operating_length = operating_length(still, reference, contact);
    p.model = pantograph::with_suspension(p.model, *suspension, rec.operating_length);
    const network::Network s = network::simplify(*suspension);
    rec.static_stiffness = s.kind == network::Network::Kind::Open ? 0.0 : network::realise(s).static_stiffness();
    if (std::abs(rec.static_stiffness) < 1e-6) rec.static_stiffness = 0;  // the realisation's round-off of a G(0) = 0
  }
  // The static contact force there, and the head's height: the rig's reaction with the head held where
  // the line holds it at standstill (the pantograph's own equilibrium with the line).
  if (p.rig_joint >= 0) {
    auto sys = reference.couple(standstill(p), contact, 1.0);
    sys->equilibrate();
    const catenary::ContactId c = sys->contact(0);
    const mbs::State rig = mbs::assemble(p.model, 0.0);
    rec.head_offset = contact_height(p, sys->model(c), sys->state(c)) - contact_height(p, p.model, rig);
    rec.static_force = static_force_at(standstill(p), rec.head_offset);
  }
  // 2. The aerodynamic trim on the reference line.
  if (trim.speed > 0) {
    rec.trimmed = true;
    rec.target = trim.target;
    AeroFit fit;
    if (trim.periodic) {
      auto mean_at = [&](double a) {
        return sweep_periodic(with_aerodynamic(p, a), reference, contact, {trim.speed}, trim.harmonics).front().stats.mean;
      };
      fit = fit_aerodynamic(mean_at, trim.speed, trim.target, trim.tolerance);
    } else {
      fit = fit_aerodynamic(p, reference, contact, trim.speed, trim.target, trim.statistics, trim.options, trim.tolerance);
    }
    rec.a = fit.a, rec.mean = fit.mean, rec.reached = fit.reached, rec.runs = fit.runs, rec.mean_without = fit.mean_without;
    if (!fit.reached && std::isnan(rec.mean)) rec.mean = fit.mean_without;
    p = with_aerodynamic(p, fit.a);
  } else {
    rec.a = p.aero.active() ? p.aero.a : 0.0;
  }
  // 3. The static contact force over the working range (EN 50206-1: the pantograph alone, its head held
  // at each height), the heights around the reference line's contact point.
  if (range && p.rig_joint >= 0) {
    if (!(range->below >= 0) || !(range->above >= 0) || !std::isfinite(range->below) || !std::isfinite(range->above) ||
        range->below + range->above <= 0 || range->points < 2)
      throw InvalidArgument(fmt::format("working range: below {} m, above {} m, {} points: expected finite heights >= 0, "
                                        "not both 0, and at least 2 points",
                                        range->below, range->above, range->points));
    // What the suspension adds to the stock pantograph's static force at each height: the stock
    // pantograph's lifting device is set to hold its static force over the range, and a suspension with
    // static stiffness G(0) moves it by what its strut then carries (docs/contact-quality.md
    // "Commissioning": the model's frame alone is not that characteristic).
    for (int k = 0; k < range->points; ++k) {
      const double h = -range->below + (range->below + range->above) * k / (range->points - 1);
      const double stock = static_force_at(still, rec.head_offset + h);
      const double mine = suspension ? static_force_at(standstill(p), rec.head_offset + h) : stock;
      rec.range_height.push_back(h);
      rec.range_model.push_back(mine);
      rec.range_force.push_back(rec.static_force + (mine - stock));
    }
  }
  out.pantograph = std::move(p);
  return out;
}

}  // namespace inerta::analysis
