// HHT-α stepping of the finite-element line with slack droppers and moving penalty contacts
// (catenary/fe_catenary.hpp). With u the displacement at t_{n+1} (Newmark):
//   a_{n+1} = c0 (u − u_n) − c2 v_n − c3 a_n,   v_{n+1} = c1 (u − u_n) − c4 v_n − c5 a_n
//   M a_{n+1} + (1+α) (C v_{n+1} + K₀ u − f_{n+1}) = α q_n,   q = C v + K₀ u − f
// so A u = r with A = c0 M + (1+α)(c1 C + K₀), constant and factorised once. Slack droppers
// (−k b bᵀ, load T₀ b) and active penalty contacts (+k N Nᵀ, load F̂ N) change A by a few rank-one
// terms w d wᵀ: u = x0 + Z (s − c), Z = A⁻¹ W, c = (D⁻¹ + WᵀZ)⁻¹ Wᵀ(x0 + Z s) (Woodbury), with the
// columns of A⁻¹ built once per DOF and cached.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary {

extern "C" {
// LAPACK (Debian liblapack): Cholesky factorisation and solve of a symmetric positive definite band matrix.
void dpbtrf_(const char* uplo, const int* n, const int* kd, double* ab, const int* ldab, int* info);
}

namespace {
constexpr std::size_t kCacheColumns = 32;  // the contact elements' DOFs
}

// L Lᵀ x = b with LAPACK's band factor (ab[(i − j) + j·ldab] = L(i, j)): the two substitutions
// written out, contiguous in the band (the reference BLAS dtbsv is several times slower here).
void FeIntegrator::solve(Eigen::VectorXd& b) const {
  const int n = static_cast<int>(b.size()), kd = kd_, ld = kd_ + 1;
  const double* ab = band_.data();
  const double* rd = rdiag_.data();
  double* x = b.data();
  for (int j = 0; j < n; ++j) {  // L y = b: each solved value scattered down its column
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    const double xj = x[j] * rd[j];
    x[j] = xj;
    const int m = std::min(kd, n - 1 - j);
    for (int i = 1; i <= m; ++i) x[j + i] -= c[i] * xj;
  }
  for (int j = n - 1; j >= 0; --j) {  // Lᵀ x = y: the newest value x[j+1] enters last (shortest dependency chain)
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    double s = x[j];
    const int m = std::min(kd, n - 1 - j);
    for (int i = m; i >= 2; --i) s -= c[i] * x[j + i];
    if (m >= 1) s -= c[1] * x[j + 1];
    x[j] = s * rd[j];
  }
  ++solves_;
}

// r = M w + Kb v with both symmetric bands (lower storage, interleaved per column): one pass, each
// stored entry used for its own row and its mirror (the step's right-hand side, no sparse traversal).
void FeIntegrator::band_products(const Eigen::VectorXd& w, const Eigen::VectorXd& v, Eigen::VectorXd& r) const {
  const int n = static_cast<int>(w.size()), kd = kd_, ld = kd_ + 1;
  r.setZero(n);
  const double* ab = mk_band_.data();
  const double *pw = w.data(), *pv = v.data();
  double* y = r.data();
  for (int j = 0; j < n; ++j) {
    const double* m = ab + 2 * static_cast<std::ptrdiff_t>(j) * ld;
    const double* k = m + ld;
    const double wj = pw[j], vj = pv[j];
    double yj = m[0] * wj + k[0] * vj;
    const int top = std::min(kd, n - 1 - j);
    for (int i = 1; i <= top; ++i) {
      y[j + i] += m[i] * wj + k[i] * vj;
      yj += m[i] * pw[j + i] + k[i] * pv[j + i];
    }
    y[j] += yj;
  }
}

