#pragma once
// Contact laws between a pantograph's contact point and the contact wire (spec/05 §5.2).
#include <string>

#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/kinematics.hpp"

namespace inerta::catenary {

/// The contact law of one pantograph: the thesis's bilateral joint (the head follows the wire, the
/// force may not become negative: a run where it does is invalid) or a unilateral penalty
/// F = max(0, k_s δ + c_s δ̇) on the overlap δ (contact loss possible).
struct Contact {
  enum class Kind { Bilateral, Penalty };
  Kind kind = Kind::Bilateral;
  double stiffness = 50e3;  ///< penalty k_s, N/m (> 0)
  double damping = 0.0;     ///< penalty c_s, N·s/m (>= 0)
  /// InvalidArgument unless k_s > 0 and c_s >= 0 (both finite).
  void validate() const;
};

const char* kind_name(Contact::Kind kind);  ///< "bilateral" | "penalty"

/// Unilateral penalty contact along Y between the pantograph's contact point P_i and the wire
/// point P_j (spec/05 §5.2): F = max(0, k_s δ + c_s δ̇) with δ = y_i − y_j + δ0 the overlap;
/// F pushes the wire up and the head down; `force` reports F (compression positive).
class PenaltyContact : public mbs::ForceElement {
 public:
  PenaltyContact(std::string name, int body_i, mbs::Vec2 u_i, int body_j, mbs::Vec2 u_j, double stiffness,
                 double damping, double overlap0);
  void add(const mbs::Model&, double t, const mbs::State& x, mbs::Workspace& ws) const override;
  double energy(const mbs::Model& model, double t, const mbs::State& x) const override;
  double power(const mbs::Model& model, double t, const mbs::State& x) const override;
  double force(const mbs::Model&, double t, const mbs::State& x, const mbs::Workspace& ws) const override;
  double length(const mbs::Model& model, const mbs::State& x) const override;  ///< overlap δ (> 0 in contact)

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
