#include "inerta/io/model_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/mbs/struts.hpp"
#include "inerta/network/layouts.hpp"

namespace inerta::io {

using mbs::Vec2;
using mbs::Vec3;

namespace {

// Reading helpers that turn every problem into "file:line: key: what; expected ...".
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& what) const {
    std::string where = file_;
    if (at.IsDefined() && at.Mark().line >= 0) where += fmt::format(":{}", at.Mark().line + 1);
    throw ModelError(fmt::format("{}: {}{}", where, key.empty() ? "" : "'" + key + "': ", what));
  }

  void keys(const YAML::Node& map, const std::string& what, std::initializer_list<const char*> allowed) const {
    if (!map.IsMap()) fail(map, what, "expected a mapping (key: value pairs)");
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      if (!it->first.IsScalar()) fail(it->first, what, "expected a plain key (a name)");
      std::string k = it->first.Scalar();
      if (!seen.insert(k).second) fail(it->first, k, fmt::format("duplicate key in {}; give each key once", what));
      bool ok = false;
      for (const char* a : allowed) ok = ok || k == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        fail(it->first, k, fmt::format("unknown key in {}; expected one of: {}", what, list));
      }
    }
  }

  YAML::Node need(const YAML::Node& map, const char* key, const std::string& what) const {
    YAML::Node n = map[key];
    if (!n.IsDefined() || n.IsNull()) fail(map, key, fmt::format("missing in {}", what));
    return n;
  }

  double number(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, key, "expected a number");
    try {
      return n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, key, fmt::format("expected a number, got '{}'", n.Scalar()));
    }
  }
  double number(const YAML::Node& map, const char* key, const std::string& what) const {
    return number(need(map, key, what), key);
  }
  double number_or(const YAML::Node& map, const char* key, double fallback) const {
    YAML::Node n = map[key];
    return n.IsDefined() && !n.IsNull() ? number(n, key) : fallback;
  }
  double nonnegative(const YAML::Node& map, const char* key, const std::string& what) const {
    double v = number(map, key, what);
    if (!(v >= 0)) fail(map[key], key, fmt::format("must be >= 0 (got {}) in {}", v, what));
    return v;
  }
  bool boolean(const YAML::Node& n, const std::string& key) const {
    try {
      return n.as<bool>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected true or false");
    }
  }
  std::string text(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, key, "expected a text value");
    return n.Scalar();
  }
  std::string text(const YAML::Node& map, const char* key, const std::string& what) const {
    return text(need(map, key, what), key);
  }
  Vec2 vec2(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected a list of two numbers [x, y]");
    return {number(n[0], key), number(n[1], key)};
  }
  Vec3 vec3(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, key, "expected a list of three numbers [x, y, z] (a 3D model)");
    return {number(n[0], key), number(n[1], key), number(n[2], key)};
  }
  Vec3 unit3(const YAML::Node& n, const std::string& key) const {
    Vec3 v = vec3(n, key);
    if (!(v.norm() > 0)) fail(n, key, "must be a non-zero vector");
    return v.normalized();
  }
  // Angle from `key` (rad) or `key_deg` (degrees), not both.
  double angle(const YAML::Node& map, const std::string& key, double fallback) const {
    YAML::Node r = map[key], d = map[key + "_deg"];
    if (r.IsDefined() && d.IsDefined())
      fail(d, key + "_deg", fmt::format("give either {} (rad) or {}_deg, not both", key, key));
    if (r.IsDefined()) return number(r, key);
    if (d.IsDefined()) return number(d, key + "_deg") * std::numbers::pi / 180.0;
    return fallback;
  }

 private:
  std::string file_;
};

mbs::TimeFunction time_function(const Reader& rd, const YAML::Node& n, const std::string& key) {
  if (n.IsScalar()) return mbs::TimeFunction::constant(rd.number(n, key));
  if (!n.IsMap()) rd.fail(n, key, "expected a number or a function {type: constant|sine|table, ...}");
  std::string type = rd.text(n, "type", key);
  if (type == "constant") {
    rd.keys(n, key + " (constant)", {"type", "value"});
    return mbs::TimeFunction::constant(rd.number(n, "value", key));
  }
  if (type == "sine") {
    rd.keys(n, key + " (sine)", {"type", "amplitude", "frequency", "phase", "phase_deg", "offset"});
    double f = rd.number(n, "frequency", key);
    if (!(f >= 0)) rd.fail(n["frequency"], "frequency", "must be >= 0 (Hz)");
    return mbs::TimeFunction::sine(rd.number(n, "amplitude", key), f, rd.angle(n, "phase", 0.0),
                                   rd.number_or(n, "offset", 0.0));
  }
  if (type == "table") {
    rd.keys(n, key + " (table)", {"type", "points"});
    YAML::Node pts = rd.need(n, "points", key);
    if (!pts.IsSequence() || pts.size() < 1) rd.fail(pts, "points", "expected a list of [t, value] pairs");
    mbs::TimeFunction f;
    f.kind = mbs::TimeFunction::Kind::Table;
    for (const auto& p : pts) {
      Vec2 tv = rd.vec2(p, "points");
      if (!f.t.empty() && !(tv.x() > f.t.back())) rd.fail(p, "points", "times must be strictly increasing");
      f.t.push_back(tv.x());
      f.v.push_back(tv.y());
    }
    return f;
  }
  rd.fail(n["type"], "type", fmt::format("unknown function type '{}'; expected constant, sine or table", type));
}

struct Loader {
  Reader rd;
  mbs::Model model;

