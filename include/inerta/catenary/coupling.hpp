#pragma once
// Pantograph–catenary coupling (spec/05 §5.2): the wire as a body on a vertical slider at the
// contact point, the lumped catenary element, and a bilateral (thesis) or penalty contact.
#include <string>

#include "inerta/catenary/lumped.hpp"
#include "inerta/mbs/model.hpp"

namespace inerta::catenary {

struct Contact {
  enum class Kind { Bilateral, Penalty };
  Kind kind = Kind::Bilateral;
  double stiffness = 50e3;  ///< penalty k_s, N/m
  double damping = 0.0;     ///< penalty c_s, N·s/m
};

/// Adds the wire body "catenary" (mass m_c0, rotation and x locked) at (x, y_unloaded) and its
/// CatenaryElement for `speed` (m/s). Returns the body index. Call Model::finalize afterwards.
int add_catenary(mbs::Model& model, const LumpedCatenary& cat, double speed, double x, double y_unloaded);

/// Couples a pantograph model to the catenary at marker `contact_marker` (the wire starts unloaded
/// at that point's assembled height): removes the joint `rig_joint` if the model has one (the
/// test-rig hold of the head), adds the wire and the contact, and the output `F_contact` (contact
/// force, compression positive; replaces an output of that name). Throws ModelError on unknown names.
mbs::Model couple(const mbs::Model& pantograph, const LumpedCatenary& cat, const Contact& contact, double speed,
                  const std::string& contact_marker, const std::string& rig_joint = "contact");

}  // namespace inerta::catenary
