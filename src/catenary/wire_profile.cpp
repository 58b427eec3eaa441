#include "inerta/catenary/wire_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/catenary/embedded.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"

namespace inerta::catenary {

ProfileContact::ProfileContact(std::string name, int body, mbs::Vec2 u, std::shared_ptr<const numerics::CubicSpline> h,
                               double x0, double speed, double y_offset, double stiffness, double damping)
    : ForceElement(std::move(name)),
      body_(body),
      u_(u),
      h_(std::move(h)),
      x0_(x0),
      v_(speed),
      y_offset_(y_offset),
      ks_(stiffness),
      cs_(damping) {
  Contact{Contact::Kind::Penalty, stiffness, damping}.validate();
  if (!h_) throw InvalidArgument("profile contact: no profile");
  if (body_ < 0) throw InvalidArgument("profile contact: the contact point must be on a body, not on the ground");
  if (!std::isfinite(x0) || !std::isfinite(speed) || !std::isfinite(y_offset))
    throw InvalidArgument("profile contact: x0, speed and offset must be finite");
}

double ProfileContact::wire_height(double t) const {
  const double xc = x0_ + v_ * t;
  if (h_->ends() != numerics::CubicSpline::Ends::Periodic && (xc < h_->x_min() || xc > h_->x_max()))
    throw NumericalError(fmt::format(
        "t = {:.6g} s: the contact point is at x = {:.6g} m, outside the wire profile [{:g}, {:g}] m; "
        "shorten the run, or make the profile periodic",
        t, xc, h_->x_min(), h_->x_max()));
  return y_offset_ + h_->value(xc);
}
double ProfileContact::wire_rate(double t) const { return v_ * h_->slope(x0_ + v_ * t); }

ProfileContact::Eval ProfileContact::evaluate(double t, const mbs::BodyFrame& f) const {
  Eval e{0, 0, 0, wire_rate(t), mbs::point_kinematics(f, u_)};
  e.delta = e.p.r.y() - wire_height(t);
  e.delta_dot = e.p.v.y() - e.yw_dot;
  e.F = e.delta > 0 ? std::max(0.0, ks_ * e.delta + cs_ * e.delta_dot) : 0.0;
  return e;
}

void ProfileContact::add(const mbs::Model& model, double t, const mbs::State&, mbs::Workspace& ws) const {
  const Eval e = evaluate(t, ws.frame(body_));
  if (e.F == 0) return;
  const int a = model.q_adr(body_);
  ws.Q[a + 1] -= e.F;  // down on the contact point: G_Pᵀ (0, −F)
  ws.Q[a + 2] -= e.p.Atu.y() * e.F;
}

double ProfileContact::energy(const mbs::Model& model, double t, const mbs::State& x) const {
  const Eval e = evaluate(t, model.frame(x, body_));
  return e.delta > 0 ? 0.5 * ks_ * e.delta * e.delta : 0.0;
}

double ProfileContact::power(const mbs::Model& model, double t, const mbs::State& x) const {
  // Power on the body −F ẏ_P, less −d(½ k δ²)/dt = −k δ (ẏ_P − ẏ_w): damping, clipping and the moving wire.
  const Eval e = evaluate(t, model.frame(x, body_));
  if (e.delta <= 0) return 0.0;
  return -(e.F - ks_ * e.delta) * e.p.v.y() - ks_ * e.delta * e.yw_dot;
}

double ProfileContact::force(const mbs::Model&, double t, const mbs::State&, const mbs::Workspace& ws) const {
  return evaluate(t, ws.frame(body_)).F;
}

double ProfileContact::length(const mbs::Model& model, const mbs::State& x) const {
  // At rest (t = 0): the overlap with the wire at the starting point.
  return evaluate(0.0, model.frame(x, body_)).delta;
}

// The catenary type ----------------------------------------------------------------------------
WireProfileCatenary::WireProfileCatenary(WireProfile profile) : p_(std::move(profile)) {
  using Ends = numerics::CubicSpline::Ends;
  h_ = std::make_shared<numerics::CubicSpline>(p_.x, p_.h, p_.periodic ? Ends::Periodic : Ends::Natural);
  if (p_.span < 0 || !std::isfinite(p_.span))
    throw InvalidArgument(fmt::format("wire profile: span must be > 0 m, got {}", p_.span));
  if (p_.span > 0)
    span_ = p_.span;
  else if (p_.periodic)
    span_ = p_.x.back() - p_.x.front();
  else
    throw InvalidArgument("wire profile: a profile that does not repeat needs its span (m) for the statistics windows");
}

std::string WireProfileCatenary::describe() const {
  auto [lo, hi] = std::minmax_element(p_.h.begin(), p_.h.end());
  return fmt::format("wire profile: {} points over {:g} m{}, heights {:.4g} … {:.4g} m (mean {:.4g} m), span {:g} m",
                     p_.x.size(), p_.x.back() - p_.x.front(), p_.periodic ? " (repeating)" : "", *lo, *hi, h_->mean(),
                     span_);
}

std::shared_ptr<const Catenary> WireProfileCatenary::mean() const {
  WireProfile flat;
  flat.x = {p_.x.front(), p_.x.back()};
  flat.h = {h_->mean(), h_->mean()};
  flat.periodic = true;
  flat.span = span_;
  return std::make_shared<WireProfileCatenary>(flat);
}

std::unique_ptr<Coupled> WireProfileCatenary::make_coupled(const std::vector<PantographOnLine>& pantographs,
                                                           double speed) const {
  std::vector<EmbeddedCoupled::Part> parts;
  for (std::size_t k = 0; k < pantographs.size(); ++k) {
    const PantographOnLine& p = pantographs[k];
    if (p.contact.kind != Contact::Kind::Penalty)
      throw ModelError(fmt::format(
          "pantograph {}: the wire-profile catenary is a rigid wire; it needs a penalty contact (contact: {{type: "
          "penalty, stiffness: ...}}), not a bilateral one",
          k + 1));
    mbs::Model m = p.pantograph.model;
    if (p.pantograph.rig_joint >= 0) m.remove_joint(m.joints[static_cast<std::size_t>(p.pantograph.rig_joint)].name);
    std::erase_if(m.outputs, [](const mbs::Output& o) { return o.name == "F_contact"; });
    m.finalize();
    const mbs::State x = mbs::assemble(m, 0.0);
    const mbs::Marker point = p.pantograph.contact();
    const double y0 = mbs::point_kinematics(m.frame(x, point.body), point.u).r.y();
    if (!p_.periodic && (p.x0 < h_->x_min() || p.x0 > h_->x_max()))
      throw ModelError(fmt::format("pantograph {}: x0 = {:g} m is outside the wire profile [{:g}, {:g}] m", k + 1, p.x0,
                                   h_->x_min(), h_->x_max()));
    // The wire touches the contact point's assembled position at the start.
    m.forces.push_back(std::make_shared<ProfileContact>("contact", point.body, point.u, h_, p.x0, speed,
                                                        y0 - h_->value(p.x0), p.contact.stiffness, p.contact.damping));
    mbs::Output F;
    F.name = "F_contact";
    F.kind = mbs::Output::Kind::ElementForce;
    F.index = static_cast<int>(m.forces.size()) - 1;
    m.outputs.push_back(F);
    m.finalize();
    parts.push_back({std::move(m), F, false, p.x0});
  }
  return std::make_unique<EmbeddedCoupled>(std::move(parts), speed, span_);
}

}  // namespace inerta::catenary
