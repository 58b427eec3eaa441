// Lumped n-mass pantograph (pantograph/lumped.hpp).
#include "inerta/pantograph/lumped.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/struts.hpp"

namespace inerta::pantograph {

namespace {
constexpr const char* kWhat = "lumped pantograph";
constexpr double kReach = 10.0;  // m, the struts' length (lumped.hpp)

void finite(const std::string& key, double v, const char* unit) {
  if (!std::isfinite(v)) throw InvalidArgument(kWhat, key, fmt::format("must be a finite number ({}), got {}", unit, v));
}
}  // namespace

void LumpedPantographData::validate() const {
  if (mass.empty()) throw InvalidArgument(kWhat, "masses", "at least one mass (the head) is needed");
  if (stiffness.size() != mass.size())
    throw InvalidArgument(kWhat, "stiffness",
                          fmt::format("needs one value per mass ({}): k_i joins mass i to the next, the last to the "
                                      "ground; got {}",
                                      mass.size(), stiffness.size()));
  if (damping.size() != mass.size())
    throw InvalidArgument(kWhat, "damping",
                          fmt::format("needs one value per mass ({}), at the places of the springs; got {}",
                                      mass.size(), damping.size()));
  for (std::size_t i = 0; i < mass.size(); ++i) {
    if (!(mass[i] > 0) || !std::isfinite(mass[i]))
      throw InvalidArgument(kWhat, fmt::format("masses[{}]", i), fmt::format("must be > 0 (kg), got {}", mass[i]));
    if (!(stiffness[i] >= 0) || !std::isfinite(stiffness[i]))
      throw InvalidArgument(kWhat, fmt::format("stiffness[{}]", i),
                            fmt::format("must be >= 0 (N/m), got {}", stiffness[i]));
    if (!(damping[i] >= 0) || !std::isfinite(damping[i]))
      throw InvalidArgument(kWhat, fmt::format("damping[{}]", i),
                            fmt::format("must be >= 0 (N·s/m), got {}", damping[i]));
  }
  if (!(static_uplift >= 0) || !std::isfinite(static_uplift))
    throw InvalidArgument(kWhat, "static_uplift", fmt::format("must be >= 0 (N, upward), got {}", static_uplift));
  finite("aerodynamic.a", aero_a, "N·s²/m²");
  finite("aerodynamic.b", aero_b, "N·s/m");
  finite("aerodynamic.c", aero_c, "N");
}

Pantograph make_lumped_pantograph(const LumpedPantographData& d) {
  d.validate();
  const int n = static_cast<int>(d.mass.size());
  Pantograph p;
  mbs::Model& m = p.model;
  m.name = "lumped pantograph";
  m.source = "lumped pantograph";
  m.options.gravity = false;  // the static uplift is net of the weight (lumped.hpp)
  auto body_name = [](int i) { return i == 0 ? std::string("head") : fmt::format("m{}", i + 1); };
  for (int i = 0; i < n; ++i) {
    mbs::Body b;
    b.name = body_name(i);
    b.mass = d.mass[static_cast<std::size_t>(i)];
    b.inertia = 1.0;  // irrelevant: the rotation is locked by the slider
    m.bodies.push_back(b);
    m.markers.push_back({b.name + ".cm", i, mbs::Vec2::Zero()});
  }
  m.markers.push_back({"ground.origin", mbs::kGround, mbs::Vec2::Zero()});
  for (int i = 0; i < n; ++i) {
    mbs::Joint slide;
    slide.name = "slide_" + body_name(i);
    slide.type = mbs::JointType::Prismatic;
    slide.body_i = mbs::kGround, slide.body_j = i;
    slide.axis = mbs::Vec2(0, 1);
    m.joints.push_back(slide);
  }
  // Spring and damper i: from mass i's centre to a point kReach above mass i+1 (or the ground's origin).
  const mbs::Vec2 above(0, kReach);
  for (int i = 0; i < n; ++i) {
    const int next = i + 1 < n ? i + 1 : mbs::kGround;
    const auto s = static_cast<std::size_t>(i);
    m.forces.push_back(std::make_shared<mbs::Spring>(fmt::format("k{}", i + 1), i, mbs::Vec2::Zero().eval(), next,
                                                     above, d.stiffness[s], kReach));
    m.forces.push_back(
        std::make_shared<mbs::Damper>(fmt::format("c{}", i + 1), i, mbs::Vec2::Zero().eval(), next, above, d.damping[s]));
  }
  m.forces.push_back(std::make_shared<mbs::PointForce>("static_uplift", n - 1, mbs::Vec2::Zero(), mbs::Vec2(0, 1),
                                                       mbs::TimeFunction::constant(d.static_uplift)));
  mbs::Joint rig;
  rig.name = "rig";
  rig.type = mbs::JointType::Driving;
  rig.body_j = 0;
  rig.component = 1;
  rig.value0 = 0;
  rig.motion = mbs::TimeFunction::constant(0.0);
  m.joints.push_back(rig);
  for (int i = 0; i < n; ++i) {
    mbs::Output y;
    y.name = "y_" + body_name(i);
    y.kind = mbs::Output::Kind::Coordinate;
    y.index = i;
    y.component = 1;
    m.outputs.push_back(y);
  }
  m.finalize();
  p.contact_marker = 0;  // head.cm
  p.rig_joint = n;
  m.outputs.push_back(p.rig_force());
  if (d.aero_a != 0 || d.aero_b != 0 || d.aero_c != 0) p.aero = {0, d.aero_a, d.aero_b, d.aero_c};
  return p;
}

}  // namespace inerta::pantograph
