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

#include "inerta/catenary/catenary.hpp"
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
  /// InvalidArgument with the offending coefficient (see Lumped).
  void validate() const;
};

/// The catenary's mass variation, damping and stiffness acting on the vertical coordinate of the
/// catenary body (which carries the constant mass m_c0); y measured from y_unloaded.
class CatenaryElement : public mbs::ForceElement {
 public:
  /// Needs the wire body's coordinate address (q index of its vertical coordinate).
  CatenaryElement(std::string name, int wire_y, LumpedCatenary cat, double speed, double y_unloaded);
  const LumpedCatenary& catenary() const { return cat_; }
  double speed() const { return v_; }
  double pumping_frequency() const { return v_ / cat_.span; }

  void add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const override;
  double energy(const mbs::Model&, double t, const mbs::State& x) const override;
  double power(const mbs::Model&, double t, const mbs::State& x) const override;
  double force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace& ws) const override;
  double length(const mbs::Model&, const mbs::State& x) const override;  ///< uplift y − y_unloaded

 private:
  int iy_;
  LumpedCatenary cat_;
  double v_, y0_;
};

/// The lumped catenary as a catenary type: embedded (the wire is a body of the pantograph's
/// multibody model: mass m_c0 on a vertical slider under the contact point, with the
/// CatenaryElement), one pantograph (a point model has no distance between pantographs).
class Lumped final : public Catenary {
 public:
  /// InvalidArgument unless span > 0, m_c0 > 0, k_c0 > 0, c_c0 >= 0 and the coefficients stay
  /// positive (non-negative for c) over a span.
  explicit Lumped(LumpedCatenary params);
  const LumpedCatenary& params() const { return p_; }
  std::string describe() const override;
  double span() const override { return p_.span; }
  int max_pantographs() const override { return 1; }
  std::shared_ptr<const Catenary> mean() const override;  ///< harmonics zeroed
  const LumpedCatenary* point_model() const override { return &p_; }

 protected:
  std::unique_ptr<Coupled> make_coupled(const std::vector<PantographOnLine>& pantographs, double speed) const override;

 private:
  LumpedCatenary p_;
};

/// One pantograph coupled to a lumped catenary (spec/05 §5.2): the multibody model and its typed
/// handles (the wire body, its vertical coordinate, the catenary element, the contact force).
struct LumpedCoupling {
  mbs::Model model;
  int wire_body = -1;         ///< index of the wire body
  int wire_y = -1;            ///< index of its vertical coordinate in q
  int element = -1;           ///< index of the CatenaryElement in model.forces
  mbs::Output contact_force;  ///< compression positive; also the model's output F_contact
  double y_unloaded = 0;      ///< the wire's unloaded height (the contact point's assembled height), m
  bool bilateral = true;
};

/// Removes the rig's hold of the head (and its outputs), adds the wire at the contact point's
/// assembled height, the CatenaryElement for `speed` (m/s) and the contact (bilateral coupling
/// joint or PenaltyContact), and the output F_contact (replacing an output of that name).
LumpedCoupling couple_lumped(const pantograph::Pantograph& p, const LumpedCatenary& cat, const Contact& contact,
                             double speed);

/// Adds the wire body "catenary" (mass m_c0, rotation and x locked) at (x, y_unloaded) and its
/// CatenaryElement for `speed` (m/s) to a model. Returns the body index. Call Model::finalize afterwards.
int add_catenary(mbs::Model& model, const LumpedCatenary& cat, double speed, double x, double y_unloaded);

}  // namespace inerta::catenary
