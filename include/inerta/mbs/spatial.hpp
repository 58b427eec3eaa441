#pragma once
// Spatial kinematics with Euler parameters (spec/01 §1.4). Body coordinates q_i = [R; p] (7 numbers):
// R the centre of mass, p = [e0 e1 e2 e3] a unit quaternion (one normalisation constraint pᵀp − 1 = 0
// per body). Euler parameters, not the thesis's Z-X-Z angles: those are singular at θ = 0, which is
// exactly the planar configuration of every example.
//   A   = (e0² − eᵀe) I + 2 e eᵀ + 2 e0 ẽ                      (rotation, body → global)
//   E   = [−e, ẽ + e0 I],  G = [−e, −ẽ + e0 I]                 (3×4; ω = 2 E ṗ global, ω̄ = 2 G ṗ body)
//   u   = A ū,  ṙ_P = Ṙ + ω × u = Ṙ − 2 ũ E ṗ                 (eq. 3.22 with H_p = −2 ũ E)
//   r̈_P = R̈ − 2 ũ E p̈ + ω × (ω × u)                           (eq. 3.25; Ė ṗ = 0)
#include <Eigen/Dense>

#include "inerta/mbs/kinematics.hpp"

namespace inerta::mbs {

using Vec4 = Eigen::Vector4d;
using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat37 = Eigen::Matrix<double, 3, 7>;

inline Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}
inline Mat3 rotation(const Vec4& p) {
  const Vec3 e = p.tail<3>();
  return (p[0] * p[0] - e.squaredNorm()) * Mat3::Identity() + 2 * e * e.transpose() + 2 * p[0] * skew(e);
}
inline Mat34 E_matrix(const Vec4& p) {
  Mat34 E;
  E.col(0) = -p.tail<3>();
  E.rightCols<3>() = skew(p.tail<3>()) + p[0] * Mat3::Identity();
  return E;
}
inline Mat34 G_matrix(const Vec4& p) {
  Mat34 G;
  G.col(0) = -p.tail<3>();
  G.rightCols<3>() = -skew(p.tail<3>()) + p[0] * Mat3::Identity();
  return G;
}
/// Unit quaternion of a rotation by `angle` about the unit `axis`.
inline Vec4 quaternion(const Vec3& axis, double angle) {
  Vec4 p;
  p << std::cos(angle / 2), std::sin(angle / 2) * axis.normalized();
  return p;
}
/// ṗ of angular velocity ω (global): ṗ = ½ Eᵀ ω (for a unit p).
inline Vec4 p_dot(const Vec4& p, const Vec3& omega) { return 0.5 * E_matrix(p).transpose() * omega; }

/// A body's spatial frame at (q, q̇) (identity at rest for ground).
struct SpatialFrame {
  Vec3 R = Vec3::Zero(), Rd = Vec3::Zero();
  Vec4 p = Vec4(1, 0, 0, 0), pd = Vec4::Zero();
  Mat3 A = Mat3::Identity();
  Mat34 E = Mat34::Zero();  ///< zero for ground: its points have no Jacobian
  Vec3 w = Vec3::Zero();    ///< angular velocity, global
  /// In place from the body's 7 coordinates and velocities.
  void set(const double* q, const double* qd) {
    R = Eigen::Map<const Vec3>(q), Rd = Eigen::Map<const Vec3>(qd);
    p = Eigen::Map<const Vec4>(q + 3), pd = Eigen::Map<const Vec4>(qd + 3);
    A = rotation(p);
    E = E_matrix(p);
    w = 2 * E * pd;
  }
  static SpatialFrame of(const Vec7& q, const Vec7& qd) {
    SpatialFrame f;
    f.set(q.data(), qd.data());
    return f;
  }
};

/// A body-fixed vector: a point (position, with R) or a direction (without).
///   v = [R +] A ū,  v̇ = G q̇_i,  v̈ = G q̈_i + bias,  G = [I or 0, −2 ũ E] (3×7, u = A ū),
/// applied without forming G: G q̇ = [Ṙ] − 2 u × (E ṗ),  Gᵀ x = [x or 0; 2 Eᵀ (u × x)].
struct SpatialVector {
  Vec3 v, vd, bias, u;
  Mat34 E;
  bool point;
  Vec3 G_mul(const Vec7& qd) const {
    return (point ? Vec3(qd.head<3>()) : Vec3::Zero()) - 2 * u.cross(E * qd.tail<4>());
  }
  Vec7 Gt(const Vec3& x) const {
    Vec7 g;
    g.head<3>() = point ? x : Vec3::Zero();
    g.tail<4>() = 2 * E.transpose() * u.cross(x);
    return g;
  }
};
inline SpatialVector spatial_vector(const SpatialFrame& f, const Vec3& u_local, bool point) {
  SpatialVector s;
  s.u = f.A * u_local;
  s.v = point ? Vec3(f.R + s.u) : s.u;
  s.vd = f.w.cross(s.u) + (point ? f.Rd : Vec3::Zero());
  s.bias = f.w.cross(f.w.cross(s.u));
  s.E = f.E;
  s.point = point;
  return s;
}

/// Strut kinematics in 3D (eqs. 3.20–3.25 with Euler parameters): J = êᵀ [−G_Pi  G_Pj] (1×14),
/// with êᵀ G_P = [êᵀ, 2 (u × ê)ᵀ E] (G_P = [I, −2 ũ E]).
inline StrutKinematics strut_kinematics(const SpatialFrame& fi, const Vec3& ui, const SpatialFrame& fj,
                                        const Vec3& uj) {
  const Vec3 u_i = fi.A * ui, u_j = fj.A * uj;
  const Vec3 w_i = fi.w.cross(u_i), w_j = fj.w.cross(u_j);
  StrutKinematics s;
  const Vec3 r = fj.R + u_j - fi.R - u_i, rd = fj.Rd + w_j - fi.Rd - w_i;
  s.l = r.norm();
  const Vec3 e = r / s.l;
  s.l_dot = rd.dot(e);
  s.J.resize(14);
  s.J.head<3>() = -e;
  s.J.segment<4>(3) = -2 * fi.E.transpose() * u_i.cross(e);
  s.J.segment<3>(7) = e;
  s.J.tail<4>() = 2 * fj.E.transpose() * u_j.cross(e);
  s.a_n_axial = e.dot(fj.w.cross(w_j) - fi.w.cross(w_i));
  s.centripetal = (rd.squaredNorm() - s.l_dot * s.l_dot) / s.l;
  return s;
}

}  // namespace inerta::mbs