FeIntegrator::FeIntegrator(const FeLine& line, double dt, double alpha) : L_(line), h_(dt), alpha_(alpha) {
  if (!(dt > 0) || !std::isfinite(dt)) throw InvalidArgument("finite-element catenary", "time_step", "must be > 0 (s)");
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0))
    throw InvalidArgument("finite-element catenary", "alpha", fmt::format("HHT-α needs −1/3 <= α <= 0, got {}", alpha));
  gamma_ = 0.5 - alpha_;
  beta_ = 0.25 * (1 - alpha_) * (1 - alpha_);
  c0_ = 1 / (beta_ * h_ * h_);
  c1_ = gamma_ / (beta_ * h_);
  c2_ = 1 / (beta_ * h_);
  c3_ = 1 / (2 * beta_) - 1;
  c4_ = gamma_ / beta_ - 1;
  c5_ = h_ * (gamma_ / (2 * beta_) - 1);
  // A in LAPACK's lower band storage (the DOFs are numbered station by station: a narrow band).
  const Eigen::SparseMatrix<double> A = c0_ * L_.M() + (1 + alpha_) * (c1_ * L_.C() + L_.K());
  const int n = static_cast<int>(A.rows());
  kd_ = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) kd_ = std::max(kd_, static_cast<int>(it.row()) - j);
  const int ldab = kd_ + 1;
  band_.assign(static_cast<std::size_t>(ldab) * static_cast<std::size_t>(n), 0.0);
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) band_[static_cast<std::size_t>(it.row() - j) + static_cast<std::size_t>(j) * ldab] = it.value();
  int info = 0;
  dpbtrf_("L", &n, &kd_, band_.data(), &ldab, &info);
  if (info != 0)
    throw NumericalError(fmt::format("finite-element catenary: the step matrix is not positive definite (LAPACK dpbtrf {})", info));
  rdiag_.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) rdiag_[static_cast<std::size_t>(j)] = 1 / band_[static_cast<std::size_t>(j) * ldab];
  // r = M w1 + (1+α) C vt with C = a M + b K: M and (1+α) b K in the same lower band storage as A,
  // interleaved per column ([M(j..j+kd, j), Kb(j..j+kd, j)]) so that one pass reads both.
  mk_band_.assign(2 * static_cast<std::size_t>(ldab) * static_cast<std::size_t>(n), 0.0);
  auto put = [&](const Eigen::SparseMatrix<double>& S, double scale, int which) {
    for (int j = 0; j < S.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
        if (it.row() >= j)
          mk_band_[2 * static_cast<std::size_t>(ldab) * static_cast<std::size_t>(j) + static_cast<std::size_t>(which * ldab) +
                   static_cast<std::size_t>(it.row() - j)] = scale * it.value();
  };
  put(L_.M(), 1.0, 0);
  put(L_.K(), (1 + alpha_) * L_.data().rayleigh_stiffness, 1);
  slot_of_.assign(static_cast<std::size_t>(L_.n_dofs()), -1);
}

const Eigen::VectorXd& FeIntegrator::column(int dof) {
  ++clock_;
  int slot = slot_of_[static_cast<std::size_t>(dof)];
  if (slot >= 0) {
    cache_used_[static_cast<std::size_t>(slot)] = clock_;
    return cache_[static_cast<std::size_t>(slot)];
  }
  if (cache_.size() < kCacheColumns) {
    slot = static_cast<int>(cache_.size());
    cache_.emplace_back();
    cache_dof_.push_back(-1);
    cache_used_.push_back(0);
  } else {
    slot = 0;
    for (std::size_t i = 1; i < cache_.size(); ++i)
      if (cache_used_[i] < cache_used_[static_cast<std::size_t>(slot)]) slot = static_cast<int>(i);
    slot_of_[static_cast<std::size_t>(cache_dof_[static_cast<std::size_t>(slot)])] = -1;
  }
  Eigen::VectorXd& col = cache_[static_cast<std::size_t>(slot)];
  col.setZero(L_.n_dofs());
  col[dof] = 1;
  solve(col);
  cache_dof_[static_cast<std::size_t>(slot)] = dof;
  cache_used_[static_cast<std::size_t>(slot)] = clock_;
  slot_of_[static_cast<std::size_t>(dof)] = slot;
  return col;
}

