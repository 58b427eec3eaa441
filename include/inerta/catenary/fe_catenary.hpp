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
#include <atomic>
#include <cstdint>
#include <mutex>
#include <memory>
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/catenary/lumped.hpp"

namespace inerta::catenary {

/// A tensioned wire.
struct FeWire {
  double tension = 0;          ///< T, N
  double mass_per_length = 0;  ///< ρA, kg/m
  double EI = 0;               ///< bending stiffness, N·m²
  double wave_speed() const;   ///< sqrt(T/ρA), m/s
};

/// Element matrices of a tensioned Euler–Bernoulli beam on [w_i, θ_i, w_j, θ_j] (header comment).
Eigen::Matrix4d beam_stiffness(double EI, double tension, double length);
Eigen::Matrix4d beam_mass(double mass_per_length, double length);

/// A stitch wire at a mast (docs/catenary-fe.md "Stitch wire"): a short tensioned wire of `length`
/// centred on the mast, its ends clamped to the messenger (the same vertical displacement, slopes
/// free), not supported at the mast, from which the droppers near the mast hang (`dropper_x`: signed
/// positions from the mast, negative in the span before it). Every interior mast carries one; the
/// line's two end masts (anchors) carry none, and the stitch droppers on the line's side of an end
/// mast hang from the messenger there. `enabled = false`: the same line without the stitch wire,
/// every stitch dropper hanging from the messenger at its position.
struct FeStitch {
  bool present = false;          ///< the file has a `stitch:` section
  bool enabled = true;
  double length = 0;             ///< m, between its two clamps on the messenger
  FeWire wire;                   ///< tension (N), mass per length (kg/m), EI (N·m²)
  double clamp_mass = 0;         ///< kg, at each of its two clamps on the messenger
  std::vector<double> dropper_x;       ///< m from the mast, signed, |x| < length / 2
  std::vector<double> dropper_presag;  ///< m, contact-wire pre-sag at each (positive down); empty: 0
  double dropper_EA = 200e3;               ///< N
  double dropper_mass_per_length = 0;      ///< kg/m
  double clamp_mass_stitch = 0;            ///< kg, at each stitch dropper's upper end
  double clamp_mass_contact = 0;           ///< kg, at each stitch dropper's contact-wire end
};

/// Irregularities of the line (docs/catenary-fe.md "Irregularities"), applied to the form-found line.
struct FeIrregularity {
  /// m: random dropper-length errors, normal N(0, std²) truncated at ±4 std (a draw beyond is drawn
  /// again), from splitmix64-seeded xoshiro256** and Box–Muller (the same numbers on every platform);
  /// 0: none. One value per dropper in line order (stitch droppers included).
  double dropper_length_std = 0;
  std::uint64_t seed = 1;
  /// m, explicit per-dropper length errors in line order (added to the random ones); empty: none.
  std::vector<double> dropper_length_errors;
  /// A contact-wire height-error profile (x m, Δz m, up): interpolated linearly at the droppers and
  /// added to the form-finding's target heights (an installation error). Empty: none.
  std::vector<double> height_error_x, height_error_dz;
  std::string height_errors_file;  ///< where the profile was read from (for messages)
  struct PointMass {
    double x;     ///< m along the line
    double mass;  ///< kg
  };
  std::vector<PointMass> point_masses;  ///< hard spots on the contact wire (clamps, section insulators)
  /// The dynamics (K, M) with each dropper's own stiffness EA/L' and mass; false (default): with the
  /// designed droppers' (the form-finding without errors), so that the modal solve keeps the perfect
  /// line's modes (docs/catenary-fe.md "Irregularities"). The static state is exact either way.
  bool exact_dropper_dynamics = false;
  bool any() const {
    return dropper_length_std > 0 || !dropper_length_errors.empty() || !height_error_x.empty() || !point_masses.empty();
  }
};

/// The random dropper-length errors of `irr` for `count` droppers (m; FeIrregularity header).
std::vector<double> dropper_length_errors(const FeIrregularity& irr, std::size_t count);

/// Everything a catenary file gives (docs/model-format.md#finite-element-catenary).
struct FeCatenaryData {
  double span = 55;          ///< m, distance between masts
  int spans = 10;            ///< number of spans; masts at x = 0, span, …, spans·span
  double encumbrance = 1.2;  ///< m, messenger height above the contact wire at the masts
  std::vector<double> dropper_x;  ///< m from the span's first mast, strictly inside (0, span), increasing
  std::vector<double> presag;     ///< m, contact-wire pre-sag at each dropper (positive down)
  std::vector<double> nominal_dropper_length;  ///< m, optional (for comparison with the form-finding)
  FeWire messenger, contact_wire;
  double dropper_EA = 200e3;                 ///< N
  double dropper_mass_per_length = 0.117;    ///< kg/m
  double clamp_mass_messenger = 0.195;       ///< kg, at each dropper's messenger end
  double clamp_mass_contact = 0.165;         ///< kg, at each dropper's contact-wire end
  double support_stiffness = 500e3;          ///< N/m, messenger support at each mast
  double support_mass = 0;                   ///< kg, at each messenger support
  double registration_stiffness = 2673.58;   ///< N/m, contact-wire registration (steady arm) at each mast
  double registration_mass = 0;              ///< kg, at each registration
  /// m, the design limit of the contact wire's uplift at a registration (steady arm); NaN: not given
  /// (the acceptance criterion support_uplift is then not assessed). Not part of the dynamics.
  double registration_uplift_limit = NAN;
  /// A stop limits the registration's uplift physically (registration.uplift_limited: true): the acceptance
  /// criterion support_uplift takes its limited_clearance_factor (1.5 S₀) in place of 2 S₀. Not part of the dynamics.
  bool registration_uplift_limited = false;
  double element_length = 0.25;              ///< m, largest element; nodes at every dropper and mast
  double rayleigh_mass = 0.0125;             ///< a, 1/s
  double rayleigh_stiffness = 1e-4;          ///< b, s
  double gravity = 9.81;                     ///< m/s²
  double time_step = 1e-3;                   ///< s, structural (and coupling) step
  double hht_alpha = 0.0;                    ///< α of HHT-α, in [−1/3, 0]
  /// Structural solver of a run: the modal solve of a window of spans around the pantographs
  /// (fe_modal.hpp; `solver: modal` in models/catenary-fe.yaml) or the direct solve of the whole
  /// line (the reference; the default of a file without `solver`, so that older files keep their results).
  enum class Solver { Modal, Direct } solver = Solver::Direct;
  double modal_cutoff = 100; ///< Hz, highest natural frequency kept (droppers taut)
  int window_behind = 2;     ///< spans of the window behind the rearmost pantograph's span; −1: the whole line
  int window_ahead = 3;      ///< spans ahead of the leading pantograph's span; −1: the whole line
  int section_first = -1, section_last = -1;  ///< analysis section: spans first..last (1-based); −1: default
  FeStitch stitch;            ///< none unless stitch.present
  FeIrregularity irregularity;
  bool has_stitch() const { return stitch.present && stitch.enabled; }

