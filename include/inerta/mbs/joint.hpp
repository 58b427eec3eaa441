#pragma once
// Joints as holonomic constraints C(q, t) = 0 (spec/02 §2.1, eqs. 4.1–4.4).
#include <string>

#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/spatial.hpp"
#include "inerta/mbs/time_function.hpp"

namespace inerta::mbs {

constexpr int kGround = -1;

enum class JointType {
  Revolute,   ///< r_Pi − r_Pj = 0 (eqs. 6.29–6.36); 3D: and the axis of j ⊥ two normals of i
  Spherical,  ///< 3D: r_Pi − r_Pj = 0
  Prismatic,  ///< θ_j − θ_i − θ0 = 0;  (r_Pj − r_Pi)·(A_i n̄⊥) = 0
  Fixed,      ///< r_Pi − r_Pj = 0 with P = j's centre of mass;  θ_j − θ_i − θ0 = 0 (eq. 6.28)
  Driving,    ///< coordinate(s) of body j or of point P_j = value0 + f(t)
  Distance,   ///< |r_Pj − r_Pi| − length0 = 0 (a strut whose network is rigid)
  Coupling,   ///< (r_Pj − r_Pi)[component] − value0 = 0 (bilateral pantograph–catenary contact)
};

struct Joint {
  std::string name;
  JointType type = JointType::Revolute;
  int body_i = kGround, body_j = kGround;
  Vec2 u_i = Vec2::Zero(), u_j = Vec2::Zero();  ///< joint points in body frames (global if ground)
  Vec2 axis = Vec2(1, 0);                       ///< prismatic: unit axis in body i's frame
  double theta0 = 0;                            ///< prismatic, fixed: θ_j − θ_i locked value
  // Driving: component 0 = x, 1 = y of point P_j (u_j), or 2 = θ_j; value = value0 + f(t).
  int component = 0;
  double value0 = 0;
  double length0 = 0;  ///< distance joint
  TimeFunction motion;
  int row = 0;  ///< first constraint row (set by Model::finalize)
  // 3D (spatial = true): points and body-frame unit vectors, see evaluate_joint_3d.
  bool spatial = false;
  Vec3 p_i = Vec3::Zero(), p_j = Vec3::Zero();
  Vec3 a_i[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, a_j[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};

  int rows() const {
    if (spatial) {
      switch (type) {
        case JointType::Spherical:
          return 3;
        case JointType::Revolute:
        case JointType::Prismatic:
          return 5;
        case JointType::Fixed:
          return 6;
        default:
          return 1;
      }
    }
    switch (type) {
      case JointType::Spherical:
      case JointType::Revolute:
        return 2;
      case JointType::Prismatic:
        return 2;
      case JointType::Fixed:
        return 3;
      case JointType::Driving:
      case JointType::Distance:
      case JointType::Coupling:
        return 1;
    }
    return 0;
  }
};

/// One constraint equation of a joint, evaluated at (q, q̇, t):
///   C, C_t, the gradients wrt q_i and q_j, and γ = Q_d of eq. 4.3 (C_q q̈ = γ).
struct ConstraintRow {
  double C = 0, Ct = 0, gamma = 0;
  Vec3 gi = Vec3::Zero(), gj = Vec3::Zero();
};

/// Evaluates the rows of joint `jt` given both bodies' frames (identity for ground).
/// Returns the number of rows written into `rows` (at most 3).
int evaluate_joint(const Joint& jt, double t, const BodyFrame& fi, const BodyFrame& fj, ConstraintRow rows[3]);

/// A 3D constraint row: gradients over the 7 coordinates [R; p] of bodies i and j.
struct ConstraintRow3 {
  double C = 0, Ct = 0, gamma = 0;
  Vec7 gi = Vec7::Zero(), gj = Vec7::Zero();
};

/// 3D joints (at most 6 rows), with a = A ā the body-fixed unit vectors a_i[k], a_j[k] and
/// d = r_Pj − r_Pi:
///   spherical  r_Pi − r_Pj = 0
///   revolute   spherical + a_i0·a_j0 = 0, a_i1·a_j0 = 0        (a_j0 the axis, a_i0, a_i1 ⊥ it)
///   prismatic  a_i0·a_j0 = a_i1·a_j0 = a_i0·a_j1 = 0, a_i0·d = a_i1·d = 0
///   fixed      r_Pi − r_Pj = 0, a_i0·a_j1 = a_i1·a_j2 = a_i2·a_j0 = 0   (a = global X, Y, Z at t0)
///   driving    component c of r_Pj = value0 + f(t);  distance |d| − length0 = 0
int evaluate_joint_3d(const Joint& jt, double t, const SpatialFrame& fi, const SpatialFrame& fj,
                      ConstraintRow3 rows[6]);

}  // namespace inerta::mbs
