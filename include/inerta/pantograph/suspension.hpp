#pragma once
// Replacing the base suspension of a pantograph model (issue 4): the dynamic network of its
// actuator becomes any network; the constant force, piston mass and friction stay.
#include "inerta/mbs/model.hpp"
#include "inerta/network/network.hpp"
#include "inerta/pantograph/pantograph.hpp"

namespace inerta::pantograph {

/// The suspension: the index in model.forces of the model's single actuator (mbs::Model::actuators).
/// ModelError naming the model if it has none, or more than one (the suspension is ambiguous).
int suspension_index(const mbs::Model& model);

/// The model with its (single) actuator's network replaced by `net` (bound, not yet simplified).
/// Internal-state offsets of the following network struts are renumbered. Throws ModelError if the
/// model has no actuator, or if `net` is rigid.
/// `reference_length` > 0 sets the length at which the new network is relaxed (default: the old one's).
mbs::Model with_suspension(const mbs::Model& model, const network::Network& net, double reference_length = -1);

/// The pantograph with its head released from the rig joint and loaded instead by a constant force
/// equal to the joint's static reaction (the static contact force), so the static equilibrium is
/// unchanged and the head is free (modes of the free pantograph, spec/06 §6.3). `static_force`
/// receives that force (N, compression positive). Throws ModelError without a rig joint.
mbs::Model release_head(const Pantograph& pantograph, double* static_force = nullptr);

}  // namespace inerta::pantograph
