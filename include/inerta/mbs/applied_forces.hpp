#pragma once
// Gravity, point forces, and rotational spring/damper on a joint's relative angle (spec/02 §2.3).
// Constructors check their parameters (parameter_check.hpp): a negative stiffness or damping, a
// zero direction, a NaN or infinite value throws inerta::InvalidArgument naming the element.
#include <type_traits>

#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/time_function.hpp"

namespace inerta::mbs {

/// Gravity on every body, eq. 6.39: Q_g = [m g_x, m g_y, 0] (3D: [m g, 0]). Potential −m g·R.
/// g (m/s², any direction) must be finite.
class Gravity : public ForceElement {
 public:
  explicit Gravity(Vec2 g);
  explicit Gravity(Vec3 g);
  void add(const Model& model, double t, const State& x, Workspace& ws) const override;
  double energy(const Model& model, double t, const State& x) const override;
  double force(const Model& model, double, const State&, const Workspace&) const override;  // total weight

 private:
  Vec2 g_;
  Vec3 g3_;
  bool spatial_ = false;
};

/// Force f(t)·d̂ at a marker, d̂ a fixed global unit direction. Power F·v_P.
/// 3D: Q = G_Pᵀ F = [F; −2 Eᵀ ũ F] (spatial.hpp). `direction` must be finite and non-zero (it is
/// normalised), u finite and f valid (TimeFunction::validate).
class PointForce : public ForceElement {
 public:
  PointForce(std::string name, int body, Vec2 u, Vec2 direction, TimeFunction f);
  PointForce(std::string name, int body, Vec3 u, Vec3 direction, TimeFunction f, std::true_type /*spatial*/);
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double power(const Model&, double t, const State& x) const override;
  double force(const Model&, double t, const State&, const Workspace&) const override { return f_.value(t); }
  std::shared_ptr<const ForceElement> with_value(const TimeFunction& f) const override;
  double load_value(double t) const override { return f_.value(t); }

 private:
  int body_;
  Vec2 u_ = Vec2::Zero(), d_ = Vec2::Zero();
  Vec3 u3_ = Vec3::Zero(), d3_ = Vec3::Zero();
  TimeFunction f_;
  bool spatial_ = false;
};

/// 3D: torque f(t)·n̂ on a body, n̂ a fixed global unit axis: Q_p = 2 Eᵀ n (spatial.hpp). Power f n̂·ω.
/// `axis` must be finite and non-zero (it is normalised), f valid.
class PointTorque : public ForceElement {
 public:
  PointTorque(std::string name, int body, Vec3 axis, TimeFunction f);
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double power(const Model&, double t, const State& x) const override;
  double force(const Model&, double t, const State&, const Workspace&) const override { return f_.value(t); }
  std::shared_ptr<const ForceElement> with_value(const TimeFunction& f) const override;
  double load_value(double t) const override { return f_.value(t); }

 private:
  int body_;
  Vec3 n_;
  TimeFunction f_;
};

/// Rotational spring and damper on Δθ = θ_j − θ_i (a revolute joint's relative angle):
/// moment −k (Δθ − Δθ0) − c Δθ̇ on body j and the opposite on body i. k ≥ 0 (N·m/rad), c ≥ 0
/// (N·m·s/rad), Δθ0 finite (rad).
class RotationalSpringDamper : public ForceElement {
 public:
  RotationalSpringDamper(std::string name, int body_i, int body_j, double k, double angle0, double c);
  /// 3D, on a revolute joint with axis s̄_i (body i's frame): Δθ = Δθ_init + the angle from h_i = A_i h̄_i
  /// to h_j = A_j h̄_j about s (h̄ ⊥ s, equal in space at the initial configuration, |Δθ − Δθ_init| < π);
  /// Δθ̇ = s·(ω_j − ω_i); the moment acts about s.
  struct Spatial {
    Vec3 s_i = Vec3::UnitZ(), h_i = Vec3::UnitX(), h_j = Vec3::UnitX();
    double angle_init = 0;
  };
  RotationalSpringDamper(std::string name, int body_i, int body_j, double k, double angle0, double c, Spatial sp);
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;                   // ½ k (Δθ − Δθ0)²
  double power(const Model&, double t, const State& x) const override;                    // −c Δθ̇²
  double force(const Model&, double t, const State& x, const Workspace&) const override;  // moment on j
  double length(const Model&, const State& x) const override;                             // Δθ

 private:
  double angle(const Model& model, const State& x) const;
  double rate(const Model& model, const State& x) const;
  int bi_, bj_;
  double k_, a0_, c_;
  Spatial sp_;
  bool spatial_ = false;
};

}  // namespace inerta::mbs
