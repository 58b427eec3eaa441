#pragma once
// Modal solve of the finite-element line (spec/05 §5.3; docs/catenary-fe.md "Modal solver").
//
// A run sees a window of whole spans around its pantographs: `window_behind` spans behind the
// rearmost pantograph's span and `window_ahead` spans ahead of the leading one's. At a window end
// that is not the line's own end, each wire ends on a dashpot sqrt(T ρA) (the impedance of a
// tensioned string: waves leave the window rather than reflect; a local force like the contacts). In the window, u = Φ q with Φ the M-orthonormal modes of
// (K₀, M) (droppers taut) below `modal_cutoff`, each mode a damped oscillator
//   q̈_i + (a + b ω_i²) q̇_i + ω_i² q_i = φ_iᵀ f       (Rayleigh C = a M + b K₀)
// stepped by the same HHT-α formulas as the direct solve (with every mode kept, the two agree to
// round-off). The local forces — penalty contacts (shape N(x)) and slack droppers (b = e_m − e_c,
// the taut dropper's force (T₀ + k bᵀu) removed) — are rank-one terms solved exactly in the modal
// space by the Woodbury identity, within the same active-set iteration as the direct solve, and
// the modes left out act on them quasi-statically through the residual flexibility
//   R(w_a, w_b) = w_aᵀ (K₀⁻¹ − Φ Ω⁻² Φᵀ) w_b
// (K₀⁻¹ columns by the window's band Cholesky), so that the static response to them is exact.
// When the pantographs enter a new span the window moves on by a span: the state on the spans both
// windows share is carried over (q' = Φ'ᵀ M' u), the span left behind is dropped, the one ahead
// starts at rest. The work of a step does not depend on the length of the line.
//
// Modes: spectrum slicing with shift-invert Lanczos (Spectra) on the band matrices, the number of
// eigenvalues in each slice known beforehand from the inertia of K₀ − σM (Sylvester), slices in
// parallel (numerics/generalised_eigen.hpp). Windows of the same shape and matrices (every interior window of a uniform line) share
// one decomposition; a window that is the mirror image of another (the last window of a symmetric
// line, of the first) takes its modes reordered.
// Sources: the windows and their mode sets in fe_modal_windows.cpp, the per-run solver in fe_modal.cpp.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <atomic>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/mode_store.hpp"
#include "inerta/numerics/band.hpp"
#include "inerta/numerics/generalised_eigen.hpp"

