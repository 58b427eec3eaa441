// Model files: joints (planar and spatial) and the assembly's held coordinates
// (docs/model-format.md#joints, #assembly). Each joint type is one registry line below.
#include "model_joints.hpp"

#include <fmt/format.h>

#include "inerta/mbs/spatial.hpp"

namespace inerta::io::detail {

using mbs::Vec3;

namespace {

// Planar -----------------------------------------------------------------------------------------

// revolute and prismatic: markers [i.P, j.P]; a prismatic joint's axis (body i's frame) and the
// tabulated relative angle θ0.
void pin_or_slider(const JointSite& s, mbs::JointType type) {
  const Loader& ld = s.ld;
  mbs::Joint& jt = s.joint;
  auto [mi, mj] = ld.marker_pair(s.node, s.what);
  jt.type = type;
  jt.body_i = ld.mk(mi).body, jt.body_j = ld.mk(mj).body;
  jt.u_i = ld.mk(mi).u, jt.u_j = ld.mk(mj).u;
  if (type == mbs::JointType::Prismatic) {
    jt.axis = ld.rd.vec2(ld.rd.need(s.node, "axis", s.what), "axis");
    if (!(jt.axis.norm() > 0)) ld.rd.fail(s.node["axis"], "axis", "must be a non-zero vector");
    jt.axis.normalize();
    jt.theta0 = ld.q_of(s.q_tabulated, jt.body_j).z() - ld.q_of(s.q_tabulated, jt.body_i).z();
  }
}
void revolute(const JointSite& s) { pin_or_slider(s, mbs::JointType::Revolute); }
void prismatic(const JointSite& s) { pin_or_slider(s, mbs::JointType::Prismatic); }

// `bodies: [i, j]` of a fixed joint.
void fixed_bodies(const JointSite& s) {
  YAML::Node bs = s.ld.rd.need(s.node, "bodies", s.what);
  if (!bs.IsSequence() || bs.size() != 2) s.ld.rd.fail(bs, "bodies", "expected a list of two bodies [body_i, body_j]");
  s.joint.type = mbs::JointType::Fixed;
  s.joint.body_i = s.ld.body(bs[0], "bodies"), s.joint.body_j = s.ld.body(bs[1], "bodies");
}

// Locks the tabulated relative pose (eq. 6.28): j's centre in i's frame and the relative angle.
void fixed(const JointSite& s) {
  fixed_bodies(s);
  mbs::Joint& jt = s.joint;
  Vec3 qi = s.ld.q_of(s.q_tabulated, jt.body_i), qj = s.ld.q_of(s.q_tabulated, jt.body_j);
  jt.u_i = mbs::rotate(-qi.z(), qj.head<2>() - qi.head<2>());
  jt.theta0 = qj.z() - qi.z();
}

// The driven body or marker of a driving joint (body_j and its point); the marker's index, −1 for a body.
int driven(const JointSite& s) {
  const Loader& ld = s.ld;
  mbs::Joint& jt = s.joint;
  jt.type = mbs::JointType::Driving;
  if (s.node["marker"].IsDefined() == s.node["body"].IsDefined())
    ld.rd.fail(s.node, s.what, "give either body (a body coordinate) or marker (a point coordinate)");
  if (s.node["body"].IsDefined()) {
    jt.body_j = ld.body(s.node["body"], "body");
    if (jt.body_j < 0) ld.rd.fail(s.node["body"], "body", "ground cannot be driven");
    return -1;
  }
  const int m = ld.marker(s.node["marker"], "marker");
  jt.body_j = ld.mk(m).body, jt.u_j = ld.mk(m).u, jt.p_j = ld.mk(m).u3;
  if (jt.body_j < 0) ld.rd.fail(s.node["marker"], "marker", "a ground marker cannot be driven");
  return m;
}

// coordinate = tabulated value + motion(t).
void driving(const JointSite& s) {
  const Reader& rd = s.ld.rd;
  mbs::Joint& jt = s.joint;
  const std::string c = rd.text(s.node, "coordinate", s.what);
  if (driven(s) < 0) {
    if (c != "x" && c != "y" && c != "theta") rd.fail(s.node["coordinate"], "coordinate", "expected x, y or theta");
  } else if (c != "x" && c != "y") {
    rd.fail(s.node["coordinate"], "coordinate", "expected x or y for a point");
  }
  jt.component = c == "x" ? 0 : c == "y" ? 1 : 2;
  Vec3 qj = s.ld.q_of(s.q_tabulated, jt.body_j);
  jt.value0 = jt.component == 2 ? qj.z() : (qj.head<2>() + mbs::rotate(qj.z(), jt.u_j))[jt.component];
  jt.motion = time_function(rd, rd.need(s.node, "motion", s.what), "motion", true);
}

// Spatial (mbs::evaluate_joint_3d): axes are global directions at the tabulated configuration ------

mbs::Mat3 A0(const Loader& ld, int b) {
  return b < 0 ? mbs::Mat3::Identity() : mbs::rotation(ld.model.bodies[static_cast<std::size_t>(b)].q0s.tail<4>());
}
Vec3 R0(const Loader& ld, int b) {
  return b < 0 ? Vec3::Zero() : Vec3(ld.model.bodies[static_cast<std::size_t>(b)].q0s.head<3>());
}

void point_joint_3d(const JointSite& s, mbs::JointType type) {
  const Loader& ld = s.ld;
  mbs::Joint& jt = s.joint;
  auto [mi, mj] = ld.marker_pair(s.node, s.what);
  jt.type = type;
  jt.body_i = ld.mk(mi).body, jt.body_j = ld.mk(mj).body;
  jt.p_i = ld.mk(mi).u3, jt.p_j = ld.mk(mj).u3;
  if (type == mbs::JointType::Spherical) return;
  const Vec3 a = ld.rd.unit3(ld.rd.need(s.node, "axis", s.what), "axis");
  Eigen::Index k = 0;
  a.cwiseAbs().minCoeff(&k);  // the least-aligned global axis
  const Vec3 h1 = a.cross(Vec3::Unit(k)).normalized(), h2 = a.cross(h1);
  const mbs::Mat3 Ai = A0(ld, jt.body_i), Aj = A0(ld, jt.body_j);
  jt.a_i[0] = Ai.transpose() * h1, jt.a_i[1] = Ai.transpose() * h2;
  jt.a_j[0] = Aj.transpose() * a, jt.a_j[1] = Aj.transpose() * h2;
}
void spherical_3d(const JointSite& s) { point_joint_3d(s, mbs::JointType::Spherical); }
void revolute_3d(const JointSite& s) { point_joint_3d(s, mbs::JointType::Revolute); }
void prismatic_3d(const JointSite& s) { point_joint_3d(s, mbs::JointType::Prismatic); }

void fixed_3d(const JointSite& s) {
  fixed_bodies(s);
  mbs::Joint& jt = s.joint;
  const mbs::Mat3 Ai = A0(s.ld, jt.body_i), Aj = A0(s.ld, jt.body_j);
  jt.p_i = Ai.transpose() * (R0(s.ld, jt.body_j) - R0(s.ld, jt.body_i));  // j's centre in i's frame
  for (int k = 0; k < 3; ++k) jt.a_i[k] = Ai.transpose().col(k), jt.a_j[k] = Aj.transpose().col(k);
}

void driving_3d(const JointSite& s) {
  const Reader& rd = s.ld.rd;
  mbs::Joint& jt = s.joint;
  const std::string c = rd.text(s.node, "coordinate", s.what);
  driven(s);
  if (c != "x" && c != "y" && c != "z")
    rd.fail(s.node["coordinate"], "coordinate", "expected x, y or z (a 3D model drives point coordinates)");
  jt.component = c == "x" ? 0 : c == "y" ? 1 : 2;
  jt.value0 = (R0(s.ld, jt.body_j) + A0(s.ld, jt.body_j) * jt.p_j)[jt.component];
  jt.motion = time_function(rd, rd.need(s.node, "motion", s.what), "motion", true);
}

const std::vector<std::string> kDrivingKeys{"body", "marker", "coordinate", "motion"};

}  // namespace

const JointRegistry& joint_types(bool spatial) {
  static const JointRegistry planar = [] {
    JointRegistry r("joint");
    r.add("revolute", {"markers"}, revolute)
        .add("prismatic", {"markers", "axis"}, prismatic)
        .add("fixed", {"bodies"}, fixed)
        .add("driving", kDrivingKeys, driving);
    return r;
  }();
  static const JointRegistry spatial3 = [] {
    JointRegistry r("joint");
    r.add("spherical", {"markers"}, spherical_3d)
        .add("revolute", {"markers", "axis"}, revolute_3d)
        .add("prismatic", {"markers", "axis"}, prismatic_3d)
        .add("fixed", {"bodies"}, fixed_3d)
        .add("driving", kDrivingKeys, driving_3d);
    return r;
  }();
  return spatial ? spatial3 : planar;
}

void Loader::joints(const YAML::Node& n) {
  if (!n.IsDefined()) return;
  if (!n.IsSequence()) rd.fail(n, "joints", "expected a list of joints");
  names_unique(n, "joint");
  const Eigen::VectorXd q = model.q0();
  const JointRegistry& types = joint_types(model.spatial());
  for (const auto& j : n) {
    mbs::Joint jt;
    jt.name = rd.text(j, "name", "joint");
    const std::string what = "joint '" + jt.name + "'";
    types.entry(rd, j, what).build({*this, j, what, q, jt});
    if (jt.type != mbs::JointType::Driving && jt.body_i == jt.body_j)
      rd.fail(j, what,
              jt.body_i < 0 ? "joins ground to ground; expected at least one body"
                            : "joins a body to itself; expected two different bodies");
    model.joints.push_back(jt);
  }
}

void Loader::assembly(const YAML::Node& n) {
  if (!n.IsDefined()) return;
  rd.keys(n, "assembly", {"hold"});
  YAML::Node h = n["hold"];
  if (!h.IsDefined()) return;
  if (!h.IsSequence()) rd.fail(h, "hold", "expected a list of coordinates such as [bar1.theta]");
  for (const auto& c : h) {
    std::string s = rd.text(c, "hold");
    int k = -1;
    for (int i = 0; i < model.n_coords(); ++i)
      if (model.coord_name(i) == s) k = i;
    if (k < 0)
      rd.fail(c, "hold",
              fmt::format(
                  "unknown coordinate '{}'; expected {}", s,
                  model.spatial() ? "body.x, body.y, body.z or body.e0 … body.e3" : "body.x, body.y or body.theta"));
    model.held.push_back(k);
  }
}

}  // namespace inerta::io::detail