  int marker(const YAML::Node& n, const std::string& key) const {
    std::string name = rd.text(n, key);
    int k = model.find_marker(name);
    if (k < 0) {
      auto dot = name.find('.');
      std::string body = dot == std::string::npos ? name : name.substr(0, dot);
      if (model.find_body(body) == -2)
        rd.fail(n, key, fmt::format("unknown body '{}' in marker '{}'; markers are written body.marker", body, name));
      rd.fail(
          n, key,
          fmt::format("unknown marker '{}'; define it under the body's markers (body.cm is the centre of mass)", name));
    }
    return k;
  }
  int body(const YAML::Node& n, const std::string& key) const {
    std::string name = rd.text(n, key);
    int b = model.find_body(name);
    if (b == -2) rd.fail(n, key, fmt::format("unknown body '{}'", name));
    return b;
  }
  std::pair<int, int> marker_pair(const YAML::Node& map, const std::string& what) const {
    YAML::Node m = rd.need(map, "markers", what);
    if (!m.IsSequence() || m.size() != 2)
      rd.fail(m, "markers", "expected a list of two markers [body_i.point, body_j.point]");
    return {marker(m[0], "markers"), marker(m[1], "markers")};
  }
  const mbs::Marker& mk(int k) const { return model.markers[static_cast<std::size_t>(k)]; }
  Vec3 q_of(const Eigen::VectorXd& q, int b) const { return b < 0 ? Vec3::Zero() : Vec3(q.segment<3>(3 * b)); }

  void names_unique(const YAML::Node& list, const std::string& what) const {
    std::set<std::string> seen;
    for (const auto& item : list) {
      if (!item.IsMap()) rd.fail(item, what, fmt::format("expected a mapping (key: value pairs) for each {}", what));
      std::string name = rd.text(item, "name", what);
      if (!seen.insert(name).second) rd.fail(item["name"], "name", fmt::format("duplicate {} name '{}'", what, name));
    }
  }

  void options(const YAML::Node& n) {
    if (!n.IsDefined()) return;
    rd.keys(n, "options", {"gravity", "baumgarte", "centripetal", "t_end", "sample"});
    if (YAML::Node g = n["gravity"]; g.IsDefined()) {
      if (g.IsSequence() && model.spatial())
        model.options.g3 = rd.vec3(g, "gravity");
      else if (g.IsSequence())
        model.options.g = rd.vec2(g, "gravity");
      else
        model.options.gravity = rd.boolean(g, "gravity");
    }
    if (YAML::Node b = n["baumgarte"]; b.IsDefined()) {
      rd.keys(b, "baumgarte", {"alpha", "beta"});
      model.options.alpha = rd.number_or(b, "alpha", 5.0);
      model.options.beta = rd.number_or(b, "beta", 5.0);
      if (model.options.alpha < 0 || model.options.beta < 0) rd.fail(b, "baumgarte", "alpha and beta must be >= 0");
    }
    if (n["centripetal"].IsDefined()) model.options.centripetal = rd.boolean(n["centripetal"], "centripetal");
    model.options.t_end = rd.number_or(n, "t_end", model.options.t_end);
    model.options.sample = rd.number_or(n, "sample", model.options.sample);
    if (!(model.options.t_end > 0)) rd.fail(n["t_end"], "t_end", "must be > 0 (s)");
    if (!(model.options.sample > 0)) rd.fail(n["sample"], "sample", "must be > 0 (s)");
  }

  void markers_of(const YAML::Node& n, int body, const std::string& body_name) {
    if (!n.IsDefined()) return;
    if (!n.IsMap())
      rd.fail(n, "markers", model.spatial() ? "expected a mapping name: [x, y, z]" : "expected a mapping name: [x, y]");
    for (auto it = n.begin(); it != n.end(); ++it) {
      std::string name = body_name + "." + it->first.as<std::string>();
      if (model.find_marker(name) >= 0) rd.fail(it->first, "markers", fmt::format("duplicate marker '{}'", name));
      if (model.spatial()) {
        Vec3 u = rd.vec3(it->second, name);
        model.markers.push_back({name, body, u.head<2>(), u});
      } else {
        model.markers.push_back({name, body, rd.vec2(it->second, name)});
      }
    }
  }

  // 3D body: inertia [Ixx, Iyy, Izz] (principal, body frame) or a 3×3 list; orientation as
  // {axis, angle|angle_deg} or quaternion [e0, e1, e2, e3]; angular_velocity [ωx, ωy, ωz] global.
  mbs::Body body3(const YAML::Node& b) {
    rd.keys(b, "body",
            {"name", "mass", "inertia", "position", "orientation", "quaternion", "velocity", "angular_velocity",
             "markers"});
    mbs::Body body;
    body.name = rd.text(b, "name", "body");
    std::string what = "body '" + body.name + "'";
    body.mass = rd.nonnegative(b, "mass", what);
    YAML::Node in = rd.need(b, "inertia", what);
    if (in.IsSequence() && in.size() == 3 && in[0].IsScalar()) {
      body.inertia3 = rd.vec3(in, "inertia").asDiagonal();
    } else if (in.IsSequence() && in.size() == 3) {
      for (int r = 0; r < 3; ++r) body.inertia3.row(r) = rd.vec3(in[r], "inertia").transpose();
      if (!body.inertia3.isApprox(body.inertia3.transpose(), 1e-12))
        rd.fail(in, "inertia", "the inertia tensor must be symmetric");
    } else {
      rd.fail(in, "inertia", "expected [Ixx, Iyy, Izz] (principal moments) or a 3×3 list [[..], [..], [..]] (kg·m²)");
    }
    Eigen::SelfAdjointEigenSolver<mbs::Mat3> es(body.inertia3);
    const Vec3 I = es.eigenvalues();
    if (!(I.minCoeff() >= 0) || I[0] + I[1] < I[2] * (1 - 1e-12))
      rd.fail(in, "inertia",
              "must be positive semi-definite and satisfy the triangle inequality I1 + I2 >= I3 of a rigid body");
    body.q0s.head<3>() = rd.vec3(rd.need(b, "position", what), "position");
    if (b["orientation"].IsDefined() && b["quaternion"].IsDefined())
      rd.fail(b["quaternion"], "quaternion", "give either orientation or quaternion, not both");
    if (YAML::Node o = b["orientation"]; o.IsDefined()) {
      rd.keys(o, "orientation", {"axis", "angle", "angle_deg"});
      body.q0s.tail<4>() =
          mbs::quaternion(rd.unit3(rd.need(o, "axis", "orientation"), "axis"), rd.angle(o, "angle", 0.0));
    } else if (YAML::Node qn = b["quaternion"]; qn.IsDefined()) {
      if (!qn.IsSequence() || qn.size() != 4) rd.fail(qn, "quaternion", "expected four numbers [e0, e1, e2, e3]");
      mbs::Vec4 p(rd.number(qn[0], "quaternion"), rd.number(qn[1], "quaternion"), rd.number(qn[2], "quaternion"),
                  rd.number(qn[3], "quaternion"));
      if (std::abs(p.norm() - 1) > 1e-6)
        rd.fail(qn, "quaternion", fmt::format("must be a unit quaternion (norm {:.8g})", p.norm()));
      body.q0s.tail<4>() = p.normalized();
    }
    if (b["velocity"].IsDefined()) body.qd0s.head<3>() = rd.vec3(b["velocity"], "velocity");
    if (b["angular_velocity"].IsDefined())
      body.qd0s.tail<4>() = mbs::p_dot(body.q0s.tail<4>(), rd.vec3(b["angular_velocity"], "angular_velocity"));
    return body;
  }