  // A tension section of a longer line (docs/catenary-fe.md "Tension sections and overlaps").
  /// m: the contact wire's height at each mast (spans + 1 values, the end masts its anchors; empty:
  /// 0 at every mast). The messenger is `encumbrance` above it at every mast, the droppers' targets
  /// are the heights interpolated linearly between the masts, less the pre-sag.
  std::vector<double> mast_height;
  /// m: the contact wire's height profile, piecewise linear through the points (height_x from the
  /// section's first mast, strictly increasing from 0 to its length; height_z up): the droppers'
  /// targets between masts, e.g. an overlap's middle span with both wires at the running height over
  /// part of it. Empty: mast_height, linear between the masts. link_sections sets both.
  std::vector<double> height_x, height_z;
  /// The height at x (m from the section's first mast): height_x/z, else mast_height, else 0.
  double height_at(double x) const;
  /// The anchors at the section's two ends: pinned (w = 0), or a tensioning device's vertical
  /// stiffness (N/m) and mass (kg) on both wires' ends.
  struct Anchor {
    bool pinned = true;
    double stiffness = 0, mass = 0;
  } anchor;
  double line_start = 0;  ///< m: x of this section's first mast along the whole line
  int first_span = 0;     ///< its first span among the line's (0-based)
  int wire_label = 1;     ///< which contact wire it is along the line: 1 (odd sections) or 2 (even)

