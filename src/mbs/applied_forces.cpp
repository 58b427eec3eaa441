#include "inerta/mbs/applied_forces.hpp"

#include "inerta/error.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/parameter_check.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

namespace {
// f, if TimeFunction::validate accepts it; otherwise InvalidArgument naming the element ("value").
TimeFunction valid(const check::Element& who, TimeFunction f) {
  try {
    f.validate();
  } catch (const InvalidArgument& e) {
    check::fail(who, "value", e.what());
  }
  return f;
}
}  // namespace

Gravity::Gravity(Vec2 g)
    : ForceElement("gravity"), g_(check::finite_vector({"gravity", ""}, "g", g)), g3_(g.x(), g.y(), 0.0) {}
Gravity::Gravity(Vec3 g)
    : ForceElement("gravity"), g_(g.head<2>()), g3_(check::finite_vector({"gravity", ""}, "g", g)), spatial_(true) {}

PointForce::PointForce(std::string name, int body, Vec2 u, Vec2 direction, TimeFunction f)
    : ForceElement(std::move(name)),
      body_(body),
      u_(check::finite_vector({"point force", this->name()}, "marker", u)),
      d_(check::direction({"point force", this->name()}, "direction", direction).normalized()),
      f_(valid({"point force", this->name()}, std::move(f))) {}
PointForce::PointForce(std::string name, int body, Vec3 u, Vec3 direction, TimeFunction f, std::true_type)
    : ForceElement(std::move(name)),
      body_(body),
      u3_(check::finite_vector({"point force", this->name()}, "marker", u)),
      d3_(check::direction({"point force", this->name()}, "direction", direction).normalized()),
      f_(valid({"point force", this->name()}, std::move(f))),
      spatial_(true) {}

PointTorque::PointTorque(std::string name, int body, Vec3 axis, TimeFunction f)
    : ForceElement(std::move(name)),
      body_(body),
      n_(check::direction({"point torque", this->name()}, "axis", axis).normalized()),
      f_(valid({"point torque", this->name()}, std::move(f))) {}

std::shared_ptr<const ForceElement> PointForce::with_value(const TimeFunction& f) const {
  auto copy = std::make_shared<PointForce>(*this);
  copy->f_ = valid({"point force", name()}, f);
  return copy;
}
std::shared_ptr<const ForceElement> PointTorque::with_value(const TimeFunction& f) const {
  auto copy = std::make_shared<PointTorque>(*this);
  copy->f_ = valid({"point torque", name()}, f);
  return copy;
}

RotationalSpringDamper::RotationalSpringDamper(std::string name, int body_i, int body_j, double k, double angle0,
                                               double c)
    : ForceElement(std::move(name)),
      bi_(body_i),
      bj_(body_j),
      k_(check::nonnegative({"rotational spring-damper", this->name()}, "k", k, "N·m/rad")),
      a0_(check::finite({"rotational spring-damper", this->name()}, "angle0", angle0, "rad")),
      c_(check::nonnegative({"rotational spring-damper", this->name()}, "c", c, "N·m·s/rad")) {}
RotationalSpringDamper::RotationalSpringDamper(std::string name, int body_i, int body_j, double k, double angle0,
                                               double c, Spatial sp)
    : RotationalSpringDamper(std::move(name), body_i, body_j, k, angle0, c) {
  const check::Element who{"rotational spring-damper", this->name()};
  check::direction(who, "joint", sp.s_i);  // the joint's axis and reference directions
  check::direction(who, "joint", sp.h_i);
  check::direction(who, "joint", sp.h_j);
  check::finite(who, "joint", sp.angle_init, "rad");
  sp_ = sp;
  spatial_ = true;
}

void Gravity::add(const Model& model, double, const State&, Workspace& ws) const {
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].weighs) continue;
    if (spatial_)
      ws.Q.segment<3>(7 * static_cast<int>(b)) += model.bodies[b].mass * g3_;
    else
      ws.Q.segment<2>(3 * static_cast<int>(b)) += model.bodies[b].mass * g_;
  }
}
double Gravity::energy(const Model& model, double, const State& x) const {
  double V = 0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].weighs) continue;
    if (spatial_)
      V -= model.bodies[b].mass * g3_.dot(x.q.segment<3>(7 * static_cast<int>(b)));
    else
      V -= model.bodies[b].mass * g_.dot(x.q.segment<2>(3 * static_cast<int>(b)));
  }
  return V;
}
double Gravity::force(const Model& model, double, const State&, const Workspace&) const {
  double m = 0;
  for (const Body& b : model.bodies) m += b.weighs ? b.mass : 0.0;
  return m * g3_.norm();
}