  void bodies(const YAML::Node& n) {
    if (!n.IsDefined()) return;
    if (!n.IsSequence()) rd.fail(n, "bodies", "expected a list of bodies");
    names_unique(n, "body");
    for (const auto& b : n) {
      if (model.spatial()) {
        mbs::Body body = body3(b);
        if (body.name == "ground" || body.name.find('.') != std::string::npos)
          rd.fail(b["name"], "name", "a body may not be called 'ground' or contain '.'");
        model.bodies.push_back(body);
        int index = static_cast<int>(model.bodies.size()) - 1;
        model.markers.push_back({body.name + ".cm", index, Vec2::Zero(), Vec3::Zero()});
        markers_of(b["markers"], index, body.name);
        continue;
      }
      rd.keys(b, "body",
              {"name", "mass", "inertia", "position", "angle", "angle_deg", "velocity", "angular_velocity", "markers"});
      mbs::Body body;
      body.name = rd.text(b, "name", "body");
      if (body.name == "ground" || body.name.find('.') != std::string::npos)
        rd.fail(b["name"], "name", "a body may not be called 'ground' or contain '.'");
      std::string what = "body '" + body.name + "'";
      body.mass = rd.nonnegative(b, "mass", what);
      body.inertia = rd.nonnegative(b, "inertia", what);
      Vec2 r = rd.vec2(rd.need(b, "position", what), "position");
      body.q0 = Vec3(r.x(), r.y(), rd.angle(b, "angle", 0.0));
      if (b["velocity"].IsDefined()) body.qd0.head<2>() = rd.vec2(b["velocity"], "velocity");
      body.qd0.z() = rd.number_or(b, "angular_velocity", 0.0);
      model.bodies.push_back(body);
      int index = static_cast<int>(model.bodies.size()) - 1;
      model.markers.push_back({body.name + ".cm", index, Vec2::Zero()});
      markers_of(b["markers"], index, body.name);
    }
  }

  // `bodies: [i, j]` of a fixed joint.
  void fixed_bodies(const YAML::Node& j, const std::string& what, mbs::Joint& jt) const {
    rd.keys(j, what, {"name", "type", "bodies"});
    YAML::Node bs = rd.need(j, "bodies", what);
    if (!bs.IsSequence() || bs.size() != 2) rd.fail(bs, "bodies", "expected a list of two bodies [body_i, body_j]");
    jt.type = mbs::JointType::Fixed;
    jt.body_i = body(bs[0], "bodies"), jt.body_j = body(bs[1], "bodies");
  }
  // The driven body or marker of a driving joint (body_j and its point); the marker's index, −1 for a body.
  int driven(const YAML::Node& j, const std::string& what, mbs::Joint& jt) const {
    rd.keys(j, what, {"name", "type", "body", "marker", "coordinate", "motion"});
    jt.type = mbs::JointType::Driving;
    if (j["marker"].IsDefined() == j["body"].IsDefined())
      rd.fail(j, what, "give either body (a body coordinate) or marker (a point coordinate)");
    if (j["body"].IsDefined()) {
      jt.body_j = body(j["body"], "body");
      if (jt.body_j < 0) rd.fail(j["body"], "body", "ground cannot be driven");
      return -1;
    }
    const int m = marker(j["marker"], "marker");
    jt.body_j = mk(m).body, jt.u_j = mk(m).u, jt.p_j = mk(m).u3;
    if (jt.body_j < 0) rd.fail(j["marker"], "marker", "a ground marker cannot be driven");
    return m;
  }