  /// The line's tension sections, each a whole section (the fields above set); consecutive ones
  /// overlap over `overlap_spans` spans (they share overlap_spans + 1 masts). Empty: the line is one
  /// section, pinned at height 0 at both ends (every file before issue 35).
  std::vector<FeCatenaryData> tension_sections;
  int overlap_spans = 0;
  /// m: the contact wire's heights over an overlap, in line order: the section that ends there
  /// (outgoing; its last value is at its anchor) and the one that starts (incoming; its first value
  /// at its anchor). Without overlap_*_x, one height per overlap support (overlap_spans + 1 values);
  /// with them, a piecewise-linear profile through (x, height), x in m from the overlap's first
  /// support, strictly increasing from 0 to overlap_spans spans.
  std::vector<double> overlap_outgoing, overlap_incoming;
  std::vector<double> overlap_outgoing_x, overlap_incoming_x;
  bool sectioned() const { return !tension_sections.empty(); }
  /// The whole line's spans (the sections' less the overlaps), for a sectioned line.
  int line_spans() const;
  /// Sets each section's place along the line (line_start, first_span, wire_label), its mast
  /// heights from the overlaps and the line's `spans`; InvalidArgument naming the key
  /// (tension_sections[k].…, overlap.…) when the sections cannot form a line.
  void link_sections();
  /// InvalidArgument naming the offending value.
  void validate() const;
};

/// The assembled line: mesh, matrices and the form-found static state. Immutable.
// Sparse Cholesky in the line's own DOF order: the DOFs are numbered along the line, so the matrices
// are banded (half bandwidth 7) and a fill-reducing ordering only costs time.
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
  friend class FeIntegrator;
};

/// The structural solver of one run on the line (a workspace, one per run): the direct HHT-α solve
/// of the whole line (FeIntegrator) or the modal solve of a moving window (FeModalSolver). Heights
/// are absolute; x along the line.
struct FeLoad;
class FeLineSolver {
 public:
  virtual ~FeLineSolver() = default;
  virtual double dt() const = 0;
  virtual double time() const = 0;
  /// At rest in the static equilibrium under upward forces F_k at x_k, at time t.
  virtual void start(const std::vector<double>& x, const std::vector<double>& F, double t) = 0;
  /// One step to time() + dt() with the loads at its end; `forces`: the upward force of each load.
  virtual void step(const std::vector<FeLoad>& loads, std::vector<double>& forces) = 0;
  virtual double height(double x) const = 0;                     ///< contact wire at x, m
  virtual double height_rate(double x, double speed) const = 0;  ///< at the point moving with speed, m/s
  virtual double uplift(double x) const = 0;                     ///< contact wire at x from its static state, m
  virtual std::vector<double> support_uplift() const = 0;        ///< contact wire at each interior mast, m
  /// Kinetic + elastic energy relative to the static state (slack droppers' springs removed), J.
  virtual double energy() const = 0;
};

/// A load on the contact wire at x for one step: either a prescribed upward force, or a penalty
/// contact with a head whose height and vertical velocity at the end of the step are given
/// (absolute heights: the wire at x is at static_height(x) + N(x)ᵀu).
struct FeLoad {
  double x = 0;
  bool penalty = false;
  double force = 0;                ///< N, prescribed (penalty = false)
  double head_y = 0, head_v = 0;   ///< m, m/s (penalty)
  double stiffness = 0, damping = 0;
  double speed = 0;                ///< m/s, for the convective part of the wire's velocity
};

/// The line's dynamic state: displacements from the static state, velocities, accelerations.
struct FeState {
  Eigen::VectorXd u, v, a;
  std::vector<char> slack;   ///< per dropper
  std::vector<char> active;  ///< per penalty load of the last step: in contact
  Eigen::VectorXd q;         ///< net internal force at this time (HHT-α only)
  double t = 0;
};

