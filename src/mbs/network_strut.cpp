#include "inerta/mbs/network_strut.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/parameter_check.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

namespace {
// A network a strut can realise: simplified (neither open nor rigid, spec/03 §3.1) with finite
// element values >= 0 (0 is kept: an open network is replaced by a zero damper by the callers).
const network::Network& realisable(const check::Element& who, const network::Network& net) {
  using K = network::Network::Kind;
  if (net.kind == K::Open || net.kind == K::Rigid)
    check::fail(who, "network",
                fmt::format("is {}; expected a simplified network with a finite admittance (network::simplify; an "
                            "open network exerts no force, a rigid one is a distance joint)",
                            net.kind == K::Open ? "open" : "rigid"));
  if (net.is_element() && !(std::isfinite(net.value) && net.value >= 0))
    check::fail(who, "params", fmt::format("element '{}' = {} must be a finite number >= 0", net.name, net.value));
  for (const network::Network& c : net.children) realisable(who, c);
  return net;
}
}  // namespace

NetworkStrut::NetworkStrut(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, const network::Network& net,
                           double l_ref, bool centripetal)
    : Strut(std::move(name), bi, ui, bj, uj),
      net_(realisable({"network strut", this->name()}, net)),
      r_(network::realise(net_)),
      l_ref_(check::nonnegative({"network strut", this->name()}, "free_length", l_ref, "m")),
      centripetal_(centripetal) {}

bool NetworkStrut::centripetal(const Model& model) const { return centripetal_ && model.options.centripetal; }

double NetworkStrut::network_tension(const StrutKinematics& s, const State& x) const {
  double F = r_.d1 * s.l_dot + r_.d0 * (s.l - l_ref_);
  if (r_.n_states() > 0) F += r_.C.dot(x.z.segment(state_offset_, r_.n_states()));
  return F;
}

void NetworkStrut::add(const Model& model, double, const State& x, Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  const int n = r_.n_states();
  if (n > 0) {  // ż = A z + B u
    auto zd = ws.zd.segment(state_offset_, n);
    zd.noalias() = r_.A * x.z.segment(state_offset_, n);
    zd += r_.B * (s.l - l_ref_);
  }
  // Direct inerter d2: the q̈ part into M (eq. 3.33), the rest of d2·l̈ into Q (eq. 3.31).
  double bias = s.a_n_axial + (centripetal(model) ? s.centripetal : 0.0);
  add_tension(network_tension(s, x) + r_.d2 * bias, s, ws);
  if (r_.d2 != 0) ws.add_M(body_i(), body_j(), s.J, r_.d2);
}

double NetworkStrut::energy(const Model& model, double, const State& x) const {
  StrutKinematics s = kinematics(model, x);
  double u = s.l - l_ref_;
  return 0.5 * r_.d2 * s.l_dot * s.l_dot + 0.5 * r_.d0 * u * u;
}

double NetworkStrut::power(const Model& model, double, const State& x) const {
  // Work rate on the bodies of everything that is not in energy(): direct damper and internal states.
  StrutKinematics s = kinematics(model, x);
  double P = -(r_.d1 * s.l_dot) * s.l_dot;
  if (r_.n_states() > 0) P -= r_.C.dot(x.z.segment(state_offset_, r_.n_states())) * s.l_dot;
  if (!centripetal(model)) P += r_.d2 * s.centripetal * s.l_dot;
  return P;
}

double NetworkStrut::force(const Model& model, double, const State& x, const Workspace& ws) const {
  StrutKinematics s = kinematics(ws);
  double l_ddot = ws.J_dot_qdd(body_i(), body_j(), s.J) + s.a_n_axial + (centripetal(model) ? s.centripetal : 0.0);
  return network_tension(s, x) + r_.d2 * l_ddot;
}

void NetworkStrut::relax(const Model& model, State& x) const {
  if (r_.n_states() == 0) return;
  x.z.segment(state_offset_, r_.n_states()) = r_.steady_state(kinematics(model, x).l - l_ref_);
}