  void joints(const YAML::Node& n) {
    if (!n.IsDefined()) return;
    if (!n.IsSequence()) rd.fail(n, "joints", "expected a list of joints");
    names_unique(n, "joint");
    const Eigen::VectorXd q = model.q0();
    for (const auto& j : n) {
      mbs::Joint jt;
      jt.name = rd.text(j, "name", "joint");
      std::string what = "joint '" + jt.name + "'";
      std::string type = rd.text(j, "type", what);
      if (model.spatial()) {
        joint3(j, jt, what, type);
      } else if (type == "revolute" || type == "prismatic") {
        if (type == "revolute")
          rd.keys(j, what, {"name", "type", "markers"});
        else
          rd.keys(j, what, {"name", "type", "markers", "axis"});
        auto [mi, mj] = marker_pair(j, what);
        jt.type = type == "revolute" ? mbs::JointType::Revolute : mbs::JointType::Prismatic;
        jt.body_i = mk(mi).body, jt.body_j = mk(mj).body;
        jt.u_i = mk(mi).u, jt.u_j = mk(mj).u;
        if (jt.type == mbs::JointType::Prismatic) {
          jt.axis = rd.vec2(rd.need(j, "axis", what), "axis");
          if (!(jt.axis.norm() > 0)) rd.fail(j["axis"], "axis", "must be a non-zero vector");
          jt.axis.normalize();
          jt.theta0 = q_of(q, jt.body_j).z() - q_of(q, jt.body_i).z();
        }
      } else if (type == "fixed") {
        fixed_bodies(j, what, jt);
        Vec3 qi = q_of(q, jt.body_i), qj = q_of(q, jt.body_j);
        jt.u_i = mbs::rotate(-qi.z(), qj.head<2>() - qi.head<2>());  // j's centre in i's frame
        jt.theta0 = qj.z() - qi.z();
      } else if (type == "driving") {
        const std::string c = rd.text(j, "coordinate", what);
        if (driven(j, what, jt) < 0) {
          if (c != "x" && c != "y" && c != "theta") rd.fail(j["coordinate"], "coordinate", "expected x, y or theta");
        } else if (c != "x" && c != "y") {
          rd.fail(j["coordinate"], "coordinate", "expected x or y for a point");
        }
        jt.component = c == "x" ? 0 : c == "y" ? 1 : 2;
        Vec3 qj = q_of(q, jt.body_j);
        jt.value0 = jt.component == 2 ? qj.z() : (qj.head<2>() + mbs::rotate(qj.z(), jt.u_j))[jt.component];
        jt.motion = time_function(rd, rd.need(j, "motion", what), "motion");
      } else {
        rd.fail(j["type"], "type",
                fmt::format("unknown joint type '{}'; expected revolute, prismatic, fixed or driving", type));
      }
      if (jt.type != mbs::JointType::Driving && jt.body_i == jt.body_j)
        rd.fail(j, what,
                jt.body_i < 0 ? "joins ground to ground; expected at least one body"
                              : "joins a body to itself; expected two different bodies");
      model.joints.push_back(jt);
    }
  }

  // Tabulated frame of a 3D body (identity for ground).
  mbs::Mat3 A0(int b) const {
    return b < 0 ? mbs::Mat3::Identity() : mbs::rotation(model.bodies[static_cast<std::size_t>(b)].q0s.tail<4>());
  }
  Vec3 R0(int b) const { return b < 0 ? Vec3::Zero() : Vec3(model.bodies[static_cast<std::size_t>(b)].q0s.head<3>()); }

  // 3D joints (mbs::evaluate_joint_3d): axes are global directions at the tabulated configuration.
  void joint3(const YAML::Node& j, mbs::Joint& jt, const std::string& what, const std::string& type) {
    if (type == "spherical" || type == "revolute" || type == "prismatic") {
      if (type == "spherical")
        rd.keys(j, what, {"name", "type", "markers"});
      else
        rd.keys(j, what, {"name", "type", "markers", "axis"});
      auto [mi, mj] = marker_pair(j, what);
      jt.type = type == "spherical"  ? mbs::JointType::Spherical
                : type == "revolute" ? mbs::JointType::Revolute
                                     : mbs::JointType::Prismatic;
      jt.body_i = mk(mi).body, jt.body_j = mk(mj).body;
      jt.p_i = mk(mi).u3, jt.p_j = mk(mj).u3;
      if (type != "spherical") {
        const Vec3 s = rd.unit3(rd.need(j, "axis", what), "axis");
        Eigen::Index k = 0;
        s.cwiseAbs().minCoeff(&k);  // the least-aligned global axis
        const Vec3 h1 = s.cross(Vec3::Unit(k)).normalized(), h2 = s.cross(h1);
        const mbs::Mat3 Ai = A0(jt.body_i), Aj = A0(jt.body_j);
        jt.a_i[0] = Ai.transpose() * h1, jt.a_i[1] = Ai.transpose() * h2;
        jt.a_j[0] = Aj.transpose() * s, jt.a_j[1] = Aj.transpose() * h2;
      }
    } else if (type == "fixed") {
      fixed_bodies(j, what, jt);
      const mbs::Mat3 Ai = A0(jt.body_i), Aj = A0(jt.body_j);
      jt.p_i = Ai.transpose() * (R0(jt.body_j) - R0(jt.body_i));  // j's centre in i's frame
      for (int k = 0; k < 3; ++k) jt.a_i[k] = Ai.transpose().col(k), jt.a_j[k] = Aj.transpose().col(k);
    } else if (type == "driving") {
      const std::string c = rd.text(j, "coordinate", what);
      driven(j, what, jt);
      if (c != "x" && c != "y" && c != "z")
        rd.fail(j["coordinate"], "coordinate", "expected x, y or z (a 3D model drives point coordinates)");
      jt.component = c == "x" ? 0 : c == "y" ? 1 : 2;
      jt.value0 = (R0(jt.body_j) + A0(jt.body_j) * jt.p_j)[jt.component];
      jt.motion = time_function(rd, rd.need(j, "motion", what), "motion");
    } else {
      rd.fail(j["type"], "type",
              fmt::format("unknown joint type '{}'; expected spherical, revolute, prismatic, fixed or driving", type));
    }
  }

