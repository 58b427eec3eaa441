#include "inerta/pantograph/suspension.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

namespace inerta::pantograph {

int suspension_index(const mbs::Model& model) {
  if (model.actuators.empty())
    throw ModelError(fmt::format("{}: the model has no actuator whose suspension could be replaced", model.source));
  if (model.actuators.size() > 1)
    throw ModelError(fmt::format("{}: more than one actuator; the suspension is ambiguous", model.source));
  return model.actuators.front();
}

mbs::Model with_suspension(const mbs::Model& model, const network::Network& bound, double reference_length) {
  using network::Network;
  mbs::Model m = model;
  Network net = network::simplify(bound);
  if (net.kind == Network::Kind::Rigid)
    throw ModelError(fmt::format("suspension '{}' is rigid with these values; it would lock the pantograph",
                                 network::to_string(bound, true)));
  if (net.kind == Network::Kind::Open) {
    m.notes.push_back(fmt::format("suspension '{}' is open: only the actuator's constant force and piston mass act",
                                  network::to_string(bound, true)));
    net = Network{Network::Kind::Damper, "c", 0.0, {}, 0};
  }
  auto& f = m.forces[static_cast<std::size_t>(suspension_index(m))];
  f = f->with_network(net, reference_length > 0 ? reference_length : NAN);
  m.finalize();  // places the internal states of the new network and of every element after it
  return m;
}

mbs::Model release_head(const Pantograph& p, double* static_force) {
  const mbs::Model& model = p.model;
  const int j = p.rig_joint;
  if (j < 0) throw ModelError(fmt::format("{}: no rig joint (pantograph: rig_joint) to release", model.source));
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  mbs::Workspace ws(model);
  mbs::accelerations(model, 0.0, x, ws);
  const mbs::Vec3 r = mbs::joint_reaction(model, j, 0.0, x, ws.lambda);  // on the held body
  const int head = model.joints[static_cast<std::size_t>(j)].body_j;
  mbs::Model m = model;
  m.remove_joint(model.joints[static_cast<std::size_t>(j)].name);
  const mbs::Vec2 F = r.head<2>();
  if (F.norm() > 0)
    m.forces.push_back(std::make_shared<mbs::PointForce>("static_contact", head, mbs::Vec2::Zero(), F / F.norm(),
                                                         mbs::TimeFunction::constant(F.norm())));
  m.finalize();
  if (static_force) *static_force = -r.y();
  return m;
}

}  // namespace inerta::pantograph
