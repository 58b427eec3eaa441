#include "inerta/catenary/lumped.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "inerta/catenary/embedded.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
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

void LumpedCatenary::validate() const {
  for (const auto* a : {&k, &m, &c})
    for (double v : *a)
      if (!std::isfinite(v)) throw InvalidArgument("lumped catenary: every coefficient must be a finite number");
  if (!(span > 0) || !std::isfinite(span))
    throw InvalidArgument(fmt::format("lumped catenary: span must be > 0 (m), got {}", span));
  if (!(m[0] > 0)) throw InvalidArgument(fmt::format("lumped catenary: mc0 must be > 0 (kg), got {}", m[0]));
  if (!(k[0] > 0)) throw InvalidArgument(fmt::format("lumped catenary: kc0 must be > 0 (N/m), got {}", k[0]));
  if (c[0] < 0) throw InvalidArgument(fmt::format("lumped catenary: cc0 must be >= 0 (N·s/m), got {}", c[0]));
  // The coefficients must stay positive over a span (|first harmonics| bounded by the mean).
  auto positive = [](const std::array<double, 4>& a) { return a[0] > std::abs(a[1]) + std::abs(a[2]) + std::abs(a[3]); };
  if (!positive(k))
    throw InvalidArgument("lumped catenary: kc0 must exceed |kc1| + |kc2| + |kc3| (stiffness stays positive)");
  if (!positive(m)) throw InvalidArgument("lumped catenary: mc0 must exceed |mc1| + |mc2| + |mc3| (mass stays positive)");
  if (c[0] + 1e-300 < std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]))
    throw InvalidArgument("lumped catenary: cc0 must be at least |cc1| + |cc2| + |cc3| (damping stays non-negative)");
}

// The element ----------------------------------------------------------------------------------
CatenaryElement::CatenaryElement(std::string name, int wire_y, LumpedCatenary cat, double speed, double y_unloaded)
    : ForceElement(std::move(name)), iy_(wire_y), cat_(cat), v_(speed), y0_(y_unloaded) {
  cat_.validate();
  if (!(speed >= 0) || !std::isfinite(speed))
    throw InvalidArgument(fmt::format("catenary element: speed must be >= 0 m/s, got {}", speed));
}

void CatenaryElement::add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const {
  const double fp = pumping_frequency();
  const double y = x.q[iy_] - y0_, yd = x.qd[iy_];
  // eq. 7.1: the body carries m_c0; the harmonics of the mass enter M, c_c(t) and k_c(t) enter Q.
  ws.M(iy_, iy_) += LumpedCatenary::harmonic(cat_.m, fp, t) - cat_.m[0];
  ws.Q[iy_] -= LumpedCatenary::harmonic(cat_.c, fp, t) * yd + LumpedCatenary::harmonic(cat_.k, fp, t) * y;
}

double CatenaryElement::energy(const mbs::Model&, double t, const mbs::State& x) const {
  const double fp = pumping_frequency();
  const double y = x.q[iy_] - y0_, yd = x.qd[iy_];
  return 0.5 * (LumpedCatenary::harmonic(cat_.m, fp, t) - cat_.m[0]) * yd * yd +
         0.5 * LumpedCatenary::harmonic(cat_.k, fp, t) * y * y;
}

double CatenaryElement::power(const mbs::Model&, double t, const mbs::State& x) const {
  // Work rate on the body not in −d(energy)/dt: damping, and the explicit time variation.
  const double fp = pumping_frequency();
  const double y = x.q[iy_] - y0_, yd = x.qd[iy_];
  return -LumpedCatenary::harmonic(cat_.c, fp, t) * yd * yd +
         0.5 * LumpedCatenary::harmonic_rate(cat_.k, fp, t) * y * y +
         0.5 * LumpedCatenary::harmonic_rate(cat_.m, fp, t) * yd * yd;
}

double CatenaryElement::force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace&) const {
  const double fp = pumping_frequency();
  return -LumpedCatenary::harmonic(cat_.c, fp, t) * x.qd[iy_] - LumpedCatenary::harmonic(cat_.k, fp, t) * (x.q[iy_] - y0_);
}

double CatenaryElement::length(const mbs::Model&, const mbs::State& x) const { return x.q[iy_] - y0_; }