  // 3D rotational spring/damper on a revolute joint: reference directions at the assembled configuration.
  mbs::RotationalSpringDamper::Spatial revolute_angle(const mbs::Joint& jt, const Eigen::VectorXd& q) const {
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

  void forces(const YAML::Node& n, const Eigen::VectorXd& q_init) {
    if (model.options.gravity)
      model.forces.push_back(model.spatial() ? std::make_shared<mbs::Gravity>(model.options.g3)
                                             : std::make_shared<mbs::Gravity>(model.options.g));
    if (!n.IsDefined()) return;
    if (!n.IsSequence()) rd.fail(n, "forces", "expected a list of force elements");
    names_unique(n, "force element");
    mbs::State x0{q_init, Eigen::VectorXd::Zero(q_init.size()), {}};
    for (const auto& f : n) {
      std::string name = rd.text(f, "name", "force element");
      if (name == "gravity") rd.fail(f["name"], "name", "'gravity' is reserved (switch it in options)");
      std::string what = "force element '" + name + "'";
      std::string type = rd.text(f, "type", what);
      if (type == "spring" || type == "damper" || type == "inerter" || type == "axial_force" || type == "network" ||
          type == "actuator") {
        auto [mi, mj] = marker_pair(f, what);
        int bi = mk(mi).body, bj = mk(mj).body;
        auto end = [&](int m) { return model.spatial() ? mbs::StrutEnd(mk(m).u3) : mbs::StrutEnd(mk(m).u); };
        mbs::StrutEnd ui = end(mi), uj = end(mj);
        if (type == "actuator" && model.spatial())
          rd.fail(f["type"], "type", "the actuator (piston mass, friction) is planar only; use a network strut in 3D");
        if (bi == bj) rd.fail(f["markers"], "markers", "both terminals are on the same body; a strut needs two bodies");
        double l_init = mbs::Spring("", bi, ui, bj, uj, 0, 0).length(model, x0);
        if (!(l_init > 0))
          rd.fail(f["markers"], "markers", "the terminals coincide in the initial configuration (zero length)");
        auto free_length = [&] {
          YAML::Node fl = f["free_length"];
          if (!fl.IsDefined() || (fl.IsScalar() && fl.Scalar() == "initial")) return l_init;
          double L0 = rd.number(fl, "free_length");
          if (!(L0 >= 0)) rd.fail(fl, "free_length", "must be >= 0 (m) or 'initial'");
          return L0;
        };
        if (type == "network" || type == "actuator") {
          strut_network(f, name, what, type, bi, ui, bj, uj, free_length());
        } else if (type == "spring") {
          rd.keys(f, what, {"name", "type", "markers", "k", "free_length"});
          double L0 = free_length();
          model.forces.push_back(std::make_shared<mbs::Spring>(name, bi, ui, bj, uj, rd.nonnegative(f, "k", what), L0));
        } else if (type == "damper") {
          rd.keys(f, what, {"name", "type", "markers", "c"});
          model.forces.push_back(std::make_shared<mbs::Damper>(name, bi, ui, bj, uj, rd.nonnegative(f, "c", what)));
        } else if (type == "inerter") {
          rd.keys(f, what, {"name", "type", "markers", "b", "centripetal"});
          bool corr = f["centripetal"].IsDefined() ? rd.boolean(f["centripetal"], "centripetal") : true;
          model.forces.push_back(
              std::make_shared<mbs::Inerter>(name, bi, ui, bj, uj, rd.nonnegative(f, "b", what), corr));
        } else {
          rd.keys(f, what, {"name", "type", "markers", "force"});
          model.forces.push_back(std::make_shared<mbs::AxialForce>(name, bi, ui, bj, uj, rd.number(f, "force", what)));
        }
      } else if (type == "rotational_spring" || type == "rotational_damper" || type == "rotational_spring_damper") {
        rd.keys(f, what, {"name", "type", "joint", "k", "c", "angle0", "angle0_deg"});
        std::string jn = rd.text(f, "joint", what);
        int ji = model.find_joint(jn);
        if (ji < 0) rd.fail(f["joint"], "joint", fmt::format("unknown joint '{}'", jn));
        const mbs::Joint& jt = model.joints[static_cast<std::size_t>(ji)];
        if (jt.type != mbs::JointType::Revolute)
          rd.fail(f["joint"], "joint", fmt::format("joint '{}' is not revolute; expected a revolute joint", jn));
        double k = type == "rotational_damper" ? 0.0 : rd.nonnegative(f, "k", what);
        double c = type == "rotational_spring" ? rd.number_or(f, "c", 0.0) : rd.nonnegative(f, "c", what);
        if (c < 0) rd.fail(f["c"], "c", "must be >= 0");
        if (type == "rotational_damper" &&
            (f["k"].IsDefined() || f["angle0"].IsDefined() || f["angle0_deg"].IsDefined()))
          rd.fail(f, what, "a rotational_damper takes only c; use rotational_spring_damper for both");
        mbs::RotationalSpringDamper::Spatial sp;
        if (model.spatial()) sp = revolute_angle(jt, q_init);
        double a_init = model.spatial() ? sp.angle_init : q_of(q_init, jt.body_j).z() - q_of(q_init, jt.body_i).z();
        double a0 = a_init;
        if (f["angle0"].IsDefined() && f["angle0"].IsScalar() && f["angle0"].Scalar() == "initial") {
          if (f["angle0_deg"].IsDefined())
            rd.fail(f["angle0_deg"], "angle0_deg", "give either angle0 or angle0_deg, not both");
        } else {
          a0 = rd.angle(f, "angle0", a_init);
        }
        if (model.spatial())
          model.forces.push_back(
              std::make_shared<mbs::RotationalSpringDamper>(name, jt.body_i, jt.body_j, k, a0, c, sp));
        else
          model.forces.push_back(std::make_shared<mbs::RotationalSpringDamper>(name, jt.body_i, jt.body_j, k, a0, c));
      } else if (type == "point_force") {
        rd.keys(f, what, {"name", "type", "marker", "direction", "value"});
        int m = marker(rd.need(f, "marker", what), "marker");
        if (mk(m).body < 0)
          rd.fail(f["marker"], "marker", "a force on a ground marker does nothing; expected a body's marker");
        if (model.spatial()) {
          Vec3 d = rd.unit3(rd.need(f, "direction", what), "direction");
          model.forces.push_back(std::make_shared<mbs::PointForce>(
              name, mk(m).body, mk(m).u3, d, time_function(rd, rd.need(f, "value", what), "value"), std::true_type{}));
          continue;
        }
        Vec2 d = rd.vec2(rd.need(f, "direction", what), "direction");
        if (!(d.norm() > 0)) rd.fail(f["direction"], "direction", "must be a non-zero vector");
        model.forces.push_back(std::make_shared<mbs::PointForce>(
            name, mk(m).body, mk(m).u, d, time_function(rd, rd.need(f, "value", what), "value")));
      } else if (type == "point_torque") {
        rd.keys(f, what, {"name", "type", "body", "axis", "value"});
        if (!model.spatial()) rd.fail(f["type"], "type", "point_torque is for 3D models (dimension: 3)");
        int b = body(rd.need(f, "body", what), "body");
        if (b < 0) rd.fail(f["body"], "body", "a torque on ground does nothing; expected a body");
        model.forces.push_back(
            std::make_shared<mbs::PointTorque>(name, b, rd.unit3(rd.need(f, "axis", what), "axis"),
                                               time_function(rd, rd.need(f, "value", what), "value")));
      } else {
        rd.fail(
            f["type"], "type",
            fmt::format(
                "unknown force element type '{}'; expected spring, damper, inerter, axial_force, network, "
                "actuator, rotational_spring, rotational_damper, rotational_spring_damper, point_force or point_torque",
                type));
      }
    }
  }

  // A network strut or an actuator (spec/03): the network by layout name or expression, values in
  // `params`; an open network stays as a zero-force strut and a rigid one becomes a distance joint (both noted).
  void strut_network(const YAML::Node& f, const std::string& name, const std::string& what, const std::string& type,
                     int bi, mbs::StrutEnd ui, int bj, mbs::StrutEnd uj, double l_ref) {
    const bool act = type == "actuator";
    if (act)
      rd.keys(f, what,
              {"name", "type", "markers", "network", "params", "free_length", "centripetal", "constant_force",
               "piston_mass", "friction", "friction_velocity"});
    else
      rd.keys(f, what, {"name", "type", "markers", "network", "params", "free_length", "centripetal"});
    YAML::Node nn = f["network"];
    std::string text = act && !nn.IsDefined() ? "S2-default" : rd.text(rd.need(f, "network", what), "network");
    network::Params params;
    if (YAML::Node p = f["params"]; p.IsDefined()) {
      if (!p.IsMap()) rd.fail(p, "params", "expected a mapping element: value, e.g. {b: 10, k: 100}");
      for (auto it = p.begin(); it != p.end(); ++it) {
        std::string k = rd.text(it->first, "params");
        if (params.count(k)) rd.fail(it->first, k, "duplicate element in params; give each value once");
        const YAML::Node v = it->second;
        std::string lower = v.IsScalar() ? v.Scalar() : "";
        for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        double val = lower == "inf" || lower == ".inf" ? INFINITY : rd.number(v, k);
        params[k] = val;
      }
    }
    network::Network net;
    try {
      net = network::simplify(network::resolve(text, params));
    } catch (const network::NetworkError& e) {
      YAML::Node at = e.column > 0 || !f["params"].IsDefined() ? (nn.IsDefined() ? nn : f) : f["params"];
      rd.fail(at, e.column > 0 ? "network" : "params",
              e.column > 0 ? fmt::format("'{}': {}", text, e.what()) : fmt::format("network '{}': {}", text, e.what()));
    }
    const bool corr = f["centripetal"].IsDefined() ? rd.boolean(f["centripetal"], "centripetal") : true;
    mbs::Actuator::Params ap;
    if (act) {
      ap.constant_force = rd.number_or(f, "constant_force", 0.0);
      ap.piston_mass = rd.number_or(f, "piston_mass", 0.0);
      ap.friction = rd.number_or(f, "friction", 0.0);
      ap.friction_velocity = rd.number_or(f, "friction_velocity", 1e-3);
      if (ap.piston_mass < 0) rd.fail(f["piston_mass"], "piston_mass", "must be >= 0 (kg)");
      if (ap.piston_mass > 0 && bj < 0)
        rd.fail(f["piston_mass"], "piston_mass",
                "the rod end (second marker) is on ground; expected the rod end on a body");
      if (ap.friction < 0) rd.fail(f["friction"], "friction", "must be >= 0 (N)");
      if (!(ap.friction_velocity > 0)) rd.fail(f["friction_velocity"], "friction_velocity", "must be > 0 (m/s)");
    }
    if (net.kind == network::Network::Kind::Rigid) {
      if (act)
        rd.fail(f, what,
                fmt::format("the actuator's network '{}' is rigid with these values; expected a network with finite "
                            "values (a rigid actuator would lock the mechanism)",
                            text));
      mbs::Joint jt;
      jt.name = name;
      jt.type = mbs::JointType::Distance;
      jt.body_i = bi, jt.body_j = bj, jt.u_i = ui.u.head<2>(), jt.u_j = uj.u.head<2>(), jt.length0 = l_ref;
      jt.p_i = ui.u, jt.p_j = uj.u;
      model.joints.push_back(jt);
      model.notes.push_back(
          fmt::format("{}: network '{}' is rigid with these values; it is a distance joint '{}'", what, text, name));
      return;
    }
    if (net.kind == network::Network::Kind::Open) {
      model.notes.push_back(
          fmt::format("{}: network '{}' is open with these values; it exerts {}", what, text,
                      act ? "only the actuator's constant force, friction and piston mass" : "no force"));
      net = network::Network{network::Network::Kind::Damper, "c", 0.0, {}, 0};  // exerts no force
    }
    if (act) {
      model.forces.push_back(
          std::make_shared<mbs::Actuator>(name, bi, ui.u.head<2>(), bj, uj.u.head<2>(), net, l_ref, ap, corr));
    } else {
      model.forces.push_back(std::make_shared<mbs::NetworkStrut>(name, bi, ui, bj, uj, net, l_ref, corr));
    }
  }

  int component(const YAML::Node& o, const std::string& what, std::initializer_list<const char*> names) const {
    std::string c = rd.text(o, "component", what);
    int k = 0;
    for (const char* nm : names) {
      if (c == nm) return k;
      ++k;
    }
    std::string list;
    for (const char* nm : names) list += std::string(list.empty() ? "" : ", ") + nm;
    rd.fail(o["component"], "component", fmt::format("unknown component '{}'; expected {}", c, list));
  }

  void outputs(const YAML::Node& n) {
    if (!n.IsDefined()) return;
    if (!n.IsSequence()) rd.fail(n, "outputs", "expected a list of outputs");
    names_unique(n, "output");
    for (const auto& o : n) {
      mbs::Output out;
      out.name = rd.text(o, "name", "output");
      if (out.name == "t" || out.name.find(',') != std::string::npos)
        rd.fail(o["name"], "name", "an output may not be called 't' or contain ','");
      std::string what = "output '" + out.name + "'";
      std::string type = rd.text(o, "type", what);
      auto element = [&] {
        std::string e = rd.text(o, "element", what);
        int k = model.find_force(e);
        int j = model.find_joint(e);
        if (k < 0 && j >= 0 && model.joints[static_cast<std::size_t>(j)].type == mbs::JointType::Distance)
          rd.fail(o["element"], "element",
                  fmt::format("'{}' is a rigid network (a distance joint); expected type: multiplier, joint: {}, "
                              "component: 0 for its tension",
                              e, e));
        if (k < 0) rd.fail(o["element"], "element", fmt::format("unknown force element '{}'", e));
        return k;
      };
      if (type == "coordinate") {
        rd.keys(o, what, {"name", "type", "body", "component", "scale"});
        out.kind = mbs::Output::Kind::Coordinate;
        out.index = body(rd.need(o, "body", what), "body");
        if (out.index < 0) rd.fail(o["body"], "body", "ground has no coordinates");
        out.component = model.spatial() ? component(o, what, {"x", "y", "z", "e0", "e1", "e2", "e3"})
                                        : component(o, what, {"x", "y", "theta"});
      } else if (type == "position" || type == "velocity" || type == "acceleration") {
        rd.keys(o, what, {"name", "type", "marker", "component", "scale"});
        out.kind = type == "position"   ? mbs::Output::Kind::Position
                   : type == "velocity" ? mbs::Output::Kind::Velocity
                                        : mbs::Output::Kind::Acceleration;
        out.index = marker(rd.need(o, "marker", what), "marker");
        out.component = model.spatial() ? component(o, what, {"x", "y", "z"}) : component(o, what, {"x", "y"});
      } else if (type == "force" || type == "length") {
        rd.keys(o, what, {"name", "type", "element", "scale"});
        out.kind = type == "force" ? mbs::Output::Kind::ElementForce : mbs::Output::Kind::ElementLength;
        out.index = element();
      } else if (type == "reaction" || type == "multiplier") {
        rd.keys(o, what, {"name", "type", "joint", "component", "scale"});
        std::string jn = rd.text(o, "joint", what);
        out.index = model.find_joint(jn);
        if (out.index < 0) rd.fail(o["joint"], "joint", fmt::format("unknown joint '{}'", jn));
        if (type == "reaction") {
          out.kind = mbs::Output::Kind::Reaction;
          out.component =
              model.spatial() ? component(o, what, {"x", "y", "z"}) : component(o, what, {"x", "y", "moment"});
        } else {
          out.kind = mbs::Output::Kind::Multiplier;
          double c = rd.number(o, "component", what);
          int rows = model.joints[static_cast<std::size_t>(out.index)].rows();
          if (c != std::floor(c) || c < 0 || c >= rows)
            rd.fail(o["component"], "component", fmt::format("expected an equation index 0..{}", rows - 1));
          out.component = static_cast<int>(c);
        }
      } else {
        rd.fail(o["type"], "type",
                fmt::format("unknown output type '{}'; expected coordinate, position, velocity, "
                            "acceleration, force, length, reaction or multiplier",
                            type));
      }
      out.scale = rd.number_or(o, "scale", 1.0);
      model.outputs.push_back(out);
    }
  }

  void assembly(const YAML::Node& n) {
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
};

// Overrides "NAME.KEY=VALUE": a number of a force element or body in the YAML tree (new keys only
// inside `params`, where a network's element values live). yaml-cpp's Node::operator= rebinds
// shared data, so walking uses reset() and only the leaf is assigned.
struct Slot {
  YAML::Node map;   // the mapping that holds the value
  std::string key;  // its key there
  bool exists = false;
};

Slot locate(YAML::Node& root, const std::string& dotted, const std::function<void(const std::string&)>& fail) {
  std::vector<std::string> path;
  std::stringstream ps(dotted);
  for (std::string part; std::getline(ps, part, '.');) path.push_back(part);
  if (path.size() < 2 || std::any_of(path.begin(), path.end(), [](const std::string& p) { return p.empty(); }))
    fail("expected NAME.KEY with NAME a force element or body, e.g. c2.c or head.mass");
  YAML::Node cur;
  bool found = false;
  std::string names;
  for (const char* section : {"forces", "bodies"}) {
    const YAML::Node list = static_cast<const YAML::Node&>(root)[section];
    if (!list.IsSequence()) continue;
    for (std::size_t i = 0; i < list.size() && !found; ++i) {
      const YAML::Node item = list[i];
      if (!item.IsMap() || !item["name"].IsScalar()) continue;
      names += (names.empty() ? "" : ", ") + item["name"].Scalar();
      if (item["name"].Scalar() == path[0]) cur.reset(item), found = true;
    }
  }
  if (!found) fail(fmt::format("no force element or body named '{}'; names: {}", path[0], names));
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const YAML::Node next = static_cast<const YAML::Node&>(cur)[path[i]];
    if (next.IsDefined() && next.IsMap()) {
      cur.reset(next);
    } else if (path[i] == "params" && !next.IsDefined()) {
      cur[path[i]] = YAML::Node(YAML::NodeType::Map);  // a network strut without params yet
      cur.reset(static_cast<const YAML::Node&>(cur)[path[i]]);
    } else {
      fail(fmt::format("'{}' has no mapping '{}'", path[i - 1], path[i]));
    }
  }
  if (path.back() == "name" || path.back() == "type") fail(fmt::format("'{}' is not a number", path.back()));
  const YAML::Node leaf = static_cast<const YAML::Node&>(cur)[path.back()];
  Slot s{cur, path.back(), leaf.IsDefined() && leaf.IsScalar()};
  const bool in_params = path.size() >= 3 && path[path.size() - 2] == "params";
  if (!s.exists && !in_params) {
    std::string keys;
    for (auto it = cur.begin(); it != cur.end(); ++it)
      if (it->second.IsScalar() && it->first.Scalar() != "name" && it->first.Scalar() != "type")
        keys += (keys.empty() ? "" : ", ") + it->first.Scalar();
    fail(fmt::format("'{}' has no value '{}'; its values: {}", path[path.size() - 2], path.back(), keys));
  }
  return s;
}

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& source) {
  for (const std::string& o : overrides) {
    auto fail = [&](const std::string& what) {
      throw ModelError(fmt::format("{}: override '{}': {}", source, o, what));
    };
    const std::size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) fail("expected NAME.KEY=VALUE, e.g. c2.c=70");
    std::string v = o.substr(eq + 1), lower = v;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    double value = 0;
    if (lower == "inf" || lower == ".inf") {
      value = INFINITY;
    } else {
      std::istringstream vs(v);
      if (!(vs >> value) || !(vs >> std::ws).eof() || !std::isfinite(value)) fail("'" + v + "' is not a number");
    }
    Slot s = locate(root, o.substr(0, eq), fail);
    s.map[s.key] = std::isinf(value) ? std::string(".inf") : fmt::format("{:.17g}", value);
  }
}


