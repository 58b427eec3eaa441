// The modal solve's windows and their mode sets (catenary/fe_modal.hpp, spec/05 §5.3): a window's
// DOFs and matrices, the shapes shared between windows (equal or mirrored), each shape's modes (from
// the mode store or solved), its band Cholesky factor and residual-flexibility data.
#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <sys/stat.h>

#include "inerta/catenary/fe_modal.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/band.hpp"
#include "inerta/numerics/phase_times.hpp"

namespace inerta::catenary {

using Sparse = Eigen::SparseMatrix<double>;

void FeWindowModes::solve_K(Eigen::VectorXd& b, int first) const {
  numerics::band_cholesky_solve(cholesky.data(), static_cast<int>(b.size()), kd, b.data(), first);
}

void FeWindowModes::set_phi(std::shared_ptr<const void> owner, const double* data, Eigen::Index n, Eigen::Index m) {
  phi_owner = std::move(owner);
  new (&phi) Eigen::Map<const RowMatrix>(data, n, m);
}

void FeWindowModes::throw_damaged(double t) const {
  throw NumericalError(fmt::format(
      "finite-element catenary (modal): {}the mode file {} was cut short while this run read it (by "
      "another program?); its modes are gone, so the run stops rather than give results from them. Run again: the "
      "file no longer matches and the modes are solved anew",
      std::isfinite(t) ? fmt::format("t = {:.6g} s: ", t) : std::string(), phi_file.string()));
}

bool FeWindowModes::cut_short() const {
  if (!phi_damaged) return false;
  if (phi_damaged->load()) return true;
  struct stat st {};
  return ::stat(phi_file.c_str(), &st) == 0 && static_cast<std::uint64_t>(st.st_dev) == phi_device &&
         static_cast<std::uint64_t>(st.st_ino) == phi_inode && static_cast<std::uint64_t>(st.st_size) < phi_bytes;
}

int FeWindow::local(int global) const {
  const auto it = std::lower_bound(dofs.begin(), dofs.end(), global);
  return it != dofs.end() && *it == global ? static_cast<int>(it - dofs.begin()) : -1;
}

FeModalLine::FeModalLine(std::shared_ptr<const FeLine> line, std::optional<ModeStore> store)
    : line_(std::move(line)), store_(std::move(store)) {
  const FeCatenaryData& d = line_->data();
  if (!(d.modal_cutoff > 0) || !std::isfinite(d.modal_cutoff))
    throw InvalidArgument("finite-element catenary: solver", "cutoff", fmt::format("must be > 0 Hz, got {}", d.modal_cutoff));
  const std::vector<double>& x = line_->node_x();
  for (int s = 0; s <= d.spans; ++s) {
    const auto it = std::lower_bound(x.begin(), x.end(), s * d.span - 1e-9);
    mast_node_.push_back(static_cast<int>(it - x.begin()));
  }
}

FeModalLine::~FeModalLine() { flush_store(); }

void FeModalLine::flush_store() const {
  std::shared_future<void> last;
  {
    const std::lock_guard lock(writes_mutex_);
    last = last_write_;
  }
  if (last.valid()) last.wait();
}

int FeModalLine::window_spans(double spread) const {
  const FeCatenaryData& d = line_->data();
  if (d.window_behind < 0 || d.window_ahead < 0) return d.spans;
  const int extra = static_cast<int>(std::ceil(spread / d.span - 1e-9));
  return std::min(d.spans, d.window_behind + 1 + d.window_ahead + extra);
}

int FeModalLine::decompositions() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return solved_;
}

int FeModalLine::loaded() const { return loaded_; }

int FeModalLine::shapes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(shapes_.size());
}

std::shared_ptr<FeWindow> FeModalLine::structure(int first_span, int spans, Sparse& K, Sparse& M) const {
  const FeLine& L = *line_;
  auto w = std::make_shared<FeWindow>();
  w->first_span = first_span, w->spans = spans;
  w->first_node = mast_node(first_span), w->last_node = mast_node(first_span + spans);
  for (int node = w->first_node; node <= w->last_node; ++node)
    for (int wire = 0; wire < FeLine::kWires; ++wire)
      for (int c = 0; c < 2; ++c)
        if (const int g = L.dof(wire, node, c); g >= 0) w->dofs.push_back(g);
  std::sort(w->dofs.begin(), w->dofs.end());
  w->dofs.erase(std::unique(w->dofs.begin(), w->dofs.end()), w->dofs.end());  // a stitch clamp's w is the messenger's
  const FeWire* wires[2] = {&L.data().messenger, &L.data().contact_wire};
  for (int node : {w->first_node, w->last_node})
    for (int wire = 0; wire < 2; ++wire)
      if (const int g = L.dof(wire, node, 0); g >= 0 && node != 0 && node != L.n_nodes() - 1)
        w->ends.push_back({w->local(g), std::sqrt(wires[wire]->tension * wires[wire]->mass_per_length)});
  const double x0 = first_span * L.data().span, x1 = (first_span + spans) * L.data().span;
  for (std::size_t k = 0; k < L.droppers().size(); ++k)
    if (L.droppers()[k].x > x0 && L.droppers()[k].x < x1) w->droppers.push_back(static_cast<int>(k));
  const int n = static_cast<int>(w->dofs.size());
  auto sub = [&](const Sparse& A) {
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < n; ++j)
      for (Sparse::InnerIterator it(A, w->dofs[static_cast<std::size_t>(j)]); it; ++it)
        if (const int i = w->local(static_cast<int>(it.row())); i >= 0) t.emplace_back(i, j, it.value());
    Sparse S(n, n);
    S.setFromTriplets(t.begin(), t.end());
    return S;
  };
  K = sub(L.K()), M = sub(L.M());
  return w;
}