namespace inerta::catenary {

// The eigensolver and the band algebra the modal solve uses (numerics layer).
using numerics::BandInverse;
using numerics::lowest_modes;
using numerics::Modes;

/// One window shape: its matrices, modes, the band Cholesky factor of K₀ and what the residual
/// flexibility needs: K₀⁻¹ within the band and its columns at the "special" DOFs (each dropper's
/// messenger and contact-wire ends, then the absorbing ends).
struct FeWindowModes {
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::SparseMatrix<double> M, K;
  Eigen::VectorXd omega2;  ///< m
  /// n_w × m, a DOF a row: in memory of its own or in a mapping of the mode store's file (`phi_owner`).
  Eigen::Map<const RowMatrix> phi{nullptr, 0, 0};
  std::shared_ptr<const void> phi_owner;
  void set_phi(std::shared_ptr<const void> owner, const double* data, Eigen::Index n, Eigen::Index m);
  /// A mapped Φ's damage flag and file (catenary/mode_store.hpp): check_intact() throws a
  /// NumericalError naming the file (and the simulated time t, if finite) once the file was cut short under it.
  const std::atomic<int>* phi_damaged = nullptr;
  std::filesystem::path phi_file;
  void check_intact(double t) const {
    if (phi_damaged && phi_damaged->load(std::memory_order_relaxed)) throw_damaged(t);
  }
  [[noreturn]] void throw_damaged(double t) const;
  std::uint64_t phi_device = 0, phi_inode = 0, phi_bytes = 0;
  /// Damaged, or its file (the same one) now shorter than mapped: pages not yet read are gone too.
  bool cut_short() const;
  int kd = 0;                    ///< half bandwidth of K
  std::vector<double> cholesky;  ///< K = L Lᵀ, LAPACK lower band storage
  BandInverse band;              ///< K⁻¹ within the band
  std::vector<int> special;      ///< local DOFs
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> kinv_special;  ///< n_w × special: K⁻¹ columns
  void solve_K(Eigen::VectorXd& b, int first = 0) const;  ///< b ← K⁻¹ b (b zero before `first`)
};

/// A window of the line: spans [first_span, first_span + spans), its free DOFs (global, ascending)
/// and the modes of its shape.
struct FeWindow {
  int first_span = 0, spans = 0, first_node = 0, last_node = 0;
  std::vector<int> dofs;
  /// Absorbing ends: at a window end that is not the line's own end, a dashpot sqrt(T ρA) on each
  /// wire's w (a tensioned string's impedance: a wave leaves the window instead of being reflected).
  struct End {
    int local;
    double damping;  ///< N·s/m
  };
  std::vector<End> ends;
  std::vector<int> droppers;  ///< the line's droppers in the window, in order
  std::shared_ptr<const FeWindowModes> modes;
  int local(int global) const;  ///< index in dofs, −1 if not in the window (held or outside)
};

/// The modal data of one FeLine: the windows' decompositions, made when first asked for and kept
/// (thread-safe). Immutable for its users.
class FeModalLine {
 public:
  /// `store`: where decompositions are kept between processes (none: always solved here).
  explicit FeModalLine(std::shared_ptr<const FeLine> line, std::optional<ModeStore> store = std::nullopt);
  /// Waits for the mode store's writes (flush_store).
  ~FeModalLine();
  FeModalLine(const FeModalLine&) = delete;
  FeModalLine& operator=(const FeModalLine&) = delete;
  const FeLine& line() const { return *line_; }
  /// Spans of a window for pantographs spread over `spread` m (the whole line at most).
  int window_spans(double spread) const;
  /// The window of `spans` spans starting at first_span (decomposed on first use).
  std::shared_ptr<const FeWindow> window(int first_span, int spans) const;
  /// Every window of `spans` spans, the distinct shapes decomposed in parallel (a run calls it first).
  void prepare(int spans) const;
  int mast_node(int mast) const { return mast_node_[static_cast<std::size_t>(mast)]; }
  int decompositions() const;  ///< eigenproblems solved so far
  int loaded() const;          ///< decompositions read from the store so far
  const std::optional<ModeStore>& store() const { return store_; }
  /// Waits until the decompositions solved so far are in the store: they are written on their own
  /// threads while the run goes on (issue 39), so a run does not wait for ≈ 120 MB of writes.
  void flush_store() const;
  int shapes() const;          ///< distinct window shapes so far (a mirrored one needs no eigenproblem)

 private:
  std::shared_ptr<const FeLine> line_;
  std::vector<int> mast_node_;
  mutable std::mutex mutex_;
  mutable std::map<std::pair<int, int>, std::shared_ptr<const FeWindow>> windows_;
  mutable std::vector<std::shared_ptr<const FeWindowModes>> shapes_;
  std::optional<ModeStore> store_;
  mutable std::atomic<int> solved_{0}, loaded_{0};
  mutable std::mutex writes_mutex_;
  mutable std::shared_future<void> last_write_;  // the writes run one after the other (the store's size limit)
  std::shared_ptr<FeWindow> structure(int first_span, int spans, Eigen::SparseMatrix<double>& K,
                                      Eigen::SparseMatrix<double>& M) const;
  /// Its modes (read from the store, else made by `make` — a mirrored shape's — or solved, then
  /// stored), factor and residual data.
  std::shared_ptr<const FeWindowModes> decompose(const FeWindow& w, Eigen::SparseMatrix<double> K,
                                                 Eigen::SparseMatrix<double> M,
                                                 const std::function<Modes()>& make = {}) const;
  std::vector<std::pair<int, double>> mirror(const FeWindow& a, const FeWindow& b) const;
  /// Forgets the windows and shapes whose mapped mode file was cut short (a run stopped on one, or
  /// the file is now shorter than mapped), so that the next run solves them anew (mutex_ held).
  void drop_damaged() const;
  std::shared_ptr<const FeWindowModes> find_shape(const Eigen::SparseMatrix<double>& K,
                                                  const Eigen::SparseMatrix<double>& M) const;
};

/// The modal solve of a run (header comment).
std::unique_ptr<FeLineSolver> make_modal_solver(std::shared_ptr<const FeModalLine> modal, double spread);
/// The modal solve of `lanes` runs stepped together (FeLineLanes): one window, its matrices, the
/// loads' modal rows and couplings shared; the droppers' rows applied to every lane's state in one pass.
std::unique_ptr<FeLineLanes> make_modal_lanes(std::shared_ptr<const FeModalLine> modal, double spread, int lanes);

}  // namespace inerta::catenary