// The whole file: the model and, if the file has a `pantograph:` section, its contact point and rig joint.
pantograph::Pantograph parse_file(const std::string& text, const std::string& source,
                                  const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", source, e.mark.line + 1, e.msg));
  }
  if (!overrides.empty()) apply_overrides(root, overrides, source);
  Loader ld{Reader(source), {}};
  int contact = -1, rig_joint = -1;
  const Reader& rd = ld.rd;
  try {
    if (!root.IsMap()) rd.fail(root, "", "expected a model (a mapping with bodies, joints, forces, outputs)");
    rd.keys(
        root, "the model",
        {"name", "options", "ground", "bodies", "joints", "forces", "outputs", "assembly", "pantograph", "dimension"});
    ld.model.source = source;
    if (YAML::Node d = root["dimension"]; d.IsDefined()) {
      double dim = rd.number(d, "dimension");
      if (dim != 2 && dim != 3) rd.fail(d, "dimension", "expected 2 (planar) or 3 (spatial)");
      ld.model.dimension = static_cast<int>(dim);
    }
    ld.model.name = root["name"].IsDefined() ? rd.text(root["name"], "name") : source;
    ld.options(root["options"]);
    if (YAML::Node g = root["ground"]; g.IsDefined()) {
      rd.keys(g, "ground", {"markers"});
      ld.markers_of(g["markers"], mbs::kGround, "ground");
    }
    ld.bodies(rd.need(root, "bodies", "the model"));
    ld.joints(root["joints"]);
    ld.assembly(root["assembly"]);
    ld.model.finalize();
    try {
      mbs::State x = mbs::assemble(ld.model, 0.0);
      ld.forces(root["forces"], x.q);
      ld.model.finalize();  // internal states, and distance joints of rigid networks
    } catch (const NumericalError& e) {
      throw ModelError(fmt::format("{}: {}", source, e.what()));
    }
    ld.outputs(root["outputs"]);
    if (YAML::Node p = root["pantograph"]; p.IsDefined()) {
      if (ld.model.spatial()) rd.fail(p, "pantograph", "the pantograph-catenary analyses are planar (dimension: 2)");
      rd.keys(p, "pantograph", {"contact", "rig_joint"});
      contact = ld.marker(rd.need(p, "contact", "pantograph"), "contact");
      if (p["rig_joint"].IsDefined()) {
        const std::string rig = rd.text(p["rig_joint"], "rig_joint");
        rig_joint = ld.model.find_joint(rig);
        if (rig_joint < 0) rd.fail(p["rig_joint"], "rig_joint", fmt::format("unknown joint '{}'", rig));
      }
    }
  } catch (const YAML::Exception& e) {  // safety net: no yaml-cpp exception leaves without file:line
    throw ModelError(fmt::format("{}:{}: {}", source, e.mark.line + 1, e.msg));
  }
  return {std::move(ld.model), contact, rig_joint};
}

}  // namespace

