#pragma once
// A pantograph model with what a catenary and a test rig need to know of it (spec/04): the head's
// contact point, the joint that holds the head on the rig, and an optional aerodynamic uplift that
// depends on the running speed. Kept beside the multibody model, not inside it (mbs::Model knows
// nothing of pantographs).
#include "inerta/mbs/model.hpp"

namespace inerta::pantograph {

struct Pantograph {
  mbs::Model model;
  int contact_marker = -1;  ///< index in model.markers: the head's contact point with the wire
  int rig_joint = -1;       ///< index in model.joints: the rig's hold of the head (-1: none)
  /// Aerodynamic uplift on `body` (the head), F = a v² + b v + c (N, up; v the running speed in
  /// m/s), added as a constant force by at_speed (Catenary::couple does it). body = −1: none.
  struct Aero {
    int body = -1;
    double a = 0, b = 0, c = 0;  ///< N·s²/m², N·s/m, N
    bool active() const { return body >= 0; }
    double force(double v) const { return (a * v + b) * v + c; }  ///< N
  } aero;

  const mbs::Marker& contact() const { return model.markers[static_cast<std::size_t>(contact_marker)]; }
  bool has_rig() const { return rig_joint >= 0; }
  /// The contact force on the rig: the rig joint's reaction on the head (a driving joint's body j),
  /// vertical, compression positive. Only with has_rig().
  mbs::Output rig_force() const {
    mbs::Output o;
    o.name = "F_contact";
    o.kind = mbs::Output::Kind::Reaction;
    o.index = rig_joint;
    o.component = 1;
    o.scale = -1;
    return o;
  }
};

/// The pantograph running at speed v (m/s, finite, >= 0): a copy whose model carries the
/// aerodynamic uplift a v² + b v + c as a constant vertical force ("aerodynamic_uplift", at the
/// centre of mass of aero.body) and whose `aero` is cleared, so applying at_speed again adds
/// nothing. Without an aerodynamic term, the pantograph unchanged. InvalidArgument for a bad speed
/// or a body out of range.
Pantograph at_speed(const Pantograph& p, double v);

}  // namespace inerta::pantograph