// Coupling -------------------------------------------------------------------------------------
int add_catenary(mbs::Model& model, const LumpedCatenary& cat, double speed, double x, double y_unloaded) {
  if (model.spatial()) throw InvalidArgument("add_catenary: the lumped catenary is planar");
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
  model.finalize();  // the wire's coordinate address
  model.forces.push_back(
      std::make_shared<CatenaryElement>("catenary", model.q_adr(b) + 1, cat, speed, y_unloaded));
  return b;
}

LumpedCoupling couple_lumped(const pantograph::Pantograph& p, const LumpedCatenary& cat, const Contact& contact,
                             double speed) {
  LumpedCoupling c;
  c.model = p.model;
  mbs::Model& m = c.model;
  if (p.contact_marker < 0 || p.contact_marker >= static_cast<int>(m.markers.size()))
    throw ModelError(fmt::format("{}: the pantograph has no contact point to couple", m.source));
  contact.validate();
  // Remove the rig's hold of the head (and its outputs) and any earlier F_contact.
  if (p.rig_joint >= 0) m.remove_joint(m.joints[static_cast<std::size_t>(p.rig_joint)].name);
  std::erase_if(m.outputs, [](const mbs::Output& o) { return o.name == "F_contact"; });
  m.finalize();
  // The wire starts unloaded at the contact point's assembled position.
  const mbs::State x = mbs::assemble(m, 0.0);
  const mbs::Marker point = p.contact();
  const mbs::Vec2 r = mbs::point_kinematics(m.frame(x, point.body), point.u).r;
  c.wire_body = add_catenary(m, cat, speed, r.x(), r.y());
  c.wire_y = m.q_adr(c.wire_body) + 1;
  c.element = static_cast<int>(m.forces.size()) - 1;
  c.y_unloaded = r.y();
  c.bilateral = contact.kind == Contact::Kind::Bilateral;
  mbs::Output& F = c.contact_force;
  F.name = "F_contact";
  if (c.bilateral) {
    mbs::Joint j;
    j.name = "contact";
    j.type = mbs::JointType::Coupling;
    j.body_i = c.wire_body, j.u_i = mbs::Vec2::Zero();
    j.body_j = point.body, j.u_j = point.u;
    j.component = 1;
    m.joints.push_back(j);
    // C = y_P − y_wire: λ acts on the head as −λ (C_q,head = +1), so compression = λ.
    F.kind = mbs::Output::Kind::Multiplier;
    F.index = static_cast<int>(m.joints.size()) - 1;
  } else {
    m.forces.push_back(std::make_shared<PenaltyContact>("contact", point.body, point.u, c.wire_body, mbs::Vec2::Zero(),
                                                        contact.stiffness, contact.damping, 0.0));
    F.kind = mbs::Output::Kind::ElementForce;
    F.index = static_cast<int>(m.forces.size()) - 1;
  }
  m.outputs.push_back(F);
  m.finalize();
  return c;
}

// The catenary type ----------------------------------------------------------------------------
Lumped::Lumped(LumpedCatenary params) : p_(params) { p_.validate(); }

std::string Lumped::describe() const {
  return fmt::format("lumped catenary (eq. 7.1): span {:g} m, k_c0 = {:g} N/m, m_c0 = {:g} kg, c_c0 = {:g} N·s/m",
                     p_.span, p_.k[0], p_.m[0], p_.c[0]);
}

std::shared_ptr<const Catenary> Lumped::mean() const {
  LumpedCatenary m = p_;
  for (std::size_t i = 1; i <= 3; ++i) m.k[i] = m.m[i] = m.c[i] = 0;
  return std::make_shared<Lumped>(m);
}

std::unique_ptr<Coupled> Lumped::make_coupled(const std::vector<PantographOnLine>& pantographs, double speed) const {
  const PantographOnLine& p = pantographs.front();
  if (p.x0 != 0)
    throw ModelError(fmt::format("{}: the lumped catenary's pantograph starts at a mast (x0 = 0), got x0 = {:g} m",
                                 p.pantograph.model.source, p.x0));
  LumpedCoupling c = couple_lumped(p.pantograph, p_, p.contact, speed);
  std::vector<EmbeddedCoupled::Part> parts;
  parts.push_back({std::move(c.model), c.contact_force, c.bilateral, p.x0});
  return std::make_unique<EmbeddedCoupled>(std::move(parts), speed, p_.span);
}

}  // namespace inerta::catenary
