#include "inerta/mbs/output.hpp"

#include "inerta/mbs/dynamics.hpp"

namespace inerta::mbs {

bool needs_accelerations(const Output& out) {
  using K = Output::Kind;
  return out.kind == K::Acceleration || out.kind == K::ElementForce || out.kind == K::Reaction ||
         out.kind == K::Multiplier;
}

double evaluate_output(const Output& out, const Model& model, double t, const State& x, const Workspace& ws) {
  double value = 0;
  switch (out.kind) {
    case Output::Kind::Coordinate:
      value = x.q[model.body_coords() * out.index + out.component];
      break;
    case Output::Kind::Position:
    case Output::Kind::Velocity:
    case Output::Kind::Acceleration: {
      const Marker& mk = model.markers[static_cast<std::size_t>(out.index)];
      if (model.spatial()) {  // r, ṙ, r̈ = G q̈ + bias (spatial.hpp)
        const SpatialVector p = spatial_vector(ws.sframe(mk.body), mk.u3, true);
        if (out.kind == Output::Kind::Position)
          value = p.v[out.component];
        else if (out.kind == Output::Kind::Velocity)
          value = p.vd[out.component];
        else if (mk.body >= 0)
          value = p.G_mul(ws.qdd.segment<7>(7 * mk.body))[out.component] + p.bias[out.component];
        break;
      }
      PointKinematics p = point_kinematics(ws.frame(mk.body), mk.u);
      if (out.kind == Output::Kind::Position)
        value = p.r[out.component];
      else if (out.kind == Output::Kind::Velocity)
        value = p.v[out.component];
      else if (mk.body >= 0) {
        // r̈_P = R̈ + A_θ ū θ̈ − A ū θ̇²
        Vec3 a = ws.qdd.segment<3>(3 * mk.body);
        value = a[out.component] + p.Atu[out.component] * a.z() + p.a_bias[out.component];
      }
      break;
    }
    case Output::Kind::ElementForce:
      value = model.forces[static_cast<std::size_t>(out.index)]->force(model, t, x, ws);
      break;
    case Output::Kind::ElementLength:
      value = model.forces[static_cast<std::size_t>(out.index)]->length(model, x);
      break;
    case Output::Kind::Reaction:
      value = joint_reaction(model, out.index, t, x, ws.lambda)[out.component];
      break;
    case Output::Kind::Multiplier:
      value = ws.lambda[model.joints[static_cast<std::size_t>(out.index)].row + out.component];
      break;
  }
  return out.scale * value;
}

}  // namespace inerta::mbs
