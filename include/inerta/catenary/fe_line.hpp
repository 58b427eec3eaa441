#pragma once
// Finite-element catenary (spec/05 §5.3): messenger and contact wire as tensioned Euler–Bernoulli
// beams, droppers as bars that carry tension only, supports and registrations at the masts, any
// number of spans, both wires pinned at the line's ends. Planar, vertical plane; transverse
// displacement w (up) and slope θ = w′ at each node; axial motion is not modelled (for a tensioned
// wire under small deflection it decouples from the transverse motion).
//
//   beam element (length ℓ, Hermite cubics N1..N4 on [w_i, θ_i, w_j, θ_j]):
//     K_e = EI/ℓ³ [12 6ℓ −12 6ℓ; 6ℓ 4ℓ² −6ℓ 2ℓ²; …] + T/(30ℓ) [36 3ℓ −36 3ℓ; 3ℓ 4ℓ² −3ℓ −ℓ²; …]
//     M_e = ρA ℓ/420 [156 22ℓ 54 −13ℓ; …]          (consistent mass)
//   dropper d between messenger node m and contact-wire node c, unstretched length L_d:
//     tension T_d = max(0, EA/L_d · e_d), e_d = (y_m − y_c) − L_d; half its mass at each end, plus
//     the clamp masses
//   damping: Rayleigh, C = a M + b K₀ (K₀: all droppers taut; kept when droppers slacken)
//
// Form-finding: the dropper tensions (and the registration and support forces) are solved so that,
// under gravity, the contact wire passes through the prescribed pre-sag at every dropper and at
// height 0 at every mast, and the messenger at height `encumbrance` at every mast; the unstretched
// dropper lengths then follow from the geometry. The dynamic coordinates u are displacements from
// that static state.
//
// Time integration: HHT-α (Hilber–Hughes–Taylor), α ∈ [−1/3, 0], γ = ½ − α, β = (1 − α)²/4
// (α = 0: the trapezoidal rule, no numerical dissipation). The effective matrix of the line with
// all droppers taut is factorised once (Eigen sparse Cholesky); slack droppers and the moving
// penalty contacts are low-rank changes of it, solved exactly by the Woodbury identity from cached
// columns of its inverse, with an active-set iteration per step (a dropper slackens when its
// tension would become negative, a contact opens when its force would).
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <string>
#include <vector>

#include "inerta/catenary/fe_data.hpp"

namespace inerta::catenary {

/// The assembled line: mesh, matrices and the form-found static state. Immutable.
// Sparse Cholesky in the line's own DOF order: the DOFs are numbered along the line, so the matrices
// are banded (half bandwidth 7) and a fill-reducing ordering only costs time.
namespace compile {
struct Wires;
struct FormFound;
struct Irregular;
}  // namespace compile

using BandLlt = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>;

class FeLine {
 public:
  explicit FeLine(FeCatenaryData data);
  const FeCatenaryData& data() const { return d_; }

  int n_nodes() const { return static_cast<int>(x_.size()); }  ///< stations along the line (both wires)
  int n_dofs() const { return n_dofs_; }
  double length() const { return d_.span * d_.spans; }
  const std::vector<double>& node_x() const { return x_; }
  /// Free-DOF index of wire `w` (0 messenger, 1 contact wire, 2 stitch wire) at node i, component c
  /// (0: w, 1: θ); −1 where the DOF is fixed (the line's ends) or absent (no stitch wire there; a
  /// stitch wire's w at its clamps is the messenger's).
  int dof(int wire, int node, int c) const;
  static constexpr int kWires = 3;

  const Eigen::SparseMatrix<double>& M() const { return M_; }
  const Eigen::SparseMatrix<double>& K() const { return K_; }  ///< K₀: all droppers taut (the dynamics)
  /// The static stiffness: K with each dropper's own EA/length (the static state, elasticity); K
  /// itself unless an irregular line's dropper lengths differ from the design (FeIrregularity).
  const Eigen::SparseMatrix<double>& K_static() const { return K_static_; }
  const Eigen::SparseMatrix<double>& C() const { return C_; }