// Actuator -------------------------------------------------------------------------------------
Actuator::Actuator(std::string name, int bi, Vec2 ui, int bj, Vec2 uj, const network::Network& net, double l_ref,
                   Params p, bool centripetal)
    : NetworkStrut(std::move(name), bi, ui, bj, uj, net, l_ref, centripetal), p_(p), rod_body_(bj), rod_u_(uj) {
  const check::Element who{"actuator", this->name()};
  check::finite(who, "constant_force", p.constant_force, "N");
  check::nonnegative(who, "piston_mass", p.piston_mass, "kg");
  check::nonnegative(who, "friction", p.friction, "N");
  check::positive(who, "friction_velocity", p.friction_velocity, "m/s");
  if (p.piston_mass > 0 && bj < 0)
    check::fail(who, "piston_mass", "the rod end (second marker) is on ground; expected the rod end on a body");
}

void Actuator::add(const Model& model, double t, const State& x, Workspace& ws) const {
  NetworkStrut::add(model, t, x, ws);
  StrutKinematics s = kinematics(ws);
  double F = p_.constant_force;
  if (p_.friction > 0) F += p_.friction * std::tanh(s.l_dot / p_.friction_velocity);
  add_tension(F, s, ws);
  if (p_.piston_mass > 0 && rod_body_ >= 0) {
    // Point mass at the rod end: M += m Gᵀ G, Q += m Gᵀ (g − a_bias), G = [I, A_θ ū].
    PointKinematics pk = point_kinematics(ws.frame(rod_body_), rod_u_);
    Vec6 gx, gy;  // rows of G padded to the 6-vector of (ground, rod body)
    gx << 0, 0, 0, 1, 0, pk.Atu.x();
    gy << 0, 0, 0, 0, 1, pk.Atu.y();
    ws.add_M(kGround, rod_body_, gx, p_.piston_mass);
    ws.add_M(kGround, rod_body_, gy, p_.piston_mass);
    Vec2 f = -p_.piston_mass * pk.a_bias;
    if (model.options.gravity) f += p_.piston_mass * model.options.g;
    ws.add_Q(kGround, rod_body_, f.x() * gx + f.y() * gy);
  }
}

double Actuator::energy(const Model& model, double t, const State& x) const {
  double E = NetworkStrut::energy(model, t, x) + p_.constant_force * kinematics(model, x).l;
  if (p_.piston_mass > 0 && rod_body_ >= 0) {
    PointKinematics pk = point_kinematics(model.frame(x, rod_body_), rod_u_);
    E += 0.5 * p_.piston_mass * pk.v.squaredNorm();
    if (model.options.gravity) E -= p_.piston_mass * model.options.g.dot(pk.r);
  }
  return E;
}

double Actuator::power(const Model& model, double t, const State& x) const {
  double P = NetworkStrut::power(model, t, x);
  if (p_.friction > 0) {
    double ld = kinematics(model, x).l_dot;
    P -= p_.friction * std::tanh(ld / p_.friction_velocity) * ld;
  }
  return P;
}

double Actuator::force(const Model& model, double t, const State& x, const Workspace& ws) const {
  double F = NetworkStrut::force(model, t, x, ws) + p_.constant_force;
  if (p_.friction > 0) F += p_.friction * std::tanh(kinematics(ws).l_dot / p_.friction_velocity);
  return F;
}

// The compile step's relocation (Model::finalize): a copy with its states at `offset`.
std::shared_ptr<const ForceElement> NetworkStrut::with_state_offset(int offset) const {
  auto c = std::make_shared<NetworkStrut>(*this);
  c->state_offset_ = offset;
  return c;
}
void NetworkStrut::replace_network(const network::Network& net, double reference_length) {
  net_ = realisable({"network strut", name()}, net);
  r_ = network::realise(net_);
  if (!std::isnan(reference_length)) l_ref_ = check::nonnegative({"network strut", name()}, "free_length", reference_length, "m");
}
std::shared_ptr<const ForceElement> NetworkStrut::with_network(const network::Network& net, double reference_length) const {
  auto c = std::make_shared<NetworkStrut>(*this);
  c->replace_network(net, reference_length);
  return c;
}
std::shared_ptr<const ForceElement> Actuator::with_network(const network::Network& net, double reference_length) const {
  auto c = std::make_shared<Actuator>(*this);
  c->replace_network(net, reference_length);
  return c;
}
std::shared_ptr<const ForceElement> Actuator::with_state_offset(int offset) const {
  auto c = std::make_shared<Actuator>(*this);
  c->state_offset_ = offset;
  return c;
}

}  // namespace inerta::mbs