/// HHT-α stepping of one FeLine with a fixed step; holds the factorisation and the cache of
/// columns of its inverse (a workspace: one per run, not shared between threads).
class FeIntegrator {
 public:
  FeIntegrator(const FeLine& line, double dt, double alpha);
  double dt() const { return h_; }
  const FeLine& line() const { return L_; }
  /// The line at rest in its static equilibrium under upward forces F_k at x_k (droppers free to
  /// slacken), at time t.
  FeState initial(const std::vector<double>& x, const std::vector<double>& F, double t = 0) const;
  /// One step from s.t to s.t + dt() with the loads at the end of the step; `forces` receives the
  /// upward force on the wire of each load (N; 0 for an open contact). NumericalError (with t) if
  /// the active set of droppers and contacts does not settle.
  void step(FeState& s, const std::vector<FeLoad>& loads, std::vector<double>& forces);
  /// Kinetic + elastic energy relative to the static state (droppers as in s.slack), J.
  double energy(const FeState& s) const;
  /// Wire height (m, absolute) and its vertical velocity (m/s) at the moving point x with speed.
  double height(const FeState& s, double x) const;
  double height_rate(const FeState& s, double x, double speed) const;
  long solves() const { return solves_; }
  long active_set_passes() const { return passes_; }

 private:
  const Eigen::VectorXd& column(int dof);  ///< A⁻¹ e_dof, cached (least recently used evicted)
  void solve(Eigen::VectorXd& b) const;    ///< b ← A⁻¹ b (banded Cholesky, LAPACK)
  const FeLine& L_;
  double h_, alpha_, beta_, gamma_;
  double c0_, c1_, c2_, c3_, c4_, c5_;
  int kd_ = 0;                ///< half bandwidth of A
  std::vector<double> band_;  ///< Cholesky factor of A, LAPACK lower band storage
  std::vector<double> rdiag_;  ///< 1 / its diagonal
  std::vector<double> mk_band_;  ///< M and (1+α) b K₀, lower band storage interleaved per column
  void band_products(const Eigen::VectorXd& w, const Eigen::VectorXd& v, Eigen::VectorXd& r) const;  ///< r = M w + Kb v
  std::vector<Eigen::VectorXd> contact_z_, dropper_z_;
  std::vector<int> slot_of_;  ///< per DOF: cache slot or −1
  std::vector<Eigen::VectorXd> cache_;
  std::vector<int> cache_dof_;
  std::vector<long> cache_used_;
  long clock_ = 0;
  mutable long solves_ = 0;
  long passes_ = 0;
  Eigen::VectorXd r_, x0_, w1_, w2_, vt_;
};

/// The lumped catenary of eq. 7.1 fitted to the line (spec/05 §5.3): along one span, the point
/// stiffness k(x) = 1/e(x) (e: FeLine::elasticity), the equivalent moving mass
/// m(x) = gᵀ M g / e², the mass of the static deflection shape g = K₀⁻¹ N(x) under a unit force at
/// x seen at x (the low-frequency expansion 1/H(ω) ≈ k − m ω² of the point receptance), and the
/// damping c(x) = gᵀ C g / e² are sampled and expanded in cosines of 2π i x / L, i = 0..3 (x = 0 at
/// a mast): the coefficients k_ci, m_ci, c_ci of eq. 7.1.
struct LumpedFit {
  LumpedCatenary lumped;
  int span = 0;  ///< the span fitted (1-based)
  std::vector<double> x;  ///< m from the span's first mast
  std::vector<double> elasticity, mass, damping;  ///< FE values at x: m/N, kg, N·s/m
  std::vector<double> fitted_elasticity;          ///< 1 / (lumped k_c at x), m/N
  double max_elasticity_error = 0;                ///< max |fitted − FE| / FE over x
  /// The same with the FE elasticity averaged over one dropper spacing around x (the span-scale
  /// variation that three harmonics can follow; the dropper-scale wiggles they cannot).
  double max_smoothed_error = 0;
  double rms_error = 0, rms_smoothed_error = 0;  ///< root-mean-square of the same relative errors
};
/// span: 1-based, 0 = the middle span. points: samples along the span (>= 16).
LumpedFit fit_lumped(const FeLine& line, int span = 0, int points = 220);

