#pragma once
// Prescribed wire-height profile: a rigid contact wire whose height along the line is given (a
// design profile, or measured heights), touched through a unilateral penalty contact. Useful on its
// own for excitation by measured wire geometry, and the second catenary type behind the interface.
//
// Pantograph k, whose contact point P starts at x0_k, sees the wire at x_c(t) = x0_k + v t, height
//   y_w(t) = y_P,0 + h(x_c) − h(x0_k)          (y_P,0: P's assembled height: the wire touches P at t = 0)
// and the overlap δ = y_P − y_w, δ̇ = ẏ_P − v h′(x_c); F = max(0, k_s δ + c_s δ̇) for δ > 0, else 0,
// pushes the head down (spec/05 §5.2). h is a C² cubic spline through the table (numerics).
#include <memory>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/numerics/cubic_spline.hpp"

namespace inerta::catenary {

struct WireProfile {
  std::vector<double> x, h;  ///< m: positions along the line (strictly increasing) and the wire's heights there
  bool periodic = true;      ///< repeats every x_n − x_0 (the last height must equal the first)
  double span = 0;           ///< m: span for statistics windows; 0 = the period (periodic profiles only)
};

/// The penalty contact of one pantograph's contact point (body, u) with the profile.
class ProfileContact : public mbs::ForceElement {
 public:
  ProfileContact(std::string name, int body, mbs::Vec2 u, std::shared_ptr<const numerics::CubicSpline> h, double x0,
                 double speed, double y_offset, double stiffness, double damping);
  void add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const override;
  double energy(const mbs::Model& model, double t, const mbs::State& x) const override;
  double power(const mbs::Model& model, double t, const mbs::State& x) const override;
  double force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace& ws) const override;
  double length(const mbs::Model& model, const mbs::State& x) const override;  ///< overlap δ (> 0 in contact)
  double wire_height(double t) const;  ///< y_w(t), m
  double wire_rate(double t) const;    ///< ẏ_w(t) = v h′(x_c), m/s

 private:
  struct Eval {
    double delta, delta_dot, F, yw_dot;
    mbs::PointKinematics p;
  };
  Eval evaluate(double t, const mbs::BodyFrame& f) const;
  int body_;
  mbs::Vec2 u_;
  std::shared_ptr<const numerics::CubicSpline> h_;
  double x0_, v_, y_offset_, ks_, cs_;
};

class WireProfileCatenary final : public Catenary {
 public:
  /// InvalidArgument for fewer than 2 points, x not increasing, a periodic profile that does not
  /// close, or a non-periodic one without a span.
  explicit WireProfileCatenary(WireProfile profile);
  const WireProfile& profile() const { return p_; }
  std::string describe() const override;
  double span() const override { return span_; }
  int max_pantographs() const override { return 64; }
  std::shared_ptr<const Catenary> mean() const override;  ///< a flat wire at the mean height

 protected:
  /// Needs penalty contacts (a rigid wire and a bilateral joint would prescribe the head's motion).
  std::unique_ptr<Coupled> make_coupled(const std::vector<PantographOnLine>& pantographs, double speed) const override;

 private:
  WireProfile p_;
  std::shared_ptr<const numerics::CubicSpline> h_;
  double span_ = 0;
};

}  // namespace inerta::catenary
