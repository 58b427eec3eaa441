#pragma once
// Gravity, point forces, and rotational spring/damper on a joint's relative angle (spec/02 §2.3).
#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/time_function.hpp"

namespace inerta::mbs {

/// Gravity on every body, eq. 6.39: Q_g = [m g_x, m g_y, 0]. Potential −m g·R.
class Gravity : public ForceElement {
 public:
  explicit Gravity(Vec2 g) : ForceElement("gravity"), g_(g) {}
  void add(const Model& model, double t, const State& x, Workspace& ws) const override;
  double energy(const Model& model, double t, const State& x) const override;
  double force(const Model& model, double, const State&, const Workspace&) const override;  // total weight

 private:
  Vec2 g_;
};

/// Force f(t)·d̂ at a marker, d̂ a fixed global unit direction. Power F·v_P.
class PointForce : public ForceElement {
 public:
  PointForce(std::string name, int body, Vec2 u, Vec2 direction, TimeFunction f)
      : ForceElement(std::move(name)), body_(body), u_(u), d_(direction.normalized()), f_(std::move(f)) {}
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double power(const Model&, double t, const State& x) const override;
  double force(const Model&, double t, const State&, const Workspace&) const override { return f_.value(t); }

 private:
  int body_;
  Vec2 u_, d_;
  TimeFunction f_;
};

/// Rotational spring and damper on Δθ = θ_j − θ_i (a revolute joint's relative angle):
/// moment −k (Δθ − Δθ0) − c Δθ̇ on body j and the opposite on body i.
class RotationalSpringDamper : public ForceElement {
 public:
  RotationalSpringDamper(std::string name, int body_i, int body_j, double k, double angle0, double c)
      : ForceElement(std::move(name)), bi_(body_i), bj_(body_j), k_(k), a0_(angle0), c_(c) {}
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;                   // ½ k (Δθ − Δθ0)²
  double power(const Model&, double t, const State& x) const override;                    // −c Δθ̇²
  double force(const Model&, double t, const State& x, const Workspace&) const override;  // moment on j
  double length(const Model&, const State& x) const override;                             // Δθ

 private:
  int bi_, bj_;
  double k_, a0_, c_;
};

}  // namespace inerta::mbs