void PointForce::add(const Model&, double t, const State&, Workspace& ws) const {
  if (body_ < 0) return;
  if (spatial_) {
    const SpatialVector p = spatial_vector(ws.sframe(body_), u3_, true);
    ws.Q.segment<7>(7 * body_) += p.Gt(f_.value(t) * d3_);
    return;
  }
  PointKinematics p = point_kinematics(ws.frame(body_), u_);
  Vec2 F = f_.value(t) * d_;
  ws.Q.segment<2>(3 * body_) += F;
  ws.Q[3 * body_ + 2] += p.Atu.dot(F);  // moment about the centre of mass
}
double PointForce::power(const Model& model, double t, const State& x) const {
  if (body_ < 0) return 0.0;
  if (spatial_) return f_.value(t) * d3_.dot(spatial_vector(model.sframe(x, body_), u3_, true).vd);
  return f_.value(t) * d_.dot(point_kinematics(model.q_of(x, body_), model.qd_of(x, body_), u_).v);
}

void PointTorque::add(const Model&, double t, const State&, Workspace& ws) const {
  if (body_ >= 0) ws.Q.segment<4>(7 * body_ + 3) += 2 * ws.sframe(body_).E.transpose() * (f_.value(t) * n_);
}
double PointTorque::power(const Model& model, double t, const State& x) const {
  return body_ < 0 ? 0.0 : f_.value(t) * n_.dot(model.sframe(x, body_).w);
}

double RotationalSpringDamper::angle(const Model& model, const State& x) const {
  if (!spatial_) return model.q_of(x, bj_).z() - model.q_of(x, bi_).z();
  const SpatialFrame fi = model.sframe(x, bi_), fj = model.sframe(x, bj_);
  const Vec3 hi = fi.A * sp_.h_i, hj = fj.A * sp_.h_j, s = fi.A * sp_.s_i;
  return sp_.angle_init + std::atan2(hi.cross(hj).dot(s), hi.dot(hj));
}
double RotationalSpringDamper::rate(const Model& model, const State& x) const {
  if (!spatial_) return model.qd_of(x, bj_).z() - model.qd_of(x, bi_).z();
  const SpatialFrame fi = model.sframe(x, bi_), fj = model.sframe(x, bj_);
  return (fi.A * sp_.s_i).dot(fj.w - fi.w);
}
void RotationalSpringDamper::add(const Model& model, double, const State& x, Workspace& ws) const {
  const double m = -k_ * (angle(model, x) - a0_) - c_ * rate(model, x);
  if (spatial_) {
    const Vec3 T = m * (ws.sframe(bi_).A * sp_.s_i);
    if (bj_ >= 0) ws.Q.segment<4>(7 * bj_ + 3) += 2 * ws.sframe(bj_).E.transpose() * T;
    if (bi_ >= 0) ws.Q.segment<4>(7 * bi_ + 3) -= 2 * ws.sframe(bi_).E.transpose() * T;
    return;
  }
  if (bj_ >= 0) ws.Q[3 * bj_ + 2] += m;
  if (bi_ >= 0) ws.Q[3 * bi_ + 2] -= m;
}
double RotationalSpringDamper::energy(const Model& model, double, const State& x) const {
  double d = angle(model, x) - a0_;
  return 0.5 * k_ * d * d;
}
double RotationalSpringDamper::power(const Model& model, double, const State& x) const {
  double w = rate(model, x);
  return -c_ * w * w;
}
double RotationalSpringDamper::force(const Model& model, double, const State& x, const Workspace&) const {
  return -k_ * (angle(model, x) - a0_) - c_ * rate(model, x);
}
double RotationalSpringDamper::length(const Model& model, const State& x) const { return angle(model, x); }

}  // namespace inerta::mbs