/// The cost of work on a finite-element line before it starts, from its data alone (nothing is
/// built), on the 2-core reference machine (docs/benchmarks.md "Run-time estimate"): a guide for
/// the cost guard, not a bound.
struct FeCostEstimate {
  double unknowns = 0;  ///< of the line's mesh (FeLine::n_dofs() without building it)
  double setup = 0;     ///< s: mesh, matrices, form-finding and factorisation of the line
  double modes = 0;     ///< s: the first decomposition of the modal solve's windows (0: direct solve)
  double run = 0;       ///< s: the time steps
  double bytes = 0;     ///< memory kept: the line's matrices and factor, the windows' modes
  double total() const { return setup + modes + run; }
};
/// The unknowns of the line's mesh (both wires, w and θ at every node, w fixed at the ends).
double mesh_unknowns(const FeCatenaryData& d);
/// A run with pantographs at x0 (m) at `speed` (m/s) for t_end s (≤ 0: until the leading one
/// reaches the line's end); `setup`/`modes`: include building the line / its first modes.
FeCostEstimate estimate_cost(const FeCatenaryData& d, const std::vector<double>& x0, double speed, double t_end,
                             bool setup = true, bool modes = true);

/// One tension section as a run sees it: its line (x local, from its first mast), its modes (null:
/// the direct solve), where it lies along the whole line and which contact wire it is.
struct FeSectionLine {
  std::shared_ptr<const FeLine> line;
  std::shared_ptr<const class FeModalLine> modal;
  double start = 0, end = 0;  ///< m along the whole line: its first and last mast (its anchors)
  int wire = 1;               ///< 1 or 2 (FeCatenaryData::wire_label)
};

/// The finite-element catenary as a catenary type (co-simulated: the line is stepped by
/// FeIntegrator, each pantograph's multibody model by the multibody integrator; see fe_coupled).
/// The line (mesh, form-finding, factorisation) is built when first needed, not by the constructor,
/// so that a run's cost can be estimated — and refused — before any of that work (the cost guard).
class FeCatenary final : public Catenary {
 public:
  /// Checks the data (FeCatenaryData::validate); builds nothing.
  explicit FeCatenary(FeCatenaryData data);
  const FeCatenaryData& data() const { return data_; }
  const FeLine& line() const;  ///< built on first use (thread-safe)
  std::string describe() const override;
  double span() const override { return data_.span; }
  int max_pantographs() const override { return 64; }
  double line_length() const override;
  /// The overlaps of a line of tension sections: from the incoming section's anchor to the outgoing one's.
  std::vector<Section> overlaps() const;
  double wave_speed() const override { return data_.contact_wire.wave_speed(); }
  std::vector<LineFeature> features() const override;
  Section section() const override;
  double uplift_limit() const override { return data_.registration_uplift_limit; }  // the file's: no build needed
  bool uplift_limited() const override { return data_.registration_uplift_limited; }
  std::shared_ptr<const Catenary> mean() const override;
  /// The modes of the line's windows (computed when first needed, kept for every later run: a sweep
  /// or a study decomposes a window once); nullptr with solver: direct.
  std::shared_ptr<const class FeModalLine> modal() const;
  /// The line's tension sections (one for a file without tension_sections: line() and modal()).
  const std::vector<FeSectionLine>& sections() const;
  void prepare(const std::vector<PantographOnLine>& pantographs) const override;
  double estimated_seconds(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const override;
  double estimated_setup_seconds(const std::vector<PantographOnLine>& pantographs) const override;
  double estimated_bytes(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const override;

 protected:
  std::unique_ptr<Coupled> make_coupled(const std::vector<PantographOnLine>& pantographs, double speed) const override;

 private:
  void build() const;
  FeCostEstimate estimate(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const;
  FeCatenaryData data_;
  mutable std::once_flag built_;
  mutable std::atomic<bool> line_ready_{false};
  mutable std::shared_ptr<const FeLine> line_;
  mutable std::shared_ptr<const class FeModalLine> modal_;
  mutable std::vector<FeSectionLine> sections_;
};

/// The direct solve of the whole line (FeIntegrator) as a run's solver.
std::unique_ptr<FeLineSolver> make_direct_solver(const FeLine& line);

}  // namespace inerta::catenary
