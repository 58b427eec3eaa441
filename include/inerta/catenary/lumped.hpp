#pragma once
// Time-varying lumped-mass catenary (spec/05 §5.1, eq. 7.1). Seen from a pantograph moving at
// speed v, the contact wire is a point mass moving vertically with coefficients periodic in time
// at the pumping frequency f_p = v / L:
//
//   m_c(t) ÿ_c + c_c(t) ẏ_c + k_c(t) y_c = F,   x_c(t) = x_c0 + Σ_{i=1..3} x_ci cos(2π i f_p t)
//
// y_c is measured from the unloaded wire height; F is the upward force of the pantograph. With
// positive first harmonics the line is stiffest at t = 0, i.e. at a mast.
#include <array>
#include <string>

#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/kinematics.hpp"

namespace inerta::catenary {

struct LumpedCatenary {
  double span = 60.0;                                     ///< L, m
  std::array<double, 4> m{177.3, 0.0, 0.0, 0.0};          ///< m_c0..m_c3, kg
  std::array<double, 4> c{111.0, 0.0, 0.0, 0.0};          ///< c_c0..c_c3, N·s/m
  std::array<double, 4> k{7000.0, 2100.0, 350.0, 140.0};  ///< k_c0..k_c3, N/m

  /// Σ x_i cos(2π i f_p t) and its time derivative.
  static double harmonic(const std::array<double, 4>& x, double fp, double t);
  static double harmonic_rate(const std::array<double, 4>& x, double fp, double t);
  double natural_frequency() const;  ///< (1/2π) sqrt(k_c0 / m_c0), Hz
};

/// The catenary's mass variation, damping and stiffness acting on the vertical coordinate of the
/// catenary body (which carries the constant mass m_c0); y measured from y_unloaded.
class CatenaryElement : public mbs::ForceElement {
 public:
  CatenaryElement(std::string name, int body, LumpedCatenary cat, double speed, double y_unloaded);
  const LumpedCatenary& catenary() const { return cat_; }
  double speed() const { return v_; }
  double pumping_frequency() const { return v_ / cat_.span; }

  void add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const override;
  double energy(const mbs::Model&, double t, const mbs::State& x) const override;
  double power(const mbs::Model&, double t, const mbs::State& x) const override;
  double force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace& ws) const override;
  double length(const mbs::Model&, const mbs::State& x) const override;  ///< uplift y − y_unloaded

 private:
  int body_;
  LumpedCatenary cat_;
  double v_, y0_;
};

/// Unilateral penalty contact along Y between the pantograph's contact point P_i and the wire
/// point P_j (spec/05 §5.2): F = max(0, k_s δ + c_s δ̇) with δ = y_i − y_j + δ0 the overlap;
/// F pushes the wire up and the head down; `force` reports F (compression positive).
class PenaltyContact : public mbs::ForceElement {
 public:
  PenaltyContact(std::string name, int body_i, mbs::Vec2 u_i, int body_j, mbs::Vec2 u_j, double stiffness,
                 double damping, double overlap0);
  void add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const override;
  double energy(const mbs::Model&, double t, const mbs::State& x) const override;
  double power(const mbs::Model&, double t, const mbs::State& x) const override;
  double force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace& ws) const override;
  double length(const mbs::Model&, const mbs::State& x) const override;  ///< overlap δ (> 0 in contact)

 private:
  struct Eval {
    double delta, delta_dot, F;
    mbs::PointKinematics pi, pj;
  };
  Eval evaluate(const mbs::BodyFrame& fi, const mbs::BodyFrame& fj) const;
  int bi_, bj_;
  mbs::Vec2 ui_, uj_;
  double ks_, cs_, d0_;
};

}  // namespace inerta::catenary
