#include "inerta/catenary/coupling.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"

namespace inerta::catenary {

int add_catenary(mbs::Model& model, const LumpedCatenary& cat, double speed, double x, double y_unloaded) {
  mbs::Body wire;
  wire.name = "catenary";
  wire.mass = cat.m[0];
  wire.inertia = 1.0;   // irrelevant: rotation locked
  wire.weighs = false;  // y is measured from the unloaded (statically balanced) wire height
  wire.q0 = mbs::Vec3(x, y_unloaded, 0.0);
  model.bodies.push_back(wire);
  const int b = static_cast<int>(model.bodies.size()) - 1;
  model.markers.push_back({"catenary.cm", b, mbs::Vec2::Zero()});
  mbs::Marker anchor{"ground.catenary", mbs::kGround, mbs::Vec2(x, 0.0)};
  model.markers.push_back(anchor);
  mbs::Joint slide;
  slide.name = "catenary_slide";
  slide.type = mbs::JointType::Prismatic;
  slide.body_i = mbs::kGround, slide.body_j = b;
  slide.u_i = anchor.u;
  slide.axis = mbs::Vec2(0, 1);
  model.joints.push_back(slide);
  model.forces.push_back(std::make_shared<CatenaryElement>("catenary", b, cat, speed, y_unloaded));
  return b;
}

mbs::Model couple(const mbs::Model& pantograph, const LumpedCatenary& cat, const Contact& contact, double speed,
                  const std::string& contact_marker, const std::string& rig_joint) {
  mbs::Model m = pantograph;
  const int mk = m.find_marker(contact_marker);
  if (mk < 0) throw ModelError(fmt::format("{}: unknown contact marker '{}'", m.source, contact_marker));
  // Remove the rig's hold of the head (and its outputs) and any earlier F_contact.
  m.remove_joint(rig_joint);
  std::erase_if(m.outputs, [](const mbs::Output& o) { return o.name == "F_contact"; });
  m.finalize();
  // The wire starts unloaded at the contact point's assembled position.
  mbs::State x = mbs::assemble(m, 0.0);
  const mbs::Marker point = m.markers[static_cast<std::size_t>(mk)];
  const mbs::Vec2 r = mbs::point_kinematics(m.frame(x, point.body), point.u).r;
  const int wire = add_catenary(m, cat, speed, r.x(), r.y());
  mbs::Output F;
  F.name = "F_contact";
  if (contact.kind == Contact::Kind::Bilateral) {
    mbs::Joint j;
    j.name = "contact";
    j.type = mbs::JointType::Coupling;
    j.body_i = wire, j.u_i = mbs::Vec2::Zero();
    j.body_j = point.body, j.u_j = point.u;
    j.component = 1;
    m.joints.push_back(j);
    // C = y_P − y_wire: λ acts on the head as −λ (C_q,head = +1), so compression = λ.
    F.kind = mbs::Output::Kind::Multiplier;
    F.index = static_cast<int>(m.joints.size()) - 1;
  } else {
    m.forces.push_back(std::make_shared<PenaltyContact>("contact", point.body, point.u, wire, mbs::Vec2::Zero(),
                                                        contact.stiffness, contact.damping, 0.0));
    F.kind = mbs::Output::Kind::ElementForce;
    F.index = static_cast<int>(m.forces.size()) - 1;
  }
  m.outputs.push_back(F);
  m.finalize();
  return m;
}

}  // namespace inerta::catenary