FeState FeIntegrator::initial(const std::vector<double>& x, const std::vector<double>& F, double t) const {
  FeState s;
  s.u = L_.static_displacement(x, F, &s.slack);
  s.v = Eigen::VectorXd::Zero(L_.n_dofs());
  s.a = Eigen::VectorXd::Zero(L_.n_dofs());
  s.q = Eigen::VectorXd::Zero(L_.n_dofs());  // in equilibrium
  s.t = t;
  return s;
}

double FeIntegrator::height(const FeState& s, double x) const {
  return L_.static_height(x) + L_.contact_displacement(s.u, x);
}

double FeIntegrator::height_rate(const FeState& s, double x, double speed) const {
  const FeLine::Shape sh = L_.contact_shape(x);
  double w_dot = 0, w_x = 0;
  for (int a = 0; a < 4; ++a)
    if (sh.dofs[a] >= 0) w_dot += sh.N[a] * s.v[sh.dofs[a]], w_x += sh.dN[a] * s.u[sh.dofs[a]];
  return w_dot + speed * (L_.static_slope(x) + w_x);
}

double FeIntegrator::energy(const FeState& s) const {
  double E = 0.5 * s.v.dot(L_.M() * s.v) + 0.5 * s.u.dot(L_.K() * s.u);
  const auto& drs = L_.droppers();
  for (std::size_t k = 0; k < drs.size(); ++k)
    if (k < s.slack.size() && s.slack[k]) {
      const double e = drs[k].tension / drs[k].stiffness + s.u[drs[k].dof_m] - s.u[drs[k].dof_c];
      E -= 0.5 * drs[k].stiffness * e * e;
    }
  return E;
}

