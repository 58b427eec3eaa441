// Model files: force elements (docs/model-format.md#force-elements). Each type is a builder below
// and one line of the registry at the end of this file; the element constructors check the
// physical values (InvalidArgument, reported with file:line by Reader::guard), the builders only
// what is about the file (markers, joints, "initial", network text).
#include "model_forces.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <memory>
#include <numbers>

#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/mbs/parameter_check.hpp"
#include "inerta/mbs/struts.hpp"
#include "inerta/network/layouts.hpp"

namespace inerta::io::detail {

using mbs::Vec2;
using mbs::Vec3;

namespace {

// Struts: spring, damper, inerter, axial_force, network, actuator ----------------------------------

struct Terminals {
  int bi, bj;
  mbs::StrutEnd ui, uj;
  double l_init;  ///< length in the assembled initial configuration
};

// `markers: [i.P, j.P]` of a strut; the terminals must not coincide initially.
Terminals terminals(const ForceSite& s) {
  const Loader& ld = s.ld;
  auto [mi, mj] = ld.marker_pair(s.node, s.what);
  auto end = [&](int m) { return ld.model.spatial() ? mbs::StrutEnd(ld.mk(m).u3) : mbs::StrutEnd(ld.mk(m).u); };
  Terminals t{ld.mk(mi).body, ld.mk(mj).body, end(mi), end(mj), 0.0};
  // A zero-force probe: its constructor checks the terminals (two bodies), and it measures l.
  t.l_init = mbs::AxialForce(s.name, t.bi, t.ui, t.bj, t.uj, 0.0).length(ld.model, s.x0);
  if (!(t.l_init > 0))
    ld.rd.fail(s.node["markers"], "markers", "the terminals coincide in the initial configuration (zero length)");
  return t;
}

// `free_length`: a number or `initial` (the default).
double free_length(const ForceSite& s, double l_init) {
  const YAML::Node fl = s.node["free_length"];
  if (!fl.IsDefined() || (fl.IsScalar() && fl.Scalar() == "initial")) return l_init;
  return s.ld.rd.number(fl, "free_length");
}

bool centripetal(const ForceSite& s) {
  const YAML::Node c = s.node["centripetal"];
  return c.IsDefined() ? s.ld.rd.boolean(c, "centripetal") : true;
}

void spring(const ForceSite& s) {  // eqs. 3.1, 3.5
  const Terminals t = terminals(s);
  const double L0 = free_length(s, t.l_init), k = s.ld.rd.number(s.node, "k", s.what);
  s.ld.model.forces.push_back(std::make_shared<mbs::Spring>(s.name, t.bi, t.ui, t.bj, t.uj, k, L0));
}

void damper(const ForceSite& s) {  // eqs. 3.2, 3.6–3.7
  const Terminals t = terminals(s);
  const double c = s.ld.rd.number(s.node, "c", s.what);
  s.ld.model.forces.push_back(std::make_shared<mbs::Damper>(s.name, t.bi, t.ui, t.bj, t.uj, c));
}

void inerter(const ForceSite& s) {  // eq. 3.20
  const Terminals t = terminals(s);
  const bool corr = centripetal(s);
  const double b = s.ld.rd.number(s.node, "b", s.what);
  s.ld.model.forces.push_back(std::make_shared<mbs::Inerter>(s.name, t.bi, t.ui, t.bj, t.uj, b, corr));
}

void axial_force(const ForceSite& s) {
  const Terminals t = terminals(s);
  const double F = s.ld.rd.number(s.node, "force", s.what);
  s.ld.model.forces.push_back(std::make_shared<mbs::AxialForce>(s.name, t.bi, t.ui, t.bj, t.uj, F));
}

// `params`: element: value, with inf / .inf (any case) for a rigid element.
network::Params network_params(const Reader& rd, const YAML::Node& p) {
  network::Params params;
  if (!p.IsDefined()) return params;
  if (!p.IsMap()) rd.fail(p, "params", "expected a mapping element: value, e.g. {b: 10, k: 100}");
  for (auto it = p.begin(); it != p.end(); ++it) {
    std::string k = rd.text(it->first, "params");
    if (params.count(k)) rd.fail(it->first, k, "duplicate element in params; give each value once");
    const YAML::Node v = it->second;
    std::string lower = v.IsScalar() ? v.Scalar() : "";
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    params[k] = lower == "inf" || lower == ".inf" ? INFINITY : rd.number(v, k);
  }
  return params;
}

// A network strut or an actuator (spec/03): the network by layout name or expression, values in
// `params`; an open network stays as a zero-force strut and a rigid one becomes a distance joint
// (both noted).
void strut_network(const ForceSite& s, bool act) {
  const Reader& rd = s.ld.rd;
  mbs::Model& model = s.ld.model;
  const YAML::Node& f = s.node;
  if (act && model.spatial())
    rd.fail(f["type"], "type", "the actuator (piston mass, friction) is planar only; use a network strut in 3D");
  const Terminals t = terminals(s);
  const double l_ref = free_length(s, t.l_init);
  const YAML::Node nn = f["network"];
  const std::string text = act && !nn.IsDefined() ? "S2-default" : rd.text(rd.need(f, "network", s.what), "network");
  const network::Params params = network_params(rd, f["params"]);
  network::Network net;
  try {
    net = network::simplify(network::resolve(text, params));
  } catch (const network::NetworkError& e) {
    YAML::Node at = e.column > 0 || !f["params"].IsDefined() ? (nn.IsDefined() ? nn : f) : f["params"];
    rd.fail(at, e.column > 0 ? "network" : "params",
            e.column > 0 ? fmt::format("'{}': {}", text, e.what()) : fmt::format("network '{}': {}", text, e.what()));
  }
  const bool corr = centripetal(s);
  mbs::Actuator::Params ap;  // checked by the constructor
  if (act) {
    ap.constant_force = rd.number_or(f, "constant_force", 0.0);
    ap.piston_mass = rd.number_or(f, "piston_mass", 0.0);
    ap.friction = rd.number_or(f, "friction", 0.0);
    ap.friction_velocity = rd.number_or(f, "friction_velocity", 1e-3);
  }
  if (net.kind == network::Network::Kind::Rigid) {
    if (act)
      rd.fail(f, s.what,
              fmt::format("the actuator's network '{}' is rigid with these values; expected a network with finite "
                          "values (a rigid actuator would lock the mechanism)",
                          text));
    mbs::check::nonnegative({"network strut", s.name}, "free_length", l_ref, "m");  // as NetworkStrut checks it
    mbs::Joint jt;
    jt.name = s.name;
    jt.type = mbs::JointType::Distance;
    jt.body_i = t.bi, jt.body_j = t.bj, jt.u_i = t.ui.u.head<2>(), jt.u_j = t.uj.u.head<2>(), jt.length0 = l_ref;
    jt.p_i = t.ui.u, jt.p_j = t.uj.u;
    model.joints.push_back(jt);
    model.notes.push_back(
        fmt::format("{}: network '{}' is rigid with these values; it is a distance joint '{}'", s.what, text, s.name));
    return;
  }
  if (net.kind == network::Network::Kind::Open) {
    model.notes.push_back(fmt::format("{}: network '{}' is open with these values; it exerts {}", s.what, text,
                                      act ? "only the actuator's constant force, friction and piston mass" : "no force"));
    net = network::Network{network::Network::Kind::Damper, "c", 0.0, {}, 0};  // exerts no force
  }
  if (act) {
    model.actuators.push_back(static_cast<int>(model.forces.size()));
    model.forces.push_back(
        std::make_shared<mbs::Actuator>(s.name, t.bi, t.ui.u.head<2>(), t.bj, t.uj.u.head<2>(), net, l_ref, ap, corr));
  } else
    model.forces.push_back(std::make_shared<mbs::NetworkStrut>(s.name, t.bi, t.ui, t.bj, t.uj, net, l_ref, corr));
}
void network_strut(const ForceSite& s) { strut_network(s, false); }
void actuator(const ForceSite& s) { strut_network(s, true); }

// Rotational spring / damper at a revolute joint (spec/02 §2.3) --------------------------------------

// 3D: reference directions of the joint's relative angle at the assembled configuration.
mbs::RotationalSpringDamper::Spatial revolute_angle(const mbs::Joint& jt, const Eigen::VectorXd& q) {
  auto quat = [&](int b) {
    if (b < 0) return Eigen::Quaterniond::Identity();
    const auto p = q.segment<4>(7 * b + 3);
    return Eigen::Quaterniond(p[0], p[1], p[2], p[3]).normalized();
  };
  mbs::RotationalSpringDamper::Spatial sp;
  sp.s_i = jt.a_i[0].cross(jt.a_i[1]);
  sp.h_i = jt.a_i[0];
  const Eigen::Quaterniond qi = quat(jt.body_i), qj = quat(jt.body_j), rel = qi.conjugate() * qj;
  sp.h_j = (qj.conjugate() * qi) * sp.h_i;  // equal to h_i in space now
  sp.angle_init = std::remainder(2 * std::atan2(sp.s_i.dot(rel.vec()), rel.w()), 2 * std::numbers::pi);
  return sp;
}

// Moment −k (Δθ − Δθ0) − c Δθ̇ on body j of the revolute joint `joint`.
void rotational(const ForceSite& s, bool with_spring, bool c_required) {
  const Loader& ld = s.ld;
  const Reader& rd = ld.rd;
  mbs::Model& model = s.ld.model;
  const YAML::Node& f = s.node;
  const std::string jn = rd.text(f, "joint", s.what);
  const int ji = model.find_joint(jn);
  if (ji < 0) rd.fail(f["joint"], "joint", fmt::format("unknown joint '{}'", jn));
  const mbs::Joint& jt = model.joints[static_cast<std::size_t>(ji)];
  if (jt.type != mbs::JointType::Revolute)
    rd.fail(f["joint"], "joint", fmt::format("joint '{}' is not revolute; expected a revolute joint", jn));
  const double k = with_spring ? rd.number(f, "k", s.what) : 0.0;
  const double c = c_required ? rd.number(f, "c", s.what) : rd.number_or(f, "c", 0.0);
  const Eigen::VectorXd& q = s.x0.q;
  mbs::RotationalSpringDamper::Spatial sp;
  if (model.spatial()) sp = revolute_angle(jt, q);
  const double a_init = model.spatial() ? sp.angle_init : ld.q_of(q, jt.body_j).z() - ld.q_of(q, jt.body_i).z();
  double a0 = a_init;
  if (f["angle0"].IsDefined() && f["angle0"].IsScalar() && f["angle0"].Scalar() == "initial") {
    if (f["angle0_deg"].IsDefined())
      rd.fail(f["angle0_deg"], "angle0_deg", "give either angle0 or angle0_deg, not both");
  } else {
    a0 = rd.angle(f, "angle0", a_init);
  }
  if (model.spatial())
    model.forces.push_back(std::make_shared<mbs::RotationalSpringDamper>(s.name, jt.body_i, jt.body_j, k, a0, c, sp));
  else
    model.forces.push_back(std::make_shared<mbs::RotationalSpringDamper>(s.name, jt.body_i, jt.body_j, k, a0, c));
}
void rotational_spring(const ForceSite& s) { rotational(s, true, false); }
void rotational_damper(const ForceSite& s) { rotational(s, false, true); }
void rotational_spring_damper(const ForceSite& s) { rotational(s, true, true); }

// Applied loads --------------------------------------------------------------------------------------

void point_force(const ForceSite& s) {
  const Loader& ld = s.ld;
  const Reader& rd = ld.rd;
  const int m = ld.marker(rd.need(s.node, "marker", s.what), "marker");
  if (ld.mk(m).body < 0)
    rd.fail(s.node["marker"], "marker", "a force on a ground marker does nothing; expected a body's marker");
  const YAML::Node d = rd.need(s.node, "direction", s.what);
  if (ld.model.spatial()) {
    const Vec3 d3 = rd.vec3(d, "direction").normalized();  // the constructor checks and normalises
    s.ld.model.forces.push_back(std::make_shared<mbs::PointForce>(
        s.name, ld.mk(m).body, ld.mk(m).u3, d3, time_function(rd, rd.need(s.node, "value", s.what), "value"),
        std::true_type{}));
    return;
  }
  const Vec2 d2 = rd.vec2(d, "direction");
  s.ld.model.forces.push_back(std::make_shared<mbs::PointForce>(
      s.name, ld.mk(m).body, ld.mk(m).u, d2, time_function(rd, rd.need(s.node, "value", s.what), "value")));
}

void point_torque(const ForceSite& s) {
  const Loader& ld = s.ld;
  const Reader& rd = ld.rd;
  if (!ld.model.spatial()) rd.fail(s.node["type"], "type", "point_torque is for 3D models (dimension: 3)");
  const int b = ld.body(rd.need(s.node, "body", s.what), "body");
  if (b < 0) rd.fail(s.node["body"], "body", "a torque on ground does nothing; expected a body");
  const Vec3 axis = rd.vec3(rd.need(s.node, "axis", s.what), "axis").normalized();  // checked by the constructor
  s.ld.model.forces.push_back(
      std::make_shared<mbs::PointTorque>(s.name, b, axis, time_function(rd, rd.need(s.node, "value", s.what), "value")));
}

}  // namespace

// The registry: one line per type (type, accepted keys besides name and type, builder[, hint]).
const ForceRegistry& force_element_types() {
  static const ForceRegistry registry = [] {
    ForceRegistry r("force element");
    r.add("spring", {"markers", "k", "free_length"}, spring)
        .add("damper", {"markers", "c"}, damper)
        .add("inerter", {"markers", "b", "centripetal"}, inerter)
        .add("axial_force", {"markers", "force"}, axial_force)
        .add("network", {"markers", "network", "params", "free_length", "centripetal"}, network_strut)
        .add("actuator",
             {"markers", "network", "params", "free_length", "centripetal", "constant_force", "piston_mass", "friction",
              "friction_velocity"},
             actuator)
        .add("rotational_spring", {"joint", "k", "c", "angle0", "angle0_deg"}, rotational_spring)
        .add("rotational_damper", {"joint", "c"}, rotational_damper,
             "a rotational_damper takes only c; use rotational_spring_damper for both")
        .add("rotational_spring_damper", {"joint", "k", "c", "angle0", "angle0_deg"}, rotational_spring_damper)
        .add("point_force", {"marker", "direction", "value"}, point_force)
        .add("point_torque", {"body", "axis", "value"}, point_torque);
    return r;
  }();
  return registry;
}

void Loader::forces(const YAML::Node& n, const Eigen::VectorXd& q_init) {
  if (model.options.gravity)
    model.forces.push_back(model.spatial() ? std::make_shared<mbs::Gravity>(model.options.g3)
                                           : std::make_shared<mbs::Gravity>(model.options.g));
  if (!n.IsDefined()) return;
  if (!n.IsSequence()) rd.fail(n, "forces", "expected a list of force elements");
  names_unique(n, "force element");
  const mbs::State x0{q_init, Eigen::VectorXd::Zero(q_init.size()), {}};
  const ForceRegistry& types = force_element_types();
  for (const auto& f : n) {
    const std::string name = rd.text(f, "name", "force element");
    if (name == "gravity") rd.fail(f["name"], "name", "'gravity' is reserved (switch it in options)");
    const std::string what = "force element '" + name + "'";
    const ForceRegistry::Entry& type = types.entry(rd, f, what);
    rd.guard(f, what, [&] { type.build({*this, f, name, what, x0}); });
  }
}

}  // namespace inerta::io::detail