  struct Dropper {
    double x;          ///< m along the line
    int node;          ///< station
    int dof_m, dof_c;  ///< free DOFs of w at its messenger and contact-wire ends
    double length;     ///< unstretched length from the form-finding, m
    double stiffness;  ///< N/m, in the dynamics (K): EA / its designed length (FeIrregularity::exact_dropper_dynamics)
    double tension;    ///< static tension, N (negative: slack in the static state of an irregular line)
    /// Where it hangs from: the messenger (a span dropper, or a stitch dropper without its stitch
    /// wire) or a stitch wire (dof_m is then the stitch wire's w).
    enum class Kind { Span, Stitch } kind = Kind::Span;
    bool on_stitch_wire = false;
    int index = 0;     ///< its position in droppers.x (Span) or stitch.droppers.x (Stitch)
    double EA = 0;                 ///< N
    double mass_per_length = 0;    ///< kg/m (half its mass lumped at each end)
    double clamp_upper = 0, clamp_contact = 0;  ///< kg, clamp masses at its two ends
    double static_stiffness = 0;   ///< EA / length, N/m: the static state's (K_static)
  };
  const std::vector<Dropper>& droppers() const { return droppers_; }
  /// Interior masts (the line's end masts are anchors): x and the contact wire's w DOF there.
  const std::vector<double>& support_x() const { return support_x_; }
  const std::vector<int>& support_dofs() const { return support_dofs_; }

  /// Static heights (form-found state, no pantograph) of the contact wire at x, and its slope.
  double static_height(double x) const;
  double static_slope(double x) const;
  /// Shape of the contact wire at x: the 4 free-DOF indices (−1: fixed) and the Hermite values N,
  /// and their x-derivatives dN. ModelError outside [0, length()].
  struct Shape {
    int node;  ///< the element's first station
    std::array<int, 4> dofs;
    std::array<double, 4> N, dN;
  };
  Shape contact_shape(double x) const;
  double contact_displacement(const Eigen::VectorXd& u, double x) const;  ///< N(x)ᵀ u
  Eigen::VectorXd load_vector(double x, double F) const;  ///< F N(x): an upward point force F at x
  /// Messenger height at station i in the static state, m (encumbrance at the masts).
  double messenger_height(int node) const { return messenger_y_[static_cast<std::size_t>(node)]; }
  /// Largest |form-found − nominal| dropper length, m (0 without nominal lengths; span droppers only).
  double dropper_length_error_max() const;
  /// Stitch-wire height at station i in the static state (m; NaN where there is none).
  double stitch_height(int node) const;
  /// The static state's equilibrium, checked on the assembled line itself (not the form-finding's
  /// equations): the largest |K_w w − f_g − Σ T_d b_d| over the free DOFs other than the masts'
  /// (N; K_w the wires' and supports' stiffness, w the static heights, f_g gravity, T_d the dropper
  /// tensions), and the largest |T_d − EA/L₀ (ℓ_d − L₀)| of the taut droppers (N). The static state
  /// of an irregular line is the form-found one displaced by static_displacement({}, {}) (its slack
  /// droppers carry nothing).
  struct Residual {
    double force = 0, dropper = 0, load_scale = 0;  ///< N; load_scale: the largest gravity load of a DOF
  };
  Residual equilibrium_residual() const;

  /// Linear static uplift per newton at x (all droppers taut): N(x)ᵀ K₀⁻¹ N(x), m/N.
  double elasticity(double x) const;
  /// Static displacement under upward point forces F_k at x_k on the contact wire, droppers free to
  /// slacken (active-set); `slack` receives which droppers are slack.
  Eigen::VectorXd static_displacement(const std::vector<double>& x, const std::vector<double>& F,
                                      std::vector<char>* slack = nullptr) const;

  std::string describe() const;

 private:
  FeCatenaryData d_;
  std::vector<double> x_;
  int n_dofs_ = 0;
  std::vector<int> dof_;  ///< [wire][node][c] → free DOF or −1
  Eigen::SparseMatrix<double> M_, K_, C_;
  std::vector<Dropper> droppers_;
  std::vector<double> support_x_;
  std::vector<int> support_dofs_;
  std::vector<double> y_contact_;  ///< form-found contact-wire heights at the nodes
  std::vector<double> s_contact_;  ///< and slopes
  std::vector<double> messenger_y_;
  std::vector<double> stitch_y_;   ///< form-found stitch heights at the nodes (NaN: none)
  Eigen::SparseMatrix<double> K_wires_;  ///< wires and supports, no droppers (equilibrium_residual)
  Eigen::VectorXd f_gravity_;      ///< gravity on the wires, clamps, droppers and point masses
  Eigen::VectorXd w_static_;       ///< the heights of the reference state, per DOF (w from its reference)
  Eigen::VectorXd g_dofs_;         ///< a section's straight line between its anchors' heights, per DOF (empty: none)
  Eigen::VectorXd g_anchor_force_; ///< K's columns of pinned anchors' w times g there (empty: none)
  Eigen::SparseMatrix<double> K_static_;
  BandLlt K_llt_;  ///< of K_static_
  /// The last pass of the compilation (src/catenary/fe_assembly.cpp): K, K_static, M, C, gravity, the static state.
  void assemble(const compile::Wires& w, const compile::FormFound& ff, const compile::Irregular& irr);
  friend class FeIntegrator;
};

}  // namespace inerta::catenary
