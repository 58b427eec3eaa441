#include "inerta/catenary/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::catenary {

void Contact::validate() const {
  if (!(stiffness > 0) || !std::isfinite(stiffness) || !(damping >= 0) || !std::isfinite(damping))
    throw InvalidArgument(fmt::format(
        "contact: stiffness must be > 0 N/m and damping >= 0 N·s/m (finite), got {} N/m and {} N·s/m", stiffness,
        damping));
}

const char* kind_name(Contact::Kind kind) { return kind == Contact::Kind::Bilateral ? "bilateral" : "penalty"; }

PenaltyContact::PenaltyContact(std::string name, int body_i, mbs::Vec2 u_i, int body_j, mbs::Vec2 u_j, double stiffness,
                               double damping, double overlap0)
    : ForceElement(std::move(name)),
      bi_(body_i),
      bj_(body_j),
      ui_(u_i),
      uj_(u_j),
      ks_(stiffness),
      cs_(damping),
      d0_(overlap0) {
  Contact{Contact::Kind::Penalty, stiffness, damping}.validate();
}

PenaltyContact::Eval PenaltyContact::evaluate(const mbs::BodyFrame& fi, const mbs::BodyFrame& fj) const {
  Eval e{0, 0, 0, mbs::point_kinematics(fi, ui_), mbs::point_kinematics(fj, uj_)};
  e.delta = e.pi.r.y() - e.pj.r.y() + d0_;
  e.delta_dot = e.pi.v.y() - e.pj.v.y();
  e.F = e.delta > 0 ? std::max(0.0, ks_ * e.delta + cs_ * e.delta_dot) : 0.0;
  return e;
}

void PenaltyContact::add(const mbs::Model&, double, const mbs::State&, mbs::Workspace& ws) const {
  Eval e = evaluate(ws.frame(bi_), ws.frame(bj_));
  if (e.F == 0) return;
  // Down on P_i (pantograph), up on P_j (wire); generalised forces G_Pᵀ f.
  if (bi_ >= 0) {
    ws.Q[3 * bi_ + 1] -= e.F;
    ws.Q[3 * bi_ + 2] -= e.pi.Atu.y() * e.F;
  }
  if (bj_ >= 0) {
    ws.Q[3 * bj_ + 1] += e.F;
    ws.Q[3 * bj_ + 2] += e.pj.Atu.y() * e.F;
  }
}

double PenaltyContact::energy(const mbs::Model& model, double, const mbs::State& x) const {
  Eval e = evaluate(model.frame(x, bi_), model.frame(x, bj_));
  return e.delta > 0 ? 0.5 * ks_ * e.delta * e.delta : 0.0;
}

double PenaltyContact::power(const mbs::Model& model, double, const mbs::State& x) const {
  // Beyond −d(½ k δ²)/dt: the damping part (and the clipping when F would pull).
  Eval e = evaluate(model.frame(x, bi_), model.frame(x, bj_));
  if (e.delta <= 0) return 0.0;
  return -(e.F - ks_ * e.delta) * e.delta_dot;
}

double PenaltyContact::force(const mbs::Model&, double, const mbs::State&, const mbs::Workspace& ws) const {
  return evaluate(ws.frame(bi_), ws.frame(bj_)).F;
}

double PenaltyContact::length(const mbs::Model& model, const mbs::State& x) const {
  return evaluate(model.frame(x, bi_), model.frame(x, bj_)).delta;
}

}  // namespace inerta::catenary
