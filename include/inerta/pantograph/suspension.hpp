#pragma once
// Replacing the base suspension of a pantograph model (issue 4): the dynamic network of its
// actuator becomes any network; the constant force, piston mass and friction stay.
#include "inerta/mbs/model.hpp"
#include "inerta/network/network.hpp"

namespace inerta::pantograph {

/// The model with its (single) actuator's network replaced by `net` (bound, not yet simplified).
/// Internal-state offsets of the following network struts are renumbered. Throws ModelError if the
/// model has no actuator, or if `net` is rigid.
mbs::Model with_suspension(const mbs::Model& model, const network::Network& net);

}  // namespace inerta::pantograph
