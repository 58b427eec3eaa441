#pragma once
// A pantograph model with what a catenary and a test rig need to know of it (spec/04): the head's
// contact point and the joint that holds the head on the rig. Kept beside the multibody model,
// not inside it (mbs::Model knows nothing of pantographs).
#include "inerta/mbs/model.hpp"

namespace inerta::pantograph {

struct Pantograph {
  mbs::Model model;
  int contact_marker = -1;  ///< index in model.markers: the head's contact point with the wire
  int rig_joint = -1;       ///< index in model.joints: the rig's hold of the head (-1: none)

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

}  // namespace inerta::pantograph
