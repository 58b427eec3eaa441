#include "inerta/catenary/lumped.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::catenary {

using std::numbers::pi;

double LumpedCatenary::harmonic(const std::array<double, 4>& x, double fp, double t) {
  double v = x[0];
  for (int i = 1; i <= 3; ++i) v += x[static_cast<std::size_t>(i)] * std::cos(2 * pi * i * fp * t);
  return v;
}
double LumpedCatenary::harmonic_rate(const std::array<double, 4>& x, double fp, double t) {
  double v = 0;
  for (int i = 1; i <= 3; ++i) v -= x[static_cast<std::size_t>(i)] * 2 * pi * i * fp * std::sin(2 * pi * i * fp * t);
  return v;
}
double LumpedCatenary::natural_frequency() const { return std::sqrt(k[0] / m[0]) / (2 * pi); }

CatenaryElement::CatenaryElement(std::string name, int body, LumpedCatenary cat, double speed, double y_unloaded)
    : ForceElement(std::move(name)), body_(body), cat_(cat), v_(speed), y0_(y_unloaded) {}

void CatenaryElement::add(const mbs::Model& model, double t, const mbs::State& x, mbs::Workspace& ws) const {
  const double fp = pumping_frequency();
  const int iy = 3 * body_ + 1;
  const double y = x.q[iy] - y0_, yd = x.qd[iy];
  // eq. 7.1: the body carries m_c0; the harmonics of the mass enter M, c_c(t) and k_c(t) enter Q.
  ws.M(iy, iy) += LumpedCatenary::harmonic(cat_.m, fp, t) - cat_.m[0];
  ws.Q[iy] -= LumpedCatenary::harmonic(cat_.c, fp, t) * yd + LumpedCatenary::harmonic(cat_.k, fp, t) * y;
}

double CatenaryElement::energy(const mbs::Model& model, double t, const mbs::State& x) const {
  const double fp = pumping_frequency();
  const int iy = 3 * body_ + 1;
  const double y = x.q[iy] - y0_, yd = x.qd[iy];
  return 0.5 * (LumpedCatenary::harmonic(cat_.m, fp, t) - cat_.m[0]) * yd * yd +
         0.5 * LumpedCatenary::harmonic(cat_.k, fp, t) * y * y;
}

double CatenaryElement::power(const mbs::Model& model, double t, const mbs::State& x) const {
  // Work rate on the body not in −d(energy)/dt: damping, and the explicit time variation.
  const double fp = pumping_frequency();
  const int iy = 3 * body_ + 1;
  const double y = x.q[iy] - y0_, yd = x.qd[iy];
  return -LumpedCatenary::harmonic(cat_.c, fp, t) * yd * yd +
         0.5 * LumpedCatenary::harmonic_rate(cat_.k, fp, t) * y * y +
         0.5 * LumpedCatenary::harmonic_rate(cat_.m, fp, t) * yd * yd;
}

double CatenaryElement::force(const mbs::Model& model, double t, const mbs::State& x, const mbs::Workspace&) const {
  const double fp = pumping_frequency();
  const int iy = 3 * body_ + 1;
  return -LumpedCatenary::harmonic(cat_.c, fp, t) * x.qd[iy] -
         LumpedCatenary::harmonic(cat_.k, fp, t) * (x.q[iy] - y0_);
}

double CatenaryElement::length(const mbs::Model& model, const mbs::State& x) const { return x.q[3 * body_ + 1] - y0_; }

// Penalty contact ----------------------------------------------------------------------------
PenaltyContact::PenaltyContact(std::string name, int body_i, mbs::Vec2 u_i, int body_j, mbs::Vec2 u_j, double stiffness,
                               double damping, double overlap0)
    : ForceElement(std::move(name)),
      bi_(body_i),
      bj_(body_j),
      ui_(u_i),
      uj_(u_j),
      ks_(stiffness),
      cs_(damping),
      d0_(overlap0) {}

PenaltyContact::Eval PenaltyContact::evaluate(const mbs::BodyFrame& fi, const mbs::BodyFrame& fj) const {
  Eval e{0, 0, 0, mbs::point_kinematics(fi, ui_), mbs::point_kinematics(fj, uj_)};
  e.delta = e.pi.r.y() - e.pj.r.y() + d0_;
  e.delta_dot = e.pi.v.y() - e.pj.v.y();
  e.F = e.delta > 0 ? std::max(0.0, ks_ * e.delta + cs_ * e.delta_dot) : 0.0;
  return e;
}

void PenaltyContact::add(const mbs::Model& model, double, const mbs::State&, mbs::Workspace& ws) const {
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

double PenaltyContact::force(const mbs::Model& model, double, const mbs::State&, const mbs::Workspace& ws) const {
  return evaluate(ws.frame(bi_), ws.frame(bj_)).F;
}

double PenaltyContact::length(const mbs::Model& model, const mbs::State& x) const {
  return evaluate(model.frame(x, bi_), model.frame(x, bj_)).delta;
}

}  // namespace inerta::catenary
