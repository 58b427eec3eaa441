#include "inerta/mbs/joint.hpp"

namespace inerta::mbs {

namespace {
// Point-coincidence rows r_Pi − r_Pj = 0 (eqs. 6.29–6.36); γ from r̈_P = G q̈ − A ū θ̇².
void coincidence(const PointKinematics& pi, const PointKinematics& pj, ConstraintRow* rows) {
  for (int c = 0; c < 2; ++c) {
    ConstraintRow& r = rows[c];
    r.C = pi.r[c] - pj.r[c];
    r.gi = Vec3(c == 0, c == 1, pi.Atu[c]);
    r.gj = -Vec3(c == 0, c == 1, pj.Atu[c]);
    r.gamma = -(pi.a_bias[c] - pj.a_bias[c]);
  }
}

// Relative rotation θ_j − θ_i − θ0 = 0.
void relative_angle(const Vec3& qi, const Vec3& qj, double theta0, ConstraintRow& r) {
  r.C = qj.z() - qi.z() - theta0;
  r.gi = Vec3(0, 0, -1);
  r.gj = Vec3(0, 0, 1);
}
}  // namespace

int evaluate_joint(const Joint& jt, double t, const BodyFrame& fi, const BodyFrame& fj, ConstraintRow rows[3]) {
  const Vec3 &qi = fi.q, &qj = fj.q, &qdi = fi.qd;
  for (int k = 0; k < 3; ++k) rows[k] = ConstraintRow{};
  switch (jt.type) {
    case JointType::Revolute:
    case JointType::Spherical:
    case JointType::Fixed: {
      coincidence(point_kinematics(fi, jt.u_i), point_kinematics(fj, jt.u_j), rows);
      if (jt.type == JointType::Fixed) relative_angle(qi, qj, jt.theta0, rows[2]);
      break;
    }
    case JointType::Prismatic: {
      relative_angle(qi, qj, jt.theta0, rows[0]);
      // C = d·n with d = r_Pj − r_Pi and n = A_i n̄⊥ (spec/02 §2.1).
      PointKinematics pi = point_kinematics(fi, jt.u_i), pj = point_kinematics(fj, jt.u_j);
      Vec2 nbar(-jt.axis.y(), jt.axis.x());
      Vec2 n = fi.rotate(nbar), nt(-n.y(), n.x());  // n, ∂n/∂θ_i
      Vec2 d = pj.r - pi.r, dd = pj.v - pi.v;
      double wi = qdi.z();
      ConstraintRow& r = rows[1];
      r.C = d.dot(n);
      r.gi = Vec3(-n.x(), -n.y(), -n.dot(pi.Atu) + d.dot(nt));
      r.gj = Vec3(n.x(), n.y(), n.dot(pj.Atu));
      // C̈ = C_q q̈ + n·(a_bias_j − a_bias_i) + 2 ḋ·ṅ − θ̇_i² d·n,  ṅ = θ̇_i ∂n/∂θ_i.
      r.gamma = -(n.dot(pj.a_bias - pi.a_bias) + 2 * wi * dd.dot(nt) - wi * wi * d.dot(n));
      break;
    }
    case JointType::Distance: {
      // C = l − L0, C_q = J, C̈ = J q̈ + ê·a_n + [ṙ·ṙ − l̇²]/l (eqs. 3.18–3.20).
      StrutKinematics s = strut_kinematics(fi, jt.u_i, fj, jt.u_j);
      ConstraintRow& r = rows[0];
      r.C = s.l - jt.length0;
      r.gi = s.J.head<3>();
      r.gj = s.J.tail<3>();
      r.gamma = -(s.a_n_axial + s.centripetal);
      break;
    }
    case JointType::Coupling: {
      PointKinematics pi = point_kinematics(fi, jt.u_i), pj = point_kinematics(fj, jt.u_j);
      const int c = jt.component;
      ConstraintRow& r = rows[0];
      r.C = pj.r[c] - pi.r[c] - jt.value0;
      r.gi = -Vec3(c == 0, c == 1, pi.Atu[c]);
      r.gj = Vec3(c == 0, c == 1, pj.Atu[c]);
      r.gamma = -(pj.a_bias[c] - pi.a_bias[c]);
      break;
    }
    case JointType::Driving: {
      ConstraintRow& r = rows[0];
      double f = jt.value0 + jt.motion.value(t);
      if (jt.component == 2) {
        r.C = qj.z() - f;
        r.gj = Vec3(0, 0, 1);
        r.gamma = jt.motion.d2(t);
      } else {
        PointKinematics pj = point_kinematics(fj, jt.u_j);
        int c = jt.component;
        r.C = pj.r[c] - f;
        r.gj = Vec3(c == 0, c == 1, pj.Atu[c]);
        r.gamma = -pj.a_bias[c] + jt.motion.d2(t);
      }
      r.Ct = -jt.motion.d1(t);
      break;
    }
  }
  return jt.rows();
}

}  // namespace inerta::mbs