namespace {
// A window of the same shape and matrices (to 1e-6 of the largest entry: the interior spans of a
// uniform line, whose form-found droppers differ by ~1e-9) shares its modes.
bool same(const Sparse& a, const Sparse& b) {
  if (a.rows() != b.rows() || a.nonZeros() != b.nonZeros()) return false;
  const double tol = 1e-6 * std::max(1.0, Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), a.nonZeros()).cwiseAbs().maxCoeff());
  return (Sparse(a - b)).norm() <= tol * std::sqrt(double(a.nonZeros()));
}

// Matrices of the same pattern within kShare of each other, entry by entry: the interior windows of
// a stitched line, whose form-found droppers differ mast to mast by ≈ 0.1 % in length (stiffness and
// mass; the stitch wires carry the end spans' influence further in), share their modes — the dynamics of
// a window are then those of its twin, as an irregular line's are those of the designed droppers
// (docs/catenary-fe.md "Modal solver"; measured by check-reduction).
// P A Pᵀ for the signed permutation of a mirror (row i of the result is row map[i] of A).
Sparse mirrored(const Sparse& A, const std::vector<std::pair<int, double>>& map) {
  std::vector<int> inv(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) inv[static_cast<std::size_t>(map[i].first)] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it) {
      const int r = inv[static_cast<std::size_t>(it.row())], c = inv[static_cast<std::size_t>(j)];
      t.emplace_back(r, c, map[static_cast<std::size_t>(r)].second * map[static_cast<std::size_t>(c)].second * it.value());
    }
  Sparse B(A.rows(), A.cols());
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

constexpr double kShare = 3e-3;
bool near_equal(const Sparse& a, const Sparse& b) {
  if (same(a, b)) return true;
  if (a.rows() != b.rows() || a.nonZeros() != b.nonZeros() || a.outerSize() != b.outerSize()) return false;
  // Entries that are round-off (a cancellation's 1e-9 where the other has −6e-9) compare absolutely.
  const double floor = 1e-9 * Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), a.nonZeros()).cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    Sparse::InnerIterator ia(a, j), ib(b, j);
    for (; ia && ib; ++ia, ++ib)
      if (ia.row() != ib.row() ||
          std::abs(ia.value() - ib.value()) > std::max(floor, kShare * std::max(std::abs(ia.value()), std::abs(ib.value()))))
        return false;
    if (ia || ib) return false;
  }
  return true;
}
}  // namespace

std::shared_ptr<const FeWindowModes> FeModalLine::find_shape(const Sparse& K, const Sparse& M) const {
  for (const auto& s : shapes_)
    if (near_equal(s->K, K) && near_equal(s->M, M)) return s;
  return nullptr;
}