mbs::Model parse_model(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  return parse_file(text, source, overrides).model;
}

pantograph::Pantograph parse_pantograph(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides) {
  pantograph::Pantograph p = parse_file(text, source, overrides);
  if (p.contact_marker < 0)
    throw ModelError(
        fmt::format("{}: the model has no 'pantograph: {{contact: <marker>}}' section; a catenary needs the head's "
                    "contact point",
                    source));
  return p;
}

std::optional<double> model_value(const std::string& text, const std::string& source, const std::string& key) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", source, e.mark.line + 1, e.msg));
  }
  Slot s = locate(root, key, [&](const std::string& what) {
    throw ModelError(fmt::format("{}: parameter '{}': {}", source, key, what));
  });
  if (!s.exists) return std::nullopt;
  const YAML::Node leaf = static_cast<const YAML::Node&>(s.map)[s.key];
  try {
    return leaf.as<double>();
  } catch (const YAML::Exception&) {
    throw ModelError(
        fmt::format("{}:{}: '{}': expected a number, got '{}'", source, leaf.Mark().line + 1, key, leaf.Scalar()));
  }
}

namespace {
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ModelError(fmt::format("{}: cannot open the model file", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

mbs::Model load_model(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_model(read_text(path), path, overrides);
}

pantograph::Pantograph parse_model_file(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides) {
  return parse_file(text, source, overrides);
}

pantograph::Pantograph load_model_file(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_file(read_text(path), path, overrides);
}

pantograph::Pantograph load_pantograph(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_pantograph(read_text(path), path, overrides);
}

}  // namespace inerta::io
