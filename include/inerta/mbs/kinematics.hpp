#pragma once
// Planar kinematics of body-fixed points and of uniaxial struts (spec/01 §1.3, eqs. 3.15–3.19).
// Body coordinates q_i = [x y θ] with the centre of mass as reference point; ground has q = 0.
#include <Eigen/Dense>
#include <cmath>

namespace inerta::mbs {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
/// Row over the coordinates of two bodies [q_i; q_j]: 6 in 2D, 14 in 3D (no heap allocation).
using VecJ = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 14, 1>;

/// A = rotation matrix of θ.
inline Vec2 rotate(double theta, const Vec2& u) {
  double c = std::cos(theta), s = std::sin(theta);
  return {c * u.x() - s * u.y(), s * u.x() + c * u.y()};
}
/// A_θ u = dA/dθ u = A (u rotated by +90°).
inline Vec2 rotate_d(double theta, const Vec2& u) { return rotate(theta, Vec2(-u.y(), u.x())); }

/// A body's coordinates with the trigonometry of θ evaluated once (ground: q = 0).
struct BodyFrame {
  Vec3 q = Vec3::Zero(), qd = Vec3::Zero();
  double c = 1.0, s = 0.0;  ///< cos θ, sin θ
  static BodyFrame of(const Vec3& q, const Vec3& qd) { return {q, qd, std::cos(q.z()), std::sin(q.z())}; }
  Vec2 rotate(const Vec2& u) const { return {c * u.x() - s * u.y(), s * u.x() + c * u.y()}; }
};

/// Global position, velocity and the body-coordinate Jacobian of point P (ū_P local) on a body.
struct PointKinematics {
  Vec2 r;       ///< R + A ū
  Vec2 v;       ///< Ṙ + A_θ ū θ̇
  Vec2 a_bias;  ///< r̈ − G q̈ = −A ū θ̇²
  Vec2 Au;      ///< A ū (global offset from the centre of mass)
  Vec2 Atu;     ///< A_θ ū (column of G for θ)
};

inline PointKinematics point_kinematics(const BodyFrame& f, const Vec2& u_local) {
  PointKinematics p;
  p.Au = f.rotate(u_local);
  p.Atu = Vec2(-p.Au.y(), p.Au.x());
  p.r = f.q.head<2>() + p.Au;
  p.v = f.qd.head<2>() + p.Atu * f.qd.z();
  p.a_bias = -p.Au * (f.qd.z() * f.qd.z());
  return p;
}
inline PointKinematics point_kinematics(const Vec3& q, const Vec3& qd, const Vec2& u_local) {
  return point_kinematics(BodyFrame::of(q, qd), u_local);
}

/// Kinematics of a uniaxial strut from P_i (body i) to P_j (body j): eqs. 3.15–3.20.
///   r = r_Pj − r_Pi,  l = |r|,  ê = r/l,  l̇ = ṙ·ê = J q̇_ij,  J = êᵀ H (1×6, eq. 3.18),
///   l̈ = J q̈_ij + ê·a_n + [ṙ·ṙ − l̇²]/l   (eq. 3.20 divided by b; a_n eq. 3.19).
/// `l_ddot_bias` is ê·a_n + centripetal; `centripetal` = [ṙ·ṙ − l̇²]/l ≥ 0.
struct StrutKinematics {
  double l = 0, l_dot = 0;
  VecJ J;                  ///< ∂l/∂[q_i; q_j] (6 in 2D, 14 in 3D)
  double a_n_axial = 0;    ///< ê·a_n
  double centripetal = 0;  ///< [ṙ·ṙ − (ṙ·ê)²]/l, the correction of eq. 3.9
};

inline StrutKinematics strut_kinematics(const BodyFrame& fi, const Vec2& ui, const BodyFrame& fj, const Vec2& uj) {
  PointKinematics pi = point_kinematics(fi, ui), pj = point_kinematics(fj, uj);
  StrutKinematics s;
  const Vec2 r = pj.r - pi.r, rd = pj.v - pi.v;
  s.l = r.norm();
  const Vec2 e = r / s.l;
  s.l_dot = rd.dot(e);
  s.J.resize(6);
  // Element by element: GCC 12 warns (-Warray-bounds, a false positive) on the comma initialiser's
  // 4-wide packet copy of a Vec2 into this dynamic vector in an AVX2 build.
  s.J[0] = -e.x(), s.J[1] = -e.y(), s.J[2] = -e.dot(pi.Atu), s.J[3] = e.x(), s.J[4] = e.y(), s.J[5] = e.dot(pj.Atu);
  s.a_n_axial = e.dot(pj.a_bias - pi.a_bias);
  s.centripetal = (rd.squaredNorm() - s.l_dot * s.l_dot) / s.l;
  return s;
}

}  // namespace inerta::mbs