void FeIntegrator::step(FeState& s, const std::vector<FeLoad>& loads, std::vector<double>& forces) {
  const int n = L_.n_dofs();
  const double ap = 1 + alpha_;
  const double t1 = s.t + h_;
  // Right-hand side without the set-dependent terms.
  w1_ = c0_ * s.u + c2_ * s.v + c3_ * s.a;
  vt_ = c1_ * s.u + c4_ * s.v + c5_ * s.a;  // v_{n+1} = c1 u − vt
  w1_ += (ap * L_.data().rayleigh_mass) * vt_;
  band_products(w1_, vt_, r_);
  if (alpha_ != 0) r_ += alpha_ * s.q;

  // Loads: prescribed forces into r; penalty contacts as rank-one terms.
  struct Mod {
    std::array<int, 4> dofs;
    std::array<double, 4> w;
    int nw;
    double d, coeff;  // stiffness term (1+α)·k (negative for a slack dropper) and load coefficient
  };
  std::vector<Mod> contacts;  // one per penalty load, in order
  std::vector<int> contact_load;
  std::vector<double> kc;  // ks + cs c1 of each contact
  std::vector<double> Fhat;
  forces.assign(loads.size(), 0.0);
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const FeLoad& ld = loads[k];
    const FeLine::Shape sh = L_.contact_shape(ld.x);
    if (!ld.penalty) {
      for (int a = 0; a < 4; ++a)
        if (sh.dofs[a] >= 0) r_[sh.dofs[a]] += ap * ld.force * sh.N[a];
      forces[k] = ld.force;
      continue;
    }
    double Nvt = 0, w_x = 0;
    for (int a = 0; a < 4; ++a)
      if (sh.dofs[a] >= 0) Nvt += sh.N[a] * vt_[sh.dofs[a]], w_x += sh.dN[a] * s.u[sh.dofs[a]];
    const double conv = ld.speed * (L_.static_slope(ld.x) + w_x);  // convective rate, explicit in u_n
    const double fh = ld.stiffness * (ld.head_y - L_.static_height(ld.x)) + ld.damping * (ld.head_v - conv + Nvt);
    Mod m{sh.dofs, sh.N, 4, ap * (ld.stiffness + ld.damping * c1_), ap * fh};
    contacts.push_back(m);
    contact_load.push_back(static_cast<int>(k));
    kc.push_back(ld.stiffness + ld.damping * c1_);
    Fhat.push_back(fh);
  }
  x0_ = r_;
  solve(x0_);

  const auto& drs = L_.droppers();
  if (s.slack.size() != drs.size()) s.slack.assign(drs.size(), 0);
  if (s.active.size() != contacts.size()) s.active.assign(contacts.size(), 1);
  std::vector<Mod> mods;
  Eigen::MatrixXd G;
  Eigen::VectorXd sv, c, coef;
  std::vector<const Eigen::VectorXd*> Z;  // A⁻¹ w_j of the current set
  auto value_at = [&](int dof) {             // x[dof] for the current set
    double v = x0_[dof];
    for (Eigen::Index j = 0; j < coef.size(); ++j) v += (*Z[static_cast<std::size_t>(j)])[dof] * coef[j];
    return v;
  };
  // A⁻¹ N of each contact for this step (from the cached columns), A⁻¹ b of a slack dropper (kept).
  if (contact_z_.size() < contacts.size()) contact_z_.resize(contacts.size());
  std::vector<char> have_contact_z(contacts.size(), 0);
  auto contact_z = [&](std::size_t k) -> const Eigen::VectorXd& {
    Eigen::VectorXd& z = contact_z_[k];
    if (!have_contact_z[k]) {
      z.setZero(n);
      for (int a = 0; a < 4; ++a)
        if (contacts[k].dofs[a] >= 0) z += contacts[k].w[a] * column(contacts[k].dofs[a]);
      have_contact_z[k] = 1;
    }
    return z;
  };
  if (dropper_z_.size() != drs.size()) dropper_z_.resize(drs.size());
  auto dropper_z = [&](std::size_t k) -> const Eigen::VectorXd& {
    Eigen::VectorXd& z = dropper_z_[k];
    if (z.size() == 0) {
      z.setZero(n);
      z[drs[k].dof_m] = 1, z[drs[k].dof_c] = -1;
      solve(z);
    }
    return z;
  };
  for (int pass = 0;; ++pass) {
    ++passes_;
    if (pass > 60)
      throw NumericalError(fmt::format(
          "finite-element catenary: t = {:.6g} s: the set of slack droppers and open contacts does not settle in 60 "
          "passes (a dropper or contact chattering; try a smaller time step)",
          t1));
    mods.clear();
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (s.active[k]) mods.push_back(contacts[k]);
    for (std::size_t k = 0; k < drs.size(); ++k)
      if (s.slack[k]) mods.push_back({{drs[k].dof_m, drs[k].dof_c, -1, -1}, {1.0, -1.0, 0, 0}, 2,
                                      -ap * drs[k].stiffness, ap * drs[k].tension});
    const Eigen::Index r = static_cast<Eigen::Index>(mods.size());
    Z.clear();
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (s.active[k]) Z.push_back(&contact_z(k));
    for (std::size_t k = 0; k < drs.size(); ++k)
      if (s.slack[k]) Z.push_back(&dropper_z(k));
    G.resize(r, r);
    sv.resize(r);
    Eigen::VectorXd Wx0(r);
    for (Eigen::Index i = 0; i < r; ++i) {
      const Mod& mi = mods[static_cast<std::size_t>(i)];
      sv[i] = mi.coeff;
      Wx0[i] = 0;
      for (int a = 0; a < mi.nw; ++a)
        if (mi.dofs[a] >= 0) Wx0[i] += mi.w[a] * x0_[mi.dofs[a]];
      for (Eigen::Index j = 0; j < r; ++j) {
        double g = 0;
        for (int a = 0; a < mi.nw; ++a)
          if (mi.dofs[a] >= 0) g += mi.w[a] * (*Z[static_cast<std::size_t>(j)])[mi.dofs[a]];
        G(i, j) = g;
      }
    }
    if (r > 0) {
      Eigen::MatrixXd cap = G;
      for (Eigen::Index i = 0; i < r; ++i) cap(i, i) += 1 / mods[static_cast<std::size_t>(i)].d;
      c = cap.partialPivLu().solve(Wx0 + G * sv);
      coef = sv - c;
    } else {
      coef.resize(0);
    }
    // Check the set: contact forces, dropper tensions.
    bool changed = false;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      double w = 0;
      for (int a = 0; a < 4; ++a)
        if (contacts[k].dofs[a] >= 0) w += contacts[k].w[a] * value_at(contacts[k].dofs[a]);
      const double F = Fhat[k] - kc[k] * w;
      forces[static_cast<std::size_t>(contact_load[k])] = F > 0 ? F : 0.0;
      if ((F > 0) != static_cast<bool>(s.active[k])) s.active[k] = F > 0, changed = true;
    }
    for (std::size_t k = 0; k < drs.size(); ++k) {
      const double T = drs[k].tension + drs[k].stiffness * (value_at(drs[k].dof_m) - value_at(drs[k].dof_c));
      if ((T < 0) != static_cast<bool>(s.slack[k])) s.slack[k] = T < 0, changed = true;
    }
    if (!changed) break;
  }
  // The step's solution and the Newmark update.
  w2_ = x0_;
  for (Eigen::Index j = 0; j < coef.size(); ++j) w2_ += coef[j] * *Z[static_cast<std::size_t>(j)];
  const Eigen::VectorXd a1 = c0_ * (w2_ - s.u) - c2_ * s.v - c3_ * s.a;
  s.v = c1_ * (w2_ - s.u) - c4_ * s.v - c5_ * s.a;
  s.a = a1;
  s.u.swap(w2_);
  s.t = t1;
  if (alpha_ != 0) {  // q = C v + K₀ u − f at t_{n+1}
    s.q = L_.C() * s.v + L_.K() * s.u;
    for (std::size_t k = 0; k < drs.size(); ++k)
      if (s.slack[k]) {
        const double T = drs[k].tension + drs[k].stiffness * (s.u[drs[k].dof_m] - s.u[drs[k].dof_c]);
        s.q[drs[k].dof_m] -= T, s.q[drs[k].dof_c] += T;
      }
    for (std::size_t k = 0; k < loads.size(); ++k) {
      const FeLine::Shape sh = L_.contact_shape(loads[k].x);
      for (int a = 0; a < 4; ++a)
        if (sh.dofs[a] >= 0) s.q[sh.dofs[a]] -= forces[k] * sh.N[a];
    }
  }
}

