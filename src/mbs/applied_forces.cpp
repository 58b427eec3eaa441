#include "inerta/mbs/applied_forces.hpp"

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

void Gravity::add(const Model& model, double, const State&, Workspace& ws) const {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].weighs) ws.Q.segment<2>(3 * static_cast<int>(b)) += model.bodies[b].mass * g_;
}
double Gravity::energy(const Model& model, double, const State& x) const {
  double V = 0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].weighs) V -= model.bodies[b].mass * g_.dot(x.q.segment<2>(3 * static_cast<int>(b)));
  return V;
}
double Gravity::force(const Model& model, double, const State&, const Workspace&) const {
  double m = 0;
  for (const Body& b : model.bodies) m += b.weighs ? b.mass : 0.0;
  return m * g_.norm();
}

void PointForce::add(const Model&, double t, const State&, Workspace& ws) const {
  if (body_ < 0) return;
  PointKinematics p = point_kinematics(ws.frame(body_), u_);
  Vec2 F = f_.value(t) * d_;
  ws.Q.segment<2>(3 * body_) += F;
  ws.Q[3 * body_ + 2] += p.Atu.dot(F);  // moment about the centre of mass
}
double PointForce::power(const Model&, double t, const State& x) const {
  if (body_ < 0) return 0.0;
  return f_.value(t) * d_.dot(point_kinematics(x.q_of(body_), x.qd_of(body_), u_).v);
}

void RotationalSpringDamper::add(const Model&, double, const State& x, Workspace& ws) const {
  double m = -k_ * (x.q_of(bj_).z() - x.q_of(bi_).z() - a0_) - c_ * (x.qd_of(bj_).z() - x.qd_of(bi_).z());
  if (bj_ >= 0) ws.Q[3 * bj_ + 2] += m;
  if (bi_ >= 0) ws.Q[3 * bi_ + 2] -= m;
}
double RotationalSpringDamper::energy(const Model&, double, const State& x) const {
  double d = x.q_of(bj_).z() - x.q_of(bi_).z() - a0_;
  return 0.5 * k_ * d * d;
}
double RotationalSpringDamper::power(const Model&, double, const State& x) const {
  double w = x.qd_of(bj_).z() - x.qd_of(bi_).z();
  return -c_ * w * w;
}
double RotationalSpringDamper::force(const Model&, double, const State& x, const Workspace&) const {
  return -k_ * (x.q_of(bj_).z() - x.q_of(bi_).z() - a0_) - c_ * (x.qd_of(bj_).z() - x.qd_of(bi_).z());
}
double RotationalSpringDamper::length(const Model&, const State& x) const { return x.q_of(bj_).z() - x.q_of(bi_).z(); }

}  // namespace inerta::mbs
