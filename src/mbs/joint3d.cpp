#include <stdexcept>

#include "inerta/mbs/joint.hpp"

namespace inerta::mbs {

namespace {
// Rows built from body-fixed vectors v (spatial.hpp): v̈ = G v̈-part q̈ + bias, so for C(v…):
// C_q from the G's, γ = −(C̈ − C_q q̈).

// C = a·b, a on body i, b on body j.
void dot_row(const SpatialVector& a, const SpatialVector& b, ConstraintRow3& r) {
  r.C = a.v.dot(b.v);
  r.gi = a.Gt(b.v);
  r.gj = b.Gt(a.v);
  r.gamma = -(a.v.dot(b.bias) + b.v.dot(a.bias) + 2 * a.vd.dot(b.vd));
}

// C = a·d, d = r_Pj − r_Pi, a on body i.
void dot_d_row(const SpatialVector& a, const SpatialVector& pi, const SpatialVector& pj, ConstraintRow3& r) {
  const Vec3 d = pj.v - pi.v, dd = pj.vd - pi.vd;
  r.C = a.v.dot(d);
  r.gi = a.Gt(d) - pi.Gt(a.v);
  r.gj = pj.Gt(a.v);
  r.gamma = -(d.dot(a.bias) + a.v.dot(pj.bias - pi.bias) + 2 * a.vd.dot(dd));
}

// C = r_Pi[c] − r_Pj[c].
void coincidence(const SpatialVector& pi, const SpatialVector& pj, ConstraintRow3* rows) {
  for (int c = 0; c < 3; ++c) {
    ConstraintRow3& r = rows[c];
    r.C = pi.v[c] - pj.v[c];
    r.gi = pi.Gt(Vec3::Unit(c));
    r.gj = -pj.Gt(Vec3::Unit(c));
    r.gamma = -(pi.bias[c] - pj.bias[c]);
  }
}
}  // namespace

int evaluate_joint_3d(const Joint& jt, double t, const SpatialFrame& fi, const SpatialFrame& fj,
                      ConstraintRow3 rows[6]) {
  for (int k = 0; k < 6; ++k) rows[k] = ConstraintRow3{};
  auto vi = [&](int k) { return spatial_vector(fi, jt.a_i[k], false); };
  auto vj = [&](int k) { return spatial_vector(fj, jt.a_j[k], false); };
  const SpatialVector pi = spatial_vector(fi, jt.p_i, true), pj = spatial_vector(fj, jt.p_j, true);
  switch (jt.type) {
    case JointType::Spherical:
      coincidence(pi, pj, rows);
      break;
    case JointType::Revolute: {
      coincidence(pi, pj, rows);
      const SpatialVector s = vj(0);
      dot_row(vi(0), s, rows[3]);
      dot_row(vi(1), s, rows[4]);
      break;
    }
    case JointType::Prismatic: {
      const SpatialVector h1 = vi(0), h2 = vi(1), s = vj(0);
      dot_row(h1, s, rows[0]);
      dot_row(h2, s, rows[1]);
      dot_row(h1, vj(1), rows[2]);
      dot_d_row(h1, pi, pj, rows[3]);
      dot_d_row(h2, pi, pj, rows[4]);
      break;
    }
    case JointType::Fixed:
      coincidence(pi, pj, rows);
      dot_row(vi(0), vj(1), rows[3]);
      dot_row(vi(1), vj(2), rows[4]);
      dot_row(vi(2), vj(0), rows[5]);
      break;
    case JointType::Distance: {
      // C = l − L0, C_q = J, C̈ = J q̈ + ê·a_n + [ṙ·ṙ − l̇²]/l (eqs. 3.18–3.20).
      StrutKinematics s = strut_kinematics(fi, jt.p_i, fj, jt.p_j);
      ConstraintRow3& r = rows[0];
      r.C = s.l - jt.length0;
      r.gi = s.J.head<7>();
      r.gj = s.J.tail<7>();
      r.gamma = -(s.a_n_axial + s.centripetal);
      break;
    }
    case JointType::Driving: {
      ConstraintRow3& r = rows[0];
      const int c = jt.component;
      r.C = pj.v[c] - jt.value0 - jt.motion.value(t);
      r.gj = pj.Gt(Vec3::Unit(c));
      r.gamma = -pj.bias[c] + jt.motion.d2(t);
      r.Ct = -jt.motion.d1(t);
      break;
    }
    case JointType::Coupling:
      throw std::logic_error("joint '" + jt.name + "': the pantograph-catenary coupling is planar only");
  }
  return jt.rows();
}

}  // namespace inerta::mbs
