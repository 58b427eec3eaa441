// The aerodynamic uplift of a pantograph at a running speed (pantograph/pantograph.hpp).
#include "inerta/pantograph/pantograph.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"

namespace inerta::pantograph {

Pantograph at_speed(const Pantograph& p, double v) {
  if (!p.aero.active()) return p;
  if (!(v >= 0) || !std::isfinite(v))
    throw InvalidArgument(fmt::format("at_speed: the running speed must be a finite number >= 0 m/s, got {}", v));
  if (p.aero.body >= static_cast<int>(p.model.bodies.size()))
    throw InvalidArgument(fmt::format("{}: the aerodynamic uplift acts on body {}, but the model has {} bodies",
                                      p.model.source, p.aero.body, p.model.bodies.size()));
  Pantograph q = p;
  const double F = p.aero.force(v);
  q.model.forces.push_back(std::make_shared<mbs::PointForce>("aerodynamic_uplift", p.aero.body, mbs::Vec2::Zero(),
                                                             mbs::Vec2(0, 1), mbs::TimeFunction::constant(F)));
  q.model.finalize();
  q.aero = {};
  return q;
}

}  // namespace inerta::pantograph
