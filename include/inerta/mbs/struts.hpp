#pragma once
// Uniaxial struts between two markers (spec/01 §1.1, spec/02 §2.3). Tension is positive; the
// generalised force of a tension F on [q_i; q_j] is Q = −F Jᵀ with J = êᵀ H (eqs. 6.40–6.44).
// Constructors check their parameters (parameter_check.hpp): a negative, NaN or infinite value
// throws inerta::InvalidArgument naming the element and the value.
#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/parameter_check.hpp"

namespace inerta::mbs {

/// Shortest strut length accepted during a run, m: a strut shorter than this has no defined axis and
/// stops the run (NumericalError naming it; the integrator adds the time).
inline constexpr double min_strut_length = 1e-6;

/// A strut terminal's local coordinates: a 2-vector for a planar model, a 3-vector for a spatial one.
struct StrutEnd {
  Vec3 u;
  bool spatial;
  template <class D>
  StrutEnd(const Eigen::MatrixBase<D>& v)  // NOLINT: implicit on purpose
      : u(D::RowsAtCompileTime == 3 ? Vec3(v.eval().template head<3>()) : Vec3(v[0], v[1], 0.0)),
        spatial(D::RowsAtCompileTime == 3) {
    static_assert(D::RowsAtCompileTime == 2 || D::RowsAtCompileTime == 3, "a terminal is a 2- or 3-vector");
  }
};

/// Common geometry of a strut from marker P_i (body i) to P_j (body j), in 2D or 3D (spatial.hpp):
/// the strut elements below are the same code in both.
class Strut : public ForceElement {
 public:
  /// InvalidArgument ("markers") if both terminals are on the same body (ground counts as one), if
  /// one terminal is planar and the other spatial, or if a coordinate is not finite.
  Strut(std::string name, int body_i, StrutEnd u_i, int body_j, StrutEnd u_j);
  StrutKinematics kinematics(const Model& model, const State& x) const;
  StrutKinematics kinematics(const Workspace& ws) const;  ///< from the frames of ws.set_state
  double length(const Model&, const State& x) const override;
  bool strut_vector(const Model& model, const State& x, Eigen::Vector3d& r) const override;
  int body_i() const { return body_i_; }
  int body_j() const { return body_j_; }
  Vec2 u_i() const { return u_i_.head<2>(); }
  Vec2 u_j() const { return u_j_.head<2>(); }
  bool spatial() const { return spatial_; }

 protected:
  /// Q += −F Jᵀ.
  void add_tension(double F, const StrutKinematics& s, Workspace& ws) const;

 private:
  int body_i_, body_j_;
  Vec3 u_i_, u_j_;
  bool spatial_;
};

/// Spring, eqs. 3.1/3.5: F = k (l − L0); k ≥ 0 (N/m), L0 ≥ 0 (m).
class Spring : public Strut {
 public:
  Spring(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, double k, double free_length)
      : Strut(std::move(name), bi, ui, bj, uj),
        k_(check::nonnegative({"spring", this->name()}, "k", k, "N/m")),
        L0_(check::nonnegative({"spring", this->name()}, "free_length", free_length, "m")) {}
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;  // ½ k (l − L0)²
  double force(const Model&, double t, const State& x, const Workspace& ws) const override;
  double free_length() const { return L0_; }

 private:
  double k_, L0_;
};

/// Damper, eqs. 3.2/3.6–3.7: F = c l̇; c ≥ 0 (N·s/m).
class Damper : public Strut {
 public:
  Damper(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, double c)
      : Strut(std::move(name), bi, ui, bj, uj), c_(check::nonnegative({"damper", this->name()}, "c", c, "N·s/m")) {}
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double power(const Model&, double t, const State& x) const override;  // −c l̇²
  double force(const Model&, double t, const State& x, const Workspace& ws) const override;

 private:
  double c_;
};

/// Inerter, eq. 3.20: F = b l̈ = b { (H q̈ + a_n)·ê + [ṙ·ṙ − (ṙ·ê)²]/l }. The q̈ part enters the
/// mass matrix, M_I = b Jᵀ J, and the rest the right-hand side, Q_Iv (eqs. 3.31–3.33).
/// Without the centripetal correction (eq. 3.8, the 1D textbook form) F = b (r̈·ê). Inertance b ≥ 0 (kg).
class Inerter : public Strut {
 public:
  Inerter(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, double b, bool centripetal = true)
      : Strut(std::move(name), bi, ui, bj, uj),
        b_(check::nonnegative({"inerter", this->name()}, "b", b, "kg")),
        centripetal_(centripetal) {}
  /// Correction active: this element's switch and the model-wide switch.
  bool centripetal(const Model& model) const;
  void add(const Model& model, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;  // ½ b l̇²
  /// Without the correction the element is not conservative: power b·[ṙ·ṙ − l̇²]/l·l̇.
  double power(const Model& model, double t, const State& x) const override;
  double force(const Model& model, double t, const State& x, const Workspace& ws) const override;

 private:
  double b_;
  bool centripetal_;
};

/// Constant axial force (pneumatic actuator's static force F_c, spec/02 §2.3); tension positive,
/// so a pushing actuator has force < 0 (any sign, finite, N). Potential F·l.
class AxialForce : public Strut {
 public:
  AxialForce(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, double F)
      : Strut(std::move(name), bi, ui, bj, uj), F_(check::finite({"axial force", this->name()}, "force", F, "N")) {}
  void add(const Model&, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;
  double force(const Model&, double, const State&, const Workspace&) const override { return F_; }

 private:
  double F_;
};

}  // namespace inerta::mbs
