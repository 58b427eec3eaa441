#include "inerta/mbs/struts.hpp"

#include <fmt/format.h>

#include "inerta/error.hpp"

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

Strut::Strut(std::string name, int body_i, StrutEnd u_i, int body_j, StrutEnd u_j)
    : ForceElement(std::move(name)), body_i_(body_i), body_j_(body_j), u_i_(u_i.u), u_j_(u_j.u), spatial_(u_i.spatial) {
  const check::Element who{"strut", this->name()};
  if (body_i == body_j)
    check::fail(who, "markers", "both terminals are on the same body; a strut needs two bodies");
  if (u_i.spatial != u_j.spatial) check::fail(who, "markers", "one terminal is planar and the other spatial");
  check::finite_vector(who, "markers", u_i_);
  check::finite_vector(who, "markers", u_j_);
}

StrutKinematics Strut::kinematics(const Model& model, const State& x) const {
  if (spatial_) return strut_kinematics(model.sframe(x, body_i_), u_i_, model.sframe(x, body_j_), u_j_);
  return strut_kinematics(model.frame(x, body_i_), u_i(), model.frame(x, body_j_), u_j());
}
StrutKinematics Strut::kinematics(const Workspace& ws) const {
  StrutKinematics s = spatial_ ? strut_kinematics(ws.sframe(body_i_), u_i_, ws.sframe(body_j_), u_j_)
                               : strut_kinematics(ws.frame(body_i_), u_i(), ws.frame(body_j_), u_j());
  // Through zero length the axis ê = r/l flips and the force with it (issue 15): stop instead.
  if (!(s.l >= min_strut_length))
    throw NumericalError(fmt::format("strut '{}' passes through zero length (l = {:.3g} m < {:g} m): its axis and force "
                                     "would flip; check its markers, free length and the loads that compress it",
                                     name(), s.l, min_strut_length));
  return s;
}

double Strut::length(const Model& model, const State& x) const { return kinematics(model, x).l; }

bool Strut::strut_vector(const Model& model, const State& x, Eigen::Vector3d& r) const {
  if (spatial_) {
    const SpatialFrame fi = model.sframe(x, body_i_), fj = model.sframe(x, body_j_);
    r = fj.R + fj.A * u_j_ - fi.R - fi.A * u_i_;
  } else {
    const Vec2 d = point_kinematics(model.frame(x, body_j_), u_j()).r - point_kinematics(model.frame(x, body_i_), u_i()).r;
    r << d, 0.0;
  }
  return true;
}

void Strut::add_tension(double F, const StrutKinematics& s, Workspace& ws) const {
  ws.add_Q(body_i_, body_j_, -F * s.J);
}

// Spring ---------------------------------------------------------------------------------------
void Spring::add(const Model&, double, const State&, Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  add_tension(k_ * (s.l - L0_), s, ws);
}
double Spring::energy(const Model& model, double, const State& x) const {
  double d = kinematics(model, x).l - L0_;
  return 0.5 * k_ * d * d;
}
double Spring::force(const Model& model, double, const State& x, const Workspace&) const {
  return k_ * (kinematics(model, x).l - L0_);
}

// Damper ---------------------------------------------------------------------------------------
void Damper::add(const Model&, double, const State&, Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  add_tension(c_ * s.l_dot, s, ws);
}
double Damper::power(const Model& model, double, const State& x) const {
  double ld = kinematics(model, x).l_dot;
  return -c_ * ld * ld;
}
double Damper::force(const Model& model, double, const State& x, const Workspace&) const { return c_ * kinematics(model, x).l_dot; }

// Inerter --------------------------------------------------------------------------------------
bool Inerter::centripetal(const Model& model) const { return centripetal_ && model.options.centripetal; }

void Inerter::add(const Model& model, double, const State&, Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  // eq. 3.31: Q_Iv = −b Jᵀ (ê·a_n + correction);  eq. 3.33: M_I = b Jᵀ J.
  double bias = s.a_n_axial + (centripetal(model) ? s.centripetal : 0.0);
  add_tension(b_ * bias, s, ws);
  ws.add_M(body_i(), body_j(), s.J, b_);
}
double Inerter::energy(const Model& model, double, const State& x) const {
  double ld = kinematics(model, x).l_dot;
  return 0.5 * b_ * ld * ld;
}
double Inerter::power(const Model& model, double, const State& x) const {
  if (centripetal(model)) return 0.0;
  StrutKinematics s = kinematics(model, x);
  return b_ * s.centripetal * s.l_dot;
}
double Inerter::force(const Model& model, double, const State&, const Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  return b_ * (ws.J_dot_qdd(body_i(), body_j(), s.J) + s.a_n_axial +
               (centripetal(model) ? s.centripetal : 0.0));  // eq. 3.20
}

// Constant axial force -------------------------------------------------------------------------
void AxialForce::add(const Model&, double, const State&, Workspace& ws) const { add_tension(F_, kinematics(ws), ws); }
double AxialForce::energy(const Model& model, double, const State& x) const { return F_ * kinematics(model, x).l; }

}  // namespace inerta::mbs