std::shared_ptr<const FeWindowModes> FeModalLine::decompose(const FeWindow& w, Sparse K, Sparse M,
                                                          const std::function<Modes()>& make) const {
  const FeLine& L = *line_;
  const int n = static_cast<int>(K.rows());
  auto md = std::make_shared<FeWindowModes>();
  const double cutoff = L.data().modal_cutoff;
  std::optional<StoredModes> stored;
  if (store_) stored = store_->load(K, M, cutoff);
  if (stored) {
    ++loaded_;
    md->omega2 = std::move(stored->omega2);
    md->set_phi(std::move(stored->owner), stored->phi, stored->n, stored->m);
    md->phi_damaged = stored->damaged, md->phi_file = std::move(stored->file);
    md->phi_device = stored->file_device, md->phi_inode = stored->file_inode, md->phi_bytes = stored->file_bytes;
  } else {
    if (!make) ++solved_;
    Modes modes;
    if (make) {
      const numerics::PhaseTimer t("window modes: mirrored from another");
      modes = make();
    } else if (auto map = mirror(w, w); !map.empty() && same(mirrored(K, map), K) && same(mirrored(M, map), M)) {
      // A window of identical spans is its own mirror image: its symmetric and antisymmetric modes
      // apart, half the work (numerics/generalised_eigen.hpp).
      const numerics::PhaseTimer t("window modes: eigenproblem (mirror-symmetric, two halves)");
      modes = numerics::lowest_modes_mirrored(K, M, cutoff, map);
    } else {
      const numerics::PhaseTimer t("window modes: eigenproblem");
      modes = lowest_modes(K, M, cutoff);
    }
    md->omega2 = std::move(modes.omega2);
    auto phi = std::make_shared<const FeWindowModes::RowMatrix>(std::move(modes.phi));
    md->set_phi(phi, phi->data(), phi->rows(), phi->cols());
    if (store_) {  // written on a thread of its own while the run goes on (flush_store waits)
      const std::uint64_t key = ModeStore::key(K, M, cutoff);
      const std::lock_guard lock(writes_mutex_);
      last_write_ = std::async(std::launch::async, [prev = last_write_, store = *store_, key, cutoff, omega2 = md->omega2, phi] {
        if (prev.valid()) prev.wait();
        const numerics::PhaseTimer t("mode store: write (on its own thread)");
        if (!store.save(key, cutoff, omega2, phi->data(), phi->rows(), phi->cols())) {
          // Issue 38: once a process, so that a store that cannot be written (then every process
          // solves again) is not skipped in silence; standard error only.
          static std::atomic<bool> said{false};
          if (!said.exchange(true))
            std::fprintf(stderr, "note: the mode store %s cannot be written; the modes are solved in every process "
                                 "(docs/catenary-fe.md \"Mode store\"; INERTA_CACHE=off to use none)\n",
                         store.directory().c_str());
        }
      }).share();
    }
  }
  if (md->omega2.size() == 0)  // issue 38: a solve without modes would run as a quasi-static line
    throw ModelError(fmt::format(
        "finite-element catenary: solver.cutoff = {:g} Hz is below the lowest natural frequency of the line's window: "
        "the modal solve would keep no mode; give a cut-off of at least a few Hz (the bundled line uses 100 Hz), or "
        "solver.type=direct",
        cutoff));
  // K's band Cholesky factor, the band of K⁻¹ and its columns at the special DOFs (residual flexibility).
  const numerics::PhaseTimer t("window modes: residual flexibility (K⁻¹ columns)");
  md->kd = numerics::band_width(K);
  md->cholesky = numerics::band_lower(K, md->kd);
  if (const int info = numerics::band_cholesky(md->cholesky, n, md->kd); info != 0)
    throw NumericalError(fmt::format("finite-element modes: K₀ of a window is not positive definite (LAPACK dpbtrf {})", info));
  md->band = numerics::band_inverse(md->cholesky, n, md->kd);
  for (int k : w.droppers) {
    const auto& dr = L.droppers()[static_cast<std::size_t>(k)];
    md->special.push_back(w.local(dr.dof_m));
    md->special.push_back(w.local(dr.dof_c));
  }
  for (const FeWindow::End& e : w.ends) md->special.push_back(e.local);
  // All columns at once: K⁻¹ [e_s …], the right-hand sides of a DOF side by side in a row.
  const int ns = static_cast<int>(md->special.size());
  md->kinv_special.setZero(n, ns);
  for (int j = 0; j < ns; ++j) md->kinv_special(md->special[static_cast<std::size_t>(j)], j) = 1;
  numerics::band_cholesky_solve_rows(md->cholesky.data(), n, md->kd, md->kinv_special.data(), ns);
  md->K = std::move(K), md->M = std::move(M);
  return md;
}

void FeModalLine::drop_damaged() const {
  auto damaged = [](const std::shared_ptr<const FeWindowModes>& m) { return m->cut_short(); };
  std::erase_if(shapes_, damaged);
  std::erase_if(windows_, [&](const auto& w) { return damaged(w.second->modes); });
}

std::shared_ptr<const FeWindow> FeModalLine::window(int first_span, int spans) const {
  std::lock_guard<std::mutex> lock(mutex_);
  drop_damaged();
  if (auto it = windows_.find({first_span, spans}); it != windows_.end()) return it->second;
  Sparse K, M;
  std::shared_ptr<FeWindow> w = structure(first_span, spans, K, M);
  w->modes = find_shape(K, M);
  if (!w->modes) {
    tbb::this_task_arena::isolate([&] { w->modes = decompose(*w, std::move(K), std::move(M)); });
    shapes_.push_back(w->modes);
  }
  windows_[{first_span, spans}] = w;
  return w;
}