namespace {
// The direct solve as a run's solver: the FeIntegrator and its state.
class DirectSolver final : public FeLineSolver {
 public:
  explicit DirectSolver(const FeLine& line) : L_(line), fe_(line, line.data().time_step, line.data().hht_alpha) {}
  double dt() const override { return fe_.dt(); }
  double time() const override { return s_.t; }
  void start(const std::vector<double>& x, const std::vector<double>& F, double t) override { s_ = fe_.initial(x, F, t); }
  void step(const std::vector<FeLoad>& loads, std::vector<double>& forces) override { fe_.step(s_, loads, forces); }
  double height(double x) const override { return fe_.height(s_, x); }
  double height_rate(double x, double speed) const override { return fe_.height_rate(s_, x, speed); }
  double uplift(double x) const override { return L_.contact_displacement(s_.u, x); }
  std::vector<double> support_uplift() const override {
    std::vector<double> u;
    for (int d : L_.support_dofs()) u.push_back(s_.u[d]);
    return u;
  }
  double energy() const override { return fe_.energy(s_); }

 private:
  const FeLine& L_;
  FeIntegrator fe_;
  FeState s_;
};
}  // namespace

std::unique_ptr<FeLineSolver> make_direct_solver(const FeLine& line) { return std::make_unique<DirectSolver>(line); }

}  // namespace inerta::catenary
