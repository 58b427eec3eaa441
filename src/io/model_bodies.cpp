// Model files: ground markers, bodies (planar and spatial) and the marker/body lookups
// (docs/model-format.md#ground, #bodies, #markers).
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "inerta/mbs/spatial.hpp"
#include "model_loader.hpp"

namespace inerta::io::detail {

using mbs::Vec2;
using mbs::Vec3;

int Loader::marker(const YAML::Node& n, const std::string& key) const {
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

int Loader::body(const YAML::Node& n, const std::string& key) const {
  std::string name = rd.text(n, key);
  int b = model.find_body(name);
  if (b == -2) rd.fail(n, key, fmt::format("unknown body '{}'", name));
  return b;
}

std::pair<int, int> Loader::marker_pair(const YAML::Node& map, const std::string& what) const {
  YAML::Node m = rd.need(map, "markers", what);
  if (!m.IsSequence() || m.size() != 2)
    rd.fail(m, "markers", "expected a list of two markers [body_i.point, body_j.point]");
  return {marker(m[0], "markers"), marker(m[1], "markers")};
}

void Loader::names_unique(const YAML::Node& list, const std::string& what) const {
  std::set<std::string> seen;
  for (const auto& item : list) {
    if (!item.IsMap()) rd.fail(item, what, fmt::format("expected a mapping (key: value pairs) for each {}", what));
    std::string name = rd.text(item, "name", what);
    if (!seen.insert(name).second) rd.fail(item["name"], "name", fmt::format("duplicate {} name '{}'", what, name));
  }
}

namespace {

// `markers:` of a body or of ground: name: [x, y] (3D: [x, y, z]) in the body frame.
void markers_of(Loader& ld, const YAML::Node& n, int body, const std::string& body_name) {
  const Reader& rd = ld.rd;
  mbs::Model& model = ld.model;
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
mbs::Body body3(const Reader& rd, const YAML::Node& b) {
  rd.keys(b, "body",
          {"name", "mass", "inertia", "position", "orientation", "quaternion", "velocity", "angular_velocity",
           "markers"});
  mbs::Body body;
  body.name = rd.text(b, "name", "body");
  std::string what = "body '" + body.name + "'";
  body.mass = rd.number(b, "mass", what);
  YAML::Node in = rd.need(b, "inertia", what);
  if (in.IsSequence() && in.size() == 3 && in[0].IsScalar()) {
    body.inertia3 = rd.vec3(in, "inertia").asDiagonal();
  } else if (in.IsSequence() && in.size() == 3) {
    for (int r = 0; r < 3; ++r) body.inertia3.row(r) = rd.vec3(in[r], "inertia").transpose();
  } else {
    rd.fail(in, "inertia", "expected [Ixx, Iyy, Izz] (principal moments) or a 3×3 list [[..], [..], [..]] (kg·m²)");
  }
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
    if (std::abs(p.norm() - 1) > 1e-6)  // the file's tolerance; the stored quaternion is normalised
      rd.fail(qn, "quaternion", fmt::format("must be a unit quaternion (norm {:.8g})", p.norm()));
    body.q0s.tail<4>() = p.normalized();
  }
  if (b["velocity"].IsDefined()) body.qd0s.head<3>() = rd.vec3(b["velocity"], "velocity");
  if (b["angular_velocity"].IsDefined())
    body.qd0s.tail<4>() = mbs::p_dot(body.q0s.tail<4>(), rd.vec3(b["angular_velocity"], "angular_velocity"));
  return body;
}

mbs::Body body2(const Reader& rd, const YAML::Node& b) {
  rd.keys(b, "body",
          {"name", "mass", "inertia", "position", "angle", "angle_deg", "velocity", "angular_velocity", "markers"});
  mbs::Body body;
  body.name = rd.text(b, "name", "body");
  if (body.name == "ground" || body.name.find('.') != std::string::npos)
    rd.fail(b["name"], "name", "a body may not be called 'ground' or contain '.'");
  std::string what = "body '" + body.name + "'";
  body.mass = rd.number(b, "mass", what);
  body.inertia = rd.number(b, "inertia", what);
  Vec2 r = rd.vec2(rd.need(b, "position", what), "position");
  body.q0 = Vec3(r.x(), r.y(), rd.angle(b, "angle", 0.0));
  if (b["velocity"].IsDefined()) body.qd0.head<2>() = rd.vec2(b["velocity"], "velocity");
  body.qd0.z() = rd.number_or(b, "angular_velocity", 0.0);
  return body;
}

}  // namespace

void Loader::ground(const YAML::Node& g) {
  if (!g.IsDefined()) return;
  rd.keys(g, "ground", {"markers"});
  markers_of(*this, g["markers"], mbs::kGround, "ground");
}

void Loader::bodies(const YAML::Node& n) {
  if (!n.IsDefined()) return;
  if (!n.IsSequence()) rd.fail(n, "bodies", "expected a list of bodies");
  // The system matrix of eq. 4.12 is dense (coordinates + constraints squared): 10 000 coordinates
  // are ≈ 1 GB of it; 100 000 bodies ended in std::bad_alloc (issue 38).
  const std::size_t per_body = model.spatial() ? 7 : 3, max_coordinates = 10000;
  if (n.size() * per_body > max_coordinates)
    rd.fail(n, "bodies",
            fmt::format("{} bodies ({} coordinates): at most {} coordinates ({} bodies in {}D) — the system matrix of "
                        "eq. 4.12 is dense",
                        n.size(), n.size() * per_body, max_coordinates, max_coordinates / per_body,
                        model.spatial() ? 3 : 2));
  names_unique(n, "body");
  for (const auto& b : n) {
    mbs::Body body = model.spatial() ? body3(rd, b) : body2(rd, b);
    if (model.spatial() && (body.name == "ground" || body.name.find('.') != std::string::npos))
      rd.fail(b["name"], "name", "a body may not be called 'ground' or contain '.'");
    rd.guard(b, "body '" + body.name + "'", [&] { body.validate(); });  // mass, inertia >= 0, finite values
    model.bodies.push_back(body);
    int index = static_cast<int>(model.bodies.size()) - 1;
    model.markers.push_back({body.name + ".cm", index, Vec2::Zero(), Vec3::Zero()});
    markers_of(*this, b["markers"], index, body.name);
  }
}

}  // namespace inerta::io::detail