// The window's DOFs mirrored about its middle (x → x_first + x_last − x): local index i of `b` is
// ±(local index map[i] of `a`), the sign −1 for a slope θ. Empty if the two do not correspond.
std::vector<std::pair<int, double>> FeModalLine::mirror(const FeWindow& a, const FeWindow& b) const {
  const FeLine& L = *line_;
  std::vector<std::pair<int, double>> map;
  if (a.dofs.size() != b.dofs.size() || a.last_node - a.first_node != b.last_node - b.first_node) return {};
  for (int node = b.first_node; node <= b.last_node; ++node)
    for (int wire = 0; wire < FeLine::kWires; ++wire)
      for (int c = 0; c < 2; ++c) {
        const int gb = L.dof(wire, node, c);
        if (gb < 0 || (wire == 2 && c == 0 && gb == L.dof(0, node, 0))) continue;  // a stitch clamp: the messenger's
        const int na = a.last_node - (node - b.first_node), ga = L.dof(wire, na, c);
        if (ga < 0 || a.local(ga) < 0 || (wire == 2 && c == 0 && ga == L.dof(0, na, 0))) return {};
        map.push_back({a.local(ga), c == 1 ? -1.0 : 1.0});
      }
  return map;
}


void FeModalLine::prepare(int spans) const {
  const numerics::PhaseTimer timer("windows: prepare every window's modes");
  std::lock_guard<std::mutex> lock(mutex_);
  drop_damaged();
  struct New {
    std::shared_ptr<FeWindow> w;
    Sparse K, M;
    int shape = -1;  // index into `todo`
  };
  std::vector<New> fresh;
  std::vector<std::size_t> todo;  // entries of `fresh` whose shape is decomposed here
  for (int first = 0; first + spans <= line_->data().spans; ++first) {
    if (windows_.count({first, spans})) continue;
    New nw;
    nw.w = structure(first, spans, nw.K, nw.M);
    nw.w->modes = find_shape(nw.K, nw.M);
    if (!nw.w->modes)
      for (std::size_t t = 0; t < todo.size() && nw.shape < 0; ++t)
        if (near_equal(fresh[todo[t]].K, nw.K) && near_equal(fresh[todo[t]].M, nw.M)) nw.shape = static_cast<int>(t);
    if (!nw.w->modes && nw.shape < 0) nw.shape = static_cast<int>(todo.size()), todo.push_back(fresh.size());
    fresh.push_back(std::move(nw));
  }
  // A shape that is the mirror image of an earlier one (the last window of a symmetric line is the
  // first one reversed) takes its modes from it, reordered, instead of a decomposition of its own.
  std::vector<int> mirror_of(todo.size(), -1);
  std::vector<std::vector<std::pair<int, double>>> maps(todo.size());
  for (std::size_t t = 1; t < todo.size(); ++t)
    for (std::size_t o = 0; o < t && mirror_of[t] < 0; ++o) {
      if (mirror_of[o] >= 0) continue;
      const New &a = fresh[todo[o]], &b = fresh[todo[t]];
      auto map = mirror(*a.w, *b.w);
      if (!map.empty() && same(mirrored(a.K, map), b.K) && same(mirrored(a.M, map), b.M))
        mirror_of[t] = static_cast<int>(o), maps[t] = std::move(map);
    }
  std::vector<std::shared_ptr<const FeWindowModes>> made(todo.size());
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t t) {
      if (mirror_of[t] < 0) made[t] = decompose(*fresh[todo[t]].w, fresh[todo[t]].K, fresh[todo[t]].M);
    });
    tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t t) {
      if (mirror_of[t] < 0) return;
      // Kept in the store too: a later process maps its file instead of permuting 40 MB of rows.
      made[t] = decompose(*fresh[todo[t]].w, fresh[todo[t]].K, fresh[todo[t]].M, [&] {
        const FeWindowModes& src = *made[static_cast<std::size_t>(mirror_of[t])];
        Modes m;
        m.omega2 = src.omega2;
        m.phi.resize(src.phi.rows(), src.phi.cols());
        for (std::size_t i = 0; i < maps[t].size(); ++i)
          m.phi.row(static_cast<Eigen::Index>(i)) = maps[t][i].second * src.phi.row(maps[t][i].first);
        src.check_intact(std::nan(""));  // zeros from a file cut short are never stored as another shape's modes
        return m;
      });
    });
  });
  shapes_.insert(shapes_.end(), made.begin(), made.end());
  for (New& nw : fresh) {
    if (!nw.w->modes) nw.w->modes = made[static_cast<std::size_t>(nw.shape)];
    windows_[{nw.w->first_span, spans}] = nw.w;
  }
}

}  // namespace inerta::catenary
