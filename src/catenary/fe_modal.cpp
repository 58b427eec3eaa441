// The per-run modal solver of the finite-element line (catenary/fe_modal.hpp, spec/05 §5.3): the
// modal state in the current window, the HHT-α step with the rank-one local forces, window moves.
// Several runs with their loads at the same places step together as lanes (issue 50): the window,
// its matrices and the loads' modal rows and couplings are the group's, each lane holds its state
// and does its own arithmetic in the order a lone run does it (the droppers' rows meet every lane's
// vector in one pass over them, each vector summed as alone: kernels::rows_dot_each).
// The windows and their modes: fe_modal_windows.cpp; the eigensolver and band algebra: numerics.
#include "inerta/catenary/fe_modal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "inerta/error.hpp"
#include "modal_kernels.hpp"

namespace inerta::catenary {

namespace {

// A local force of shape w (at most 4 window DOFs l with weights w): p = Φᵀw, pw = Ω⁻² p, ks = K₀⁻¹w
// at the special DOFs; a dropper or an absorbing end is itself a combination (s, sw) of special
// DOFs. d and coeff as in fe_integrator.cpp (stiffness term and load coefficient).
struct Mod {
  std::array<int, 4> l{-1, -1, -1, -1};
  std::array<double, 4> w{};
  Eigen::VectorXd p, pw, ks;
  std::array<int, 2> s{-1, -1};
  std::array<double, 2> sw{};
  double d = 0, coeff = 0;
  double x = NAN;  // m: a contact point's place (NaN: a special DOF)
};
struct Contact {
  int load;
  double k, fh;
};
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The modal solve of one or more runs (lanes) in one window.
class ModalLanes final : public FeLineLanes {
 public:
  ModalLanes(std::shared_ptr<const FeModalLine> modal, double spread, int lanes)
      : ml_(std::move(modal)), L_(ml_->line()), W_(ml_->window_spans(spread)) {
    const FeCatenaryData& d = L_.data();
    h_ = d.time_step, alpha_ = d.hht_alpha;
    if (!(h_ > 0) || !std::isfinite(h_)) throw InvalidArgument("finite-element catenary", "time_step", "must be > 0 (s)");
    if (!(alpha_ >= -1.0 / 3.0 && alpha_ <= 0))
      throw InvalidArgument("finite-element catenary", "alpha", fmt::format("HHT-α needs −1/3 <= α <= 0, got {}", alpha_));
    if (lanes < 1) throw InvalidArgument(fmt::format("modal lanes: {} lanes; at least one", lanes));
    gamma_ = 0.5 - alpha_;
    beta_ = 0.25 * (1 - alpha_) * (1 - alpha_);
    c0_ = 1 / (beta_ * h_ * h_), c1_ = gamma_ / (beta_ * h_), c2_ = 1 / (beta_ * h_);
    c3_ = 1 / (2 * beta_) - 1, c4_ = gamma_ / beta_ - 1, c5_ = h_ * (gamma_ / (2 * beta_) - 1);
    for (int i = 0; i < lanes; ++i) lanes_.push_back(std::make_unique<Lane>(*this, i));
  }
  int lanes() const override { return static_cast<int>(lanes_.size()); }
  FeLineSolver& lane(int i) override {
    if (i < 0 || i >= lanes()) throw InvalidArgument(fmt::format("modal lanes: lane {} of {}", i, lanes()));
    return *lanes_[static_cast<std::size_t>(i)];
  }
  void step(const std::vector<int>& which, const std::vector<std::vector<FeLoad>>& loads,
            std::vector<std::vector<double>>& forces, std::vector<std::exception_ptr>& errors) override;

 private:
  class Lane;
  // One run's state in the group's window, and its solver's queries (FeLineSolver).
  class Lane final : public FeLineSolver {
   public:
    Lane(ModalLanes& g, int index) : g_(g), index_(index) { slack_.assign(g.L_.droppers().size(), 0); }
    double dt() const override { return g_.h_; }
    double time() const override { return t_; }
    void start(const std::vector<double>& x, const std::vector<double>& F, double t) override;
    // Alone: a group of one (a lane of several steps with them, FeLineLanes::step).
    void step(const std::vector<FeLoad>& loads, std::vector<double>& forces) override {
      if (g_.lanes() > 1) throw std::logic_error("modal lanes: a lane of several steps with the others (FeLineLanes::step)");
      const std::vector<FeLoad>* l[1] = {&loads};
      std::vector<double>* f[1] = {&forces};
      std::exception_ptr e[1];
      const int which[1] = {index_};
      g_.step_lanes(which, 1, l, f, e);
      if (e[0]) std::rethrow_exception(e[0]);
    }
    double uplift(double x) const override;
    double height(double x) const override { return g_.L_.static_height(x) + uplift(x); }
    double height_rate(double x, double speed) const override;
    double energy() const override;
    std::vector<double> support_uplift() const override;

    // The step's parts, in the order a lone run does them (ModalLanes::step_lanes).
    void rhs();
    void loads(const std::vector<FeLoad>& loads, std::vector<double>& forces);
    void settle(std::vector<double>& forces);
    void finish(const std::vector<FeLoad>& loads, std::vector<double>& forces);
    double prescribed_residual(std::size_t i) const;
    double coeff(int si) const {  // of an entry of [contacts, specials]
      const int nc = static_cast<int>(cc_.size()), nd = static_cast<int>(g_.droppers_.size());
      if (si < nc) return cc_[static_cast<std::size_t>(si)];
      if (si < nc + nd) return g_.smods_[static_cast<std::size_t>(si - nc)].coeff;
      return ends_coeff_[si - nc - nd];
    }
    double d(int si) const {
      const int nc = static_cast<int>(cd_.size());
      return si < nc ? cd_[static_cast<std::size_t>(si)] : g_.smods_[static_cast<std::size_t>(si - nc)].d;
    }
    const Mod& mod(int si) const {
      const int nc = static_cast<int>(g_.mods_.size());
      return si < nc ? g_.mods_[static_cast<std::size_t>(si)] : g_.smods_[static_cast<std::size_t>(si - nc)];
    }

    ModalLanes& g_;
    int index_;
    double t_ = 0;
    Eigen::VectorXd q_, qd_, qdd_, qi_;
    std::vector<char> slack_;    // per dropper of the line
    std::vector<char> active_;   // per penalty load
    std::vector<double> last_F_;
    mutable std::vector<double> last_res_;  // a placeholder's computed when asked (res_ready_)
    mutable std::vector<char> res_ready_;
    std::vector<int> prescribed_load_;  // per load: its index in prescribed_ (−1: a contact)
    // Step scratch.
    Eigen::VectorXd vt_, r_, x0_, du_, coef_, sum_, wx0_, d0_, ends_coeff_;
    std::vector<Contact> contacts_;
    std::vector<double> cd_, cc_, pf_;  // per contact: its d and coeff; per prescribed load: its force
    std::vector<int> set_;
    std::vector<double> contact_w_;
    RowMajor uva_;  // a window move: u, v, a (and M⁻¹-side force) on the old window's DOFs
    Eigen::VectorXd fi_;
  };

  // lanes which[0 … n) one step (FeLineLanes::step); a lane's exception into errors[j].
  void step_lanes(const int* which, int n, const std::vector<FeLoad>* const* loads, std::vector<double>* const* forces,
                  std::exception_ptr* errors);

  int first_span_for(const std::vector<double>& x) const {
    const FeCatenaryData& d = L_.data();
    double lo = x.empty() ? 0 : x.front();
    for (double v : x) lo = std::min(lo, v);
    const int s = std::clamp(static_cast<int>(std::floor(lo / d.span)), 0, d.spans - 1);
    const int behind = d.window_behind < 0 ? d.spans : d.window_behind;
    return std::clamp(s - behind, 0, d.spans - W_);
  }

  // K₀⁻¹(i, j): within the band from the band inverse, else from the column of the lower DOF (K₀⁻¹
  // is symmetric: one column per pair of contacts), kept per window shape up to kColumnBytes (the
  // oldest dropped first; made again, the same numbers) in recycled buffers (no fresh pages a step).
  double kinv(int i, int j) const {
    const auto& md = *win_->modes;
    if (std::abs(i - j) <= md.kd) return md.band(i, j);
    if (i < j) std::swap(i, j);
    if (auto it = columns_.find(j); it != columns_.end()) return it->second[i];
    const std::size_t n = win_->dofs.size();
    const std::size_t cap = std::max<std::size_t>(8, kColumnBytes / (8 * n));
    Eigen::VectorXd c;
    if (columns_.size() >= cap) {  // drop the oldest
      auto old = columns_.find(column_order_.front());
      c = std::move(old->second);
      columns_.erase(old);
      column_order_.pop_front();
    } else if (!spare_columns_.empty()) {
      c = std::move(spare_columns_.back());
      spare_columns_.pop_back();
    }
    c.setZero(static_cast<Eigen::Index>(n));
    c[j] = 1;
    md.solve_K(c, j);
    column_order_.push_back(j);
    const double v = c[i];
    columns_.emplace(j, std::move(c));
    return v;
  }
  void clear_columns() {
    for (auto& [l, c] : columns_) spare_columns_.push_back(std::move(c));
    columns_.clear();
    column_order_.clear();
  }
  // With `px`: Φᵀ N'(x) too (shape_slope), from the same rows in the same pass.
  Mod contact_mod(const FeLine::Shape& sh, double d, double coeff, double x, Eigen::VectorXd* px = nullptr) const {
    Mod m;
    m.x = x;
    const auto& md = *win_->modes;
    const Eigen::Index nm = md.omega2.size();
    m.p = Eigen::VectorXd::Zero(nm);
    if (px) px->setZero(nm);
    m.ks = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(md.special.size()));
    for (int a = 0; a < 4; ++a)
      if (const int l = sh.dofs[a] >= 0 ? win_->local(sh.dofs[a]) : -1; l >= 0) {
        const double N = sh.N[static_cast<std::size_t>(a)], dN = sh.dN[static_cast<std::size_t>(a)];
        m.l[static_cast<std::size_t>(a)] = l, m.w[static_cast<std::size_t>(a)] = N;
        const double* row = md.phi.data() + static_cast<std::ptrdiff_t>(l) * nm;
        double* p = m.p.data();
        if (px) {
          double* q = px->data();
          for (Eigen::Index i = 0; i < nm; ++i) p[i] += N * row[i], q[i] += dN * row[i];
        } else {
          for (Eigen::Index i = 0; i < nm; ++i) p[i] += N * row[i];
        }
        m.ks += N * md.kinv_special.row(l).transpose();
      }
    m.pw = m.p.cwiseProduct(invw2_);
    m.d = d, m.coeff = coeff;
    return m;
  }
  // P (dz ∘ φ_l) for the window DOF l (P: the droppers' rows, dz = A⁻¹ − Ω⁻²/(1+α)): a unit force at
  // l, its effect on every dropper's elongation; made when a contact first reaches l, kept per shape.
  const Eigen::VectorXd& dropper_column(int l) {
    auto it = dropper_columns_.find(l);
    if (it != dropper_columns_.end()) return it->second;
    make_dropper_columns(&l, 1);
    return dropper_columns_.at(l);
  }
  // The columns of the `count` DOFs ls (not yet made), in one pass over the droppers' rows.
  void make_dropper_columns(const int* ls, int count) {
    const auto& md = *win_->modes;
    const Eigen::Index m = md.omega2.size(), nd = dropper_p_.rows();
    Eigen::MatrixXd z(m, count);
    std::vector<const double*> xs(static_cast<std::size_t>(count));
    for (int c = 0; c < count; ++c) {
      z.col(c) = md.phi.row(ls[c]).transpose().cwiseProduct(dz_);
      xs[static_cast<std::size_t>(c)] = z.col(c).data();
    }
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> h(nd, count);
    kernels::rows_dot(dropper_p_.data(), m, static_cast<int>(nd), static_cast<int>(m), xs.data(), count, h.data());
    for (int c = 0; c < count; ++c) dropper_columns_.emplace(ls[c], h.col(c));
  }
  // Φᵀ N'(x): the modal row of the wire's slope at a contact point.
  Eigen::VectorXd shape_slope(const FeLine::Shape& sh) const {
    const auto& md = *win_->modes;
    Eigen::VectorXd px = Eigen::VectorXd::Zero(md.omega2.size());
    for (int a = 0; a < 4; ++a)
      if (const int l = sh.dofs[a] >= 0 ? win_->local(sh.dofs[a]) : -1; l >= 0) px += sh.dN[static_cast<std::size_t>(a)] * md.phi.row(l).transpose();
    return px;
  }
  // Special DOFs i (weight +1) and j (weight −1, if j >= 0).
  Mod special_mod(int i, int j, double d, double coeff) const {
    const auto& md = *win_->modes;
    Mod m;
    const int li = md.special[static_cast<std::size_t>(i)];
    m.l = {li, -1, -1, -1};
    m.w = {1.0, 0, 0, 0};
    m.s = {i, j};
    m.sw = {1.0, j >= 0 ? -1.0 : 0.0};
    m.p = md.phi.row(li).transpose();
    m.ks = md.kinv_special.row(li).transpose();
    if (j >= 0) {
      const int lj = md.special[static_cast<std::size_t>(j)];
      m.l[1] = lj, m.w[1] = -1.0;
      m.p -= md.phi.row(lj).transpose();
      m.ks -= md.kinv_special.row(lj).transpose();
    }
    m.pw = m.p.cwiseProduct(invw2_);
    m.d = d, m.coeff = coeff;
    return m;
  }
  // w_aᵀ (K₀⁻¹ − Φ Ω⁻² Φᵀ) w_b; left out (0) between contact points more than kFarSpans spans apart,
  // where it is below ≈ 2·10⁻³ of a point's own (FeModal.TheResidualFlexibility…).
  double residual(const Mod& a, const Mod& b) const {
    if (std::abs(a.x - b.x) > kFarSpans * L_.data().span) return 0;
    double k = 0;
    if (a.s[0] >= 0) {
      for (int i = 0; i < 2; ++i)
        if (a.s[static_cast<std::size_t>(i)] >= 0) k += a.sw[static_cast<std::size_t>(i)] * b.ks[a.s[static_cast<std::size_t>(i)]];
    } else if (b.s[0] >= 0) {
      for (int i = 0; i < 2; ++i)
        if (b.s[static_cast<std::size_t>(i)] >= 0) k += b.sw[static_cast<std::size_t>(i)] * a.ks[b.s[static_cast<std::size_t>(i)]];
    } else {
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (a.l[static_cast<std::size_t>(i)] >= 0 && b.l[static_cast<std::size_t>(j)] >= 0)
            k += a.w[static_cast<std::size_t>(i)] * b.w[static_cast<std::size_t>(j)] * kinv(a.l[static_cast<std::size_t>(i)], b.l[static_cast<std::size_t>(j)]);
    }
    return k - a.p.dot(b.pw);
  }
  // The same for every window dropper against b: b_dᵀ(K₀⁻¹ − Φ Ω⁻² Φᵀ) w_b.
  Eigen::VectorXd residual_droppers(const Mod& b) const {
    Eigen::VectorXd r = -(dropper_p_ * b.pw);
    for (Eigen::Index j = 0; j < r.size(); ++j) r[j] += b.ks[2 * j] - b.ks[2 * j + 1];
    return r;
  }

  // Makes the window starting at span `first` the current one (the state is set by the caller).
  void enter(int first) {
    const std::shared_ptr<const FeWindowModes> before = win_ ? win_->modes : nullptr;
    win_ = ml_->window(first, W_);
    if (win_->modes != before) clear_columns(), dropper_columns_.clear();
    const auto& md = *win_->modes;
    const FeCatenaryData& d = L_.data();
    const double ap = 1 + alpha_;
    damp_ = (d.rayleigh_mass + d.rayleigh_stiffness * md.omega2.array()).matrix();
    A_ = (c0_ + ap * (c1_ * damp_.array() + md.omega2.array())).matrix();
    invA_ = A_.cwiseInverse(), invw2_ = md.omega2.cwiseInverse();
    dz_ = invA_ - invw2_ / ap;
    droppers_ = win_->droppers;
    const auto& drs = L_.droppers();
    dropper_p_.resize(static_cast<Eigen::Index>(droppers_.size()), md.omega2.size());
    smods_.clear();
    for (std::size_t j = 0; j < droppers_.size(); ++j) {
      const auto& dr = drs[static_cast<std::size_t>(droppers_[j])];
      dropper_p_.row(static_cast<Eigen::Index>(j)) = md.phi.row(win_->local(dr.dof_m)) - md.phi.row(win_->local(dr.dof_c));
    }
    support_of_.clear();  // the supports in the window, their rows of Φ packed
    const std::vector<int>& sup = L_.support_dofs();
    for (std::size_t i = 0; i < sup.size(); ++i)
      if (win_->local(sup[i]) >= 0) support_of_.push_back(static_cast<int>(i));
    support_p_.resize(static_cast<Eigen::Index>(support_of_.size()), md.omega2.size());
    for (std::size_t i = 0; i < support_of_.size(); ++i)
      support_p_.row(static_cast<Eigen::Index>(i)) = md.phi.row(win_->local(sup[static_cast<std::size_t>(support_of_[i])]));
    for (std::size_t j = 0; j < droppers_.size(); ++j) {
      const auto& dr = drs[static_cast<std::size_t>(droppers_[j])];
      smods_.push_back(special_mod(static_cast<int>(2 * j), static_cast<int>(2 * j + 1), -ap * dr.stiffness, ap * dr.tension));
    }
    for (std::size_t e = 0; e < win_->ends.size(); ++e)
      smods_.push_back(special_mod(static_cast<int>(2 * droppers_.size() + e), -1, ap * win_->ends[e].damping * c1_, 0));
    // G between special terms: p_sᵀ A⁻¹ p_t + R(s, t)/(1 + α); their effect on the droppers.
    const Eigen::Index ns = static_cast<Eigen::Index>(smods_.size()), nd = static_cast<Eigen::Index>(droppers_.size());
    gs_.resize(ns, ns);
    dws_.resize(nd, ns);
    for (Eigen::Index t = 0; t < ns; ++t) {
      const Mod& mt = smods_[static_cast<std::size_t>(t)];
      const Eigen::VectorXd zt = mt.p.cwiseProduct(dz_);
      for (Eigen::Index s2 = 0; s2 < ns; ++s2) {
        const Mod& ms = smods_[static_cast<std::size_t>(s2)];
        double k = 0;
        for (int i = 0; i < 2; ++i)
          if (ms.s[static_cast<std::size_t>(i)] >= 0) k += ms.sw[static_cast<std::size_t>(i)] * mt.ks[ms.s[static_cast<std::size_t>(i)]];
        gs_(s2, t) = ms.p.dot(zt) + k / ap;
      }
      dws_.col(t) = gs_.col(t).head(nd);
    }
  }

  // At a load point of the last step, its shape's modal rows were kept (load_p_, load_px_).
  int load_at(double x) const {
    for (std::size_t k = 0; k < last_x_.size() && k < load_p_.size(); ++k)
      if (last_x_[k] == x) return static_cast<int>(k);
    return -1;
  }

  // The window moves for the lanes which[0 … n): each one's physical state on the DOFs both windows
  // share is carried over and projected (q' = Φ'ᵀ M' u).
  void move_to(int first, const int* which, int n) {
    const std::shared_ptr<const FeWindow> old = win_;
    const auto& mo = *old->modes;
    const int C = alpha_ != 0 ? 4 : 3;  // one pass over Φ for the state's vectors
    const Eigen::Index no = mo.phi.rows(), mm = mo.phi.cols();
    // Only the old window's rows on DOFs the new one shares are needed (with a margin of M's band for
    // M u): the span left behind is not read.
    const std::shared_ptr<const FeWindow> nw = ml_->window(first, W_);
    const auto lo = std::lower_bound(old->dofs.begin(), old->dofs.end(), nw->dofs.front());
    const auto hi = std::upper_bound(old->dofs.begin(), old->dofs.end(), nw->dofs.back());
    const Eigen::Index margin = 32;
    const Eigen::Index r0 = std::max<Eigen::Index>(0, (lo - old->dofs.begin()) - margin);
    const Eigen::Index r1 = std::min<Eigen::Index>(no, (hi - old->dofs.begin()) + margin);
    std::vector<const double*> qs;  // every lane's state vectors: Φ read once for all of them
    std::vector<double*> ys;
    for (int j = 0; j < n; ++j) {
      Lane& s = *lanes_[static_cast<std::size_t>(which[j])];
      for (const Eigen::VectorXd* v : {&s.q_, &s.qd_, &s.qdd_, &s.qi_}) qs.push_back(v->data());
      qs.resize(static_cast<std::size_t>((j + 1) * C));
      s.uva_ = RowMajor::Zero(no, C);
      ys.push_back(s.uva_.data() + r0 * C);
    }
    if (r1 > r0)
      kernels::rows_dot_lanes(mo.phi.data() + r0 * mm, mm, static_cast<int>(r1 - r0), static_cast<int>(mm), qs.data(), C, n, ys.data());
    mo.check_intact(lanes_[static_cast<std::size_t>(which[0])]->t_);
    for (int j = 0; j < n; ++j) {
      Lane& s = *lanes_[static_cast<std::size_t>(which[j])];
      if (alpha_ != 0) s.fi_ = mo.M * s.uva_.col(3);
    }
    enter(first);
    const auto& mn = *win_->modes;
    const Eigen::Index nn = static_cast<Eigen::Index>(win_->dofs.size());
    const Eigen::Index m = mn.phi.cols();
    std::vector<RowMajor> rhs(static_cast<std::size_t>(n));
    std::vector<const double*> coef;
    std::vector<double*> qn;
    for (int jl = 0; jl < n; ++jl) {
      Lane& s = *lanes_[static_cast<std::size_t>(which[jl])];
      const auto u = s.uva_.col(0), v = s.uva_.col(1), a = s.uva_.col(2);
      Eigen::VectorXd u2 = Eigen::VectorXd::Zero(nn), v2 = u2, a2 = u2, f2 = u2;
      for (std::size_t i = 0, j = 0; i < old->dofs.size() && j < win_->dofs.size();) {
        if (old->dofs[i] < win_->dofs[j]) ++i;
        else if (old->dofs[i] > win_->dofs[j]) ++j;
        else {
          const Eigen::Index oi = static_cast<Eigen::Index>(i), nj = static_cast<Eigen::Index>(j);
          u2[nj] = u[oi], v2[nj] = v[oi], a2[nj] = a[oi];
          if (alpha_ != 0) f2[nj] = s.fi_[oi];
          ++i, ++j;
        }
      }
      RowMajor& r = rhs[static_cast<std::size_t>(jl)];
      r.resize(nn, C);
      r.col(0) = mn.M * u2, r.col(1) = mn.M * v2, r.col(2) = mn.M * a2;
      if (alpha_ != 0) r.col(3) = f2;
      s.q_.setZero(m), s.qd_.setZero(m), s.qdd_.setZero(m), s.qi_.setZero(m);
      for (Eigen::VectorXd* q : {&s.q_, &s.qd_, &s.qdd_, &s.qi_}) qn.push_back(q->data());
      qn.resize(static_cast<std::size_t>((jl + 1) * C));
      coef.push_back(r.data());
      s.uva_.resize(0, 0);
    }
    kernels::rows_axpy_lanes(mn.phi.data(), m, static_cast<int>(nn), static_cast<int>(m), coef.data(), C, n, qn.data());
    for (int jl = 0; jl < n; ++jl) {  // droppers left behind are forgotten; those ahead start taut
      Lane& s = *lanes_[static_cast<std::size_t>(which[jl])];
      std::vector<char> keep(s.slack_.size(), 0);
      for (int k : droppers_) keep[static_cast<std::size_t>(k)] = s.slack_[static_cast<std::size_t>(k)];
      s.slack_.swap(keep);
    }
  }

  std::shared_ptr<const FeModalLine> ml_;
  const FeLine& L_;
  int W_;
  double h_ = 0, alpha_ = 0, beta_ = 0, gamma_ = 0, c0_ = 0, c1_ = 0, c2_ = 0, c3_ = 0, c4_ = 0, c5_ = 0;
  std::vector<std::unique_ptr<Lane>> lanes_;
  std::shared_ptr<const FeWindow> win_;
  Eigen::VectorXd damp_, A_, invA_, invw2_, dz_;  // dz_ = A⁻¹ − Ω⁻²/(1+α)
  std::vector<int> droppers_;  // global indices of the window's droppers
  RowMajor dropper_p_;  // a row per window dropper: Φᵀ(e_m − e_c)
  RowMajor support_p_;  // a row per window support: Φᵀe_s
  std::vector<int> support_of_;  // their indices in the line's supports
  // The loads of the last step (the same places in every lane): x, Φᵀ N(x) and Φᵀ N'(x).
  std::vector<double> last_x_;
  std::vector<Eigen::VectorXd> load_p_, load_px_;
  static constexpr std::size_t kColumnBytes = std::size_t{256} << 20;
  static constexpr double kFarSpans = 3;
  mutable std::unordered_map<int, Eigen::VectorXd> columns_;  // K₀⁻¹ e_l of the window shape beyond its band (several contacts)
  mutable std::deque<int> column_order_;                      // their l, oldest first
  mutable std::vector<Eigen::VectorXd> spare_columns_;        // buffers of a previous shape
  std::unordered_map<int, Eigen::VectorXd> dropper_columns_;  // dropper_column(l) of the window shape
  // The step's shared part: the penalty loads' and the prescribed loads' modal rows (d, coeff per
  // lane), each contact's A⁻¹p − Ω⁻²p/(1+α) and its effect on the droppers, G of each contact.
  std::vector<double> xs_;
  std::vector<Mod> mods_, prescribed_;
  Eigen::MatrixXd gc_, dwc_, xz_, dxz_;
  std::vector<double> d0_all_;  // the droppers' rows against every lane's x0 (a row per dropper)
  // Per window: the special terms (droppers as slack ones, then the absorbing ends' dashpots), their
  // G among themselves and their effect on every dropper's elongation (a column per special term).
  std::vector<Mod> smods_;
  Eigen::MatrixXd gs_, dws_;
};

void ModalLanes::Lane::start(const std::vector<double>& x, const std::vector<double>& F, double t) {
  ModalLanes& g = g_;
  const FeLine& L = g.L_;
  if (g.W_ < L.data().spans) g.ml_->prepare(g.W_);
  t_ = t;
  std::vector<char> slack;
  const Eigen::VectorXd u = L.static_displacement(x, F, &slack);
  if (const int first = g.first_span_for(x); !g.win_ || g.ml_->window(first, g.W_) != g.win_) g.enter(first);
  // In equilibrium: q = Ω⁻² Φᵀ f under the contact forces and the slack droppers' corrections;
  // the modes left out give the residual displacement at the contact points.
  const auto& md = *g.win_->modes;
  std::fill(slack_.begin(), slack_.end(), 0);
  std::vector<Mod> ms;
  for (std::size_t k = 0; k < x.size(); ++k) ms.push_back(g.contact_mod(L.contact_shape(x[k]), 0, F[k], x[k]));
  const auto& drs = L.droppers();
  for (int k : g.droppers_)
    if (slack[static_cast<std::size_t>(k)]) {
      const auto& dr = drs[static_cast<std::size_t>(k)];
      slack_[static_cast<std::size_t>(k)] = 1;
      const int j = static_cast<int>(std::find(g.droppers_.begin(), g.droppers_.end(), k) - g.droppers_.begin());
      ms.push_back(g.special_mod(2 * j, 2 * j + 1, 0, dr.tension + dr.stiffness * (u[dr.dof_m] - u[dr.dof_c])));
    }
  q_.setZero(md.omega2.size());
  for (const Mod& m : ms) q_ += m.coeff * m.pw;  // coeff: the force here
  md.check_intact(t);
  qd_.setZero(q_.size()), qdd_.setZero(q_.size()), qi_.setZero(q_.size());
  g.last_x_ = x;
  last_F_ = F;
  last_res_.assign(x.size(), 0.0);
  res_ready_.assign(x.size(), 1);
  g.load_p_.resize(x.size()), g.load_px_.resize(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    for (const Mod& m : ms)
      if (m.coeff != 0) last_res_[k] += g.residual(ms[k], m) * m.coeff;
    g.load_p_[k] = ms[k].p;
    g.load_px_[k] = g.shape_slope(L.contact_shape(x[k]));
  }
}

// Right-hand side and the diagonal step matrix, a mode each (one pass over the modes).
void ModalLanes::Lane::rhs() {
  const ModalLanes& g = g_;
  const double ap = 1 + g.alpha_;
  const Eigen::Index nm = q_.size();
  vt_.resize(nm), r_.resize(nm);
  const double *q = q_.data(), *qd = qd_.data(), *qdd = qdd_.data(), *qi = qi_.data(), *dm = g.damp_.data();
  double *vt = vt_.data(), *r = r_.data();
  for (Eigen::Index i = 0; i < nm; ++i) {
    const double w1 = g.c0_ * q[i] + g.c2_ * qd[i] + g.c3_ * qdd[i];
    vt[i] = g.c1_ * q[i] + g.c4_ * qd[i] + g.c5_ * qdd[i];
    r[i] = w1 + ap * (dm[i] * vt[i]);
    if (g.alpha_ != 0) r[i] += g.alpha_ * qi[i];
  }
}

// The loads on this lane's state: prescribed forces into the right-hand side, each penalty contact's
// stiffness and predicted force, the absorbing ends' dashpot forces; x0 = A⁻¹ r.
void ModalLanes::Lane::loads(const std::vector<FeLoad>& loads, std::vector<double>& forces) {
  const ModalLanes& g = g_;
  const FeLine& L = g.L_;
  const double ap = 1 + g.alpha_;
  forces.assign(loads.size(), 0.0);
  contacts_.clear(), cd_.clear(), cc_.clear(), pf_.clear();
  std::size_t ci = 0, pi = 0;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const FeLoad& ld = loads[k];
    if (!ld.penalty) {
      r_ += (ap * ld.force) * g.prescribed_[pi++].p;
      pf_.push_back(ld.force);
      forces[k] = ld.force;
      continue;
    }
    const Mod& m = g.mods_[ci++];
    const double Nvt = m.p.dot(vt_), w_x = g.load_px_[k].dot(q_);
    const double conv = ld.speed * (L.static_slope(ld.x) + w_x);
    const double fh = ld.stiffness * (ld.head_y - L.static_height(ld.x)) + ld.damping * (ld.head_v - conv + Nvt);
    const double kc = ld.stiffness + ld.damping * g.c1_;
    contacts_.push_back({static_cast<int>(k), kc, fh});
    cd_.push_back(ap * kc), cc_.push_back(ap * fh);
  }
  const std::size_t nc = contacts_.size();
  if (active_.size() != nc) active_.assign(nc, 1);
  contact_w_.assign(nc, 0.0);
  const auto& md = *g.win_->modes;
  ends_coeff_.resize(static_cast<Eigen::Index>(g.win_->ends.size()));
  for (std::size_t e = 0; e < g.win_->ends.size(); ++e)  // the dashpots: F = −c v = c vt − c c1 u
    ends_coeff_[static_cast<Eigen::Index>(e)] = ap * g.win_->ends[e].damping * md.phi.row(g.win_->ends[e].local).dot(vt_);
  x0_ = r_.cwiseProduct(g.invA_);
}

// The active set of slack droppers and open contacts (d0_: the droppers' rows against x0, set by the
// group), solved in the modal space by the Woodbury identity.
void ModalLanes::Lane::settle(std::vector<double>& forces) {
  const ModalLanes& g = g_;
  const double t1 = t_ + g.h_;
  const std::size_t nc = g.mods_.size(), nd = g.droppers_.size(), ns = g.smods_.size();
  // Displacements without the set (Wx0: contacts, then specials; D0: droppers), the prescribed
  // forces' residual included.
  const Eigen::Index N = static_cast<Eigen::Index>(nc + ns);
  wx0_.resize(N);
  for (std::size_t c = 0; c < nc; ++c) wx0_[static_cast<Eigen::Index>(c)] = g.mods_[c].p.dot(x0_);
  for (std::size_t j = 0; j < nd; ++j) wx0_[static_cast<Eigen::Index>(nc + j)] = d0_[static_cast<Eigen::Index>(j)];
  for (std::size_t e = 0; e < g.win_->ends.size(); ++e) wx0_[static_cast<Eigen::Index>(nc + nd + e)] = g.smods_[nd + e].p.dot(x0_);
  for (std::size_t i = 0; i < g.prescribed_.size(); ++i) {
    const Mod& f = g.prescribed_[i];
    const double F = pf_[i];
    if (F == 0) continue;  // a window's placeholder for a pantograph on another section (fe_coupled.cpp)
    for (std::size_t c = 0; c < nc; ++c) wx0_[static_cast<Eigen::Index>(c)] += g.residual(g.mods_[c], f) * F;
    for (std::size_t s2 = 0; s2 < ns; ++s2) wx0_[static_cast<Eigen::Index>(nc + s2)] += g.residual(g.smods_[s2], f) * F;
    d0_ += g.residual_droppers(f) * F;
  }
  const auto& drs = g.L_.droppers();
  for (int pass = 0;; ++pass) {
    if (pass > 60)
      throw NumericalError(fmt::format(
          "finite-element catenary (modal): t = {:.6g} s: the set of slack droppers and open contacts does not "
          "settle in 60 passes (a dropper or contact chattering; try a smaller time step)",
          t1));
    // The set, as indices into [contacts, specials].
    set_.clear();
    for (std::size_t c = 0; c < nc; ++c)
      if (active_[c]) set_.push_back(static_cast<int>(c));
    for (std::size_t e = 0; e < g.win_->ends.size(); ++e) set_.push_back(static_cast<int>(nc + nd + e));
    for (std::size_t j = 0; j < nd; ++j)
      if (slack_[static_cast<std::size_t>(g.droppers_[j])]) set_.push_back(static_cast<int>(nc + j));
    const Eigen::Index r = static_cast<Eigen::Index>(set_.size());
    auto G = [&](int i, int j) {  // G between entries of [contacts, specials]
      if (j < static_cast<int>(nc)) return g.gc_(i, j);
      if (i < static_cast<int>(nc)) return g.gc_(j, i);
      return g.gs_(i - static_cast<int>(nc), j - static_cast<int>(nc));
    };
    coef_.resize(r);
    if (r > 0) {
      Eigen::VectorXd sv(r), Wx0(r);
      Eigen::MatrixXd Gm(r, r), cap(r, r);
      for (Eigen::Index i = 0; i < r; ++i) {
        const int si = set_[static_cast<std::size_t>(i)];
        sv[i] = coeff(si);
        Wx0[i] = wx0_[si];
        for (Eigen::Index j = 0; j < r; ++j) Gm(i, j) = G(si, set_[static_cast<std::size_t>(j)]);
        cap.row(i) = Gm.row(i);
        cap(i, i) += 1 / d(si);
      }
      coef_ = sv - cap.partialPivLu().solve(Wx0 + Gm * sv);
    }
    bool changed = false;
    for (std::size_t c = 0; c < nc; ++c) {
      double w = wx0_[static_cast<Eigen::Index>(c)];
      for (Eigen::Index j = 0; j < r; ++j) w += G(static_cast<int>(c), set_[static_cast<std::size_t>(j)]) * coef_[j];
      contact_w_[c] = w;
      const double F = contacts_[c].fh - contacts_[c].k * w;
      forces[static_cast<std::size_t>(contacts_[c].load)] = F > 0 ? F : 0.0;
      if ((F > 0) != static_cast<bool>(active_[c])) active_[c] = F > 0, changed = true;
    }
    du_ = d0_;
    for (Eigen::Index j = 0; j < r; ++j) {
      const int sj = set_[static_cast<std::size_t>(j)];
      du_ += coef_[j] * (sj < static_cast<int>(nc) ? g.dwc_.col(sj) : g.dws_.col(sj - static_cast<int>(nc)));
    }
    for (std::size_t j = 0; j < nd; ++j) {
      const int k = g.droppers_[j];
      const double T = drs[static_cast<std::size_t>(k)].tension + drs[static_cast<std::size_t>(k)].stiffness * du_[static_cast<Eigen::Index>(j)];
      if ((T < 0) != static_cast<bool>(slack_[static_cast<std::size_t>(k)])) slack_[static_cast<std::size_t>(k)] = T < 0, changed = true;
    }
    if (!changed) break;
  }
}

// The modal solution u = x0 + Σ coef_j A⁻¹ p_j, the Newmark update of q̇, q̈, and what the queries
// after the step need.
void ModalLanes::Lane::finish(const std::vector<FeLoad>& loads, std::vector<double>& forces) {
  const ModalLanes& g = g_;
  const double t1 = t_ + g.h_, ap = 1 + g.alpha_;
  const std::size_t nc = g.mods_.size();
  const Eigen::Index nm = q_.size();
  sum_.setZero(nm);
  for (std::size_t j = 0; j < set_.size(); ++j) sum_ += coef_[static_cast<Eigen::Index>(j)] * mod(set_[j]).p;
  {
    double *q = q_.data(), *qd = qd_.data(), *qdd = qdd_.data();
    const double *x0 = x0_.data(), *iA = g.invA_.data(), *sm = sum_.data();
    const double c0 = g.c0_, c1 = g.c1_, c2 = g.c2_, c3 = g.c3_, c4 = g.c4_, c5 = g.c5_;
    for (Eigen::Index i = 0; i < nm; ++i) {
      const double u = x0[i] + iA[i] * sm[i], du = u - q[i];
      const double a1 = c0 * du - c2 * qd[i] - c3 * qdd[i];
      qd[i] = c1 * du - c4 * qd[i] - c5 * qdd[i];
      qdd[i] = a1, q[i] = u;
    }
  }
  const auto& md = *g.win_->modes;
  md.check_intact(t1);  // a mapped mode file cut short: no result from its zeros (catenary/mode_store.hpp)
  t_ = t1;
  // The residual (quasi-static) displacement at each load point, for height() and uplift().
  last_F_ = forces;
  last_res_.assign(loads.size(), 0.0);
  for (std::size_t c = 0; c < nc; ++c) last_res_[static_cast<std::size_t>(contacts_[c].load)] = contact_w_[c] - g.mods_[c].p.dot(q_);
  // Prescribed forces: their residual displacement (from every force of the step); at a zero
  // force (a placeholder: it adds nothing to the energy) only when its uplift is asked for.
  prescribed_load_.assign(loads.size(), -1);
  res_ready_.assign(loads.size(), 1);
  for (std::size_t k = 0, i = 0; k < loads.size(); ++k)
    if (!loads[k].penalty) {
      prescribed_load_[k] = static_cast<int>(i);
      if (pf_[i] != 0) last_res_[k] = prescribed_residual(i);
      else res_ready_[k] = 0;
      ++i;
    }
  if (g.alpha_ != 0) {  // q = C v + K₀ u − f at t_{n+1}, in modal coordinates (f: the set's forces)
    qi_ = g.damp_.cwiseProduct(qd_) + md.omega2.cwiseProduct(q_);
    for (std::size_t j = 0; j < set_.size(); ++j) qi_ -= (coef_[static_cast<Eigen::Index>(j)] / ap) * mod(set_[j]).p;
    for (std::size_t i = 0; i < g.prescribed_.size(); ++i) qi_ -= pf_[i] * g.prescribed_[i].p;
  }
}

// The residual displacement at prescribed force i after the step: from every prescribed force and
// the set's terms.
double ModalLanes::Lane::prescribed_residual(std::size_t i) const {
  const ModalLanes& g = g_;
  const Mod& f = g.prescribed_[i];
  const double ap = 1 + g.alpha_;
  double w = 0;
  for (std::size_t k = 0; k < g.prescribed_.size(); ++k) w += g.residual(f, g.prescribed_[k]) * pf_[k];
  for (std::size_t j = 0; j < set_.size(); ++j) w += g.residual(f, mod(set_[j])) * coef_[static_cast<Eigen::Index>(j)] / ap;
  return w;
}

double ModalLanes::Lane::uplift(double x) const {
  const ModalLanes& g = g_;
  if (const int k = g.load_at(x); k >= 0) {  // with the quasi-static part of the modes left out
    const std::size_t kk = static_cast<std::size_t>(k);
    if (kk < res_ready_.size() && !res_ready_[kk])
      last_res_[kk] = prescribed_residual(static_cast<std::size_t>(prescribed_load_[kk])), res_ready_[kk] = 1;
    return g.load_p_[kk].dot(q_) + last_res_[kk];
  }
  const FeLine::Shape sh = g.L_.contact_shape(x);
  double w = 0;
  for (int a = 0; a < 4; ++a)
    if (const int l = sh.dofs[a] >= 0 ? g.win_->local(sh.dofs[a]) : -1; l >= 0) w += sh.N[a] * g.win_->modes->phi.row(l).dot(q_);
  g.win_->modes->check_intact(t_);
  return w;
}

double ModalLanes::Lane::height_rate(double x, double speed) const {
  const ModalLanes& g = g_;
  if (const int k = g.load_at(x); k >= 0)
    return g.load_p_[static_cast<std::size_t>(k)].dot(qd_) + speed * (g.L_.static_slope(x) + g.load_px_[static_cast<std::size_t>(k)].dot(q_));
  const FeLine::Shape sh = g.L_.contact_shape(x);
  double w_dot = 0, w_x = 0;
  for (int a = 0; a < 4; ++a)
    if (const int l = sh.dofs[a] >= 0 ? g.win_->local(sh.dofs[a]) : -1; l >= 0) {
      w_dot += sh.N[a] * g.win_->modes->phi.row(l).dot(qd_);
      w_x += sh.dN[a] * g.win_->modes->phi.row(l).dot(q_);
    }
  g.win_->modes->check_intact(t_);
  return w_dot + speed * (g.L_.static_slope(x) + w_x);
}

// ½ q̇ᵀq̇ + ½ qᵀΩ²q, the residual springs ½ Σ F_k ρ_k of the loads, minus the slack droppers'.
double ModalLanes::Lane::energy() const {
  const ModalLanes& g = g_;
  double E = 0.5 * qd_.squaredNorm() + 0.5 * q_.dot(g.win_->modes->omega2.cwiseProduct(q_));
  for (std::size_t k = 0; k < last_res_.size(); ++k) E += 0.5 * last_F_[k] * last_res_[k];
  const auto& drs = g.L_.droppers();
  for (std::size_t j = 0; j < g.droppers_.size(); ++j)
    if (const auto& dr = drs[static_cast<std::size_t>(g.droppers_[j])]; slack_[static_cast<std::size_t>(g.droppers_[j])] && static_cast<Eigen::Index>(j) < du_.size()) {
      const double e = dr.tension / dr.stiffness + du_[static_cast<Eigen::Index>(j)];
      E -= 0.5 * dr.stiffness * e * e;
    }
  return E;
}

std::vector<double> ModalLanes::Lane::support_uplift() const {
  const ModalLanes& g = g_;
  std::vector<double> u(g.L_.support_dofs().size(), 0.0);  // 0 outside the window
  if (g.support_p_.rows() == 0) return u;
  Eigen::VectorXd h(g.support_p_.rows());
  const double* xs[1] = {q_.data()};
  kernels::rows_dot(g.support_p_.data(), q_.size(), static_cast<int>(g.support_p_.rows()), static_cast<int>(q_.size()), xs, 1, h.data());
  for (std::size_t i = 0; i < g.support_of_.size(); ++i) u[static_cast<std::size_t>(g.support_of_[i])] = h[static_cast<Eigen::Index>(i)];
  return u;
}

void ModalLanes::step(const std::vector<int>& which, const std::vector<std::vector<FeLoad>>& loads,
                      std::vector<std::vector<double>>& forces, std::vector<std::exception_ptr>& errors) {
  const std::size_t n = which.size();
  if (loads.size() != n) throw std::logic_error("modal lanes: a list of loads per lane stepped");
  forces.resize(n), errors.assign(n, nullptr);
  if (n == 0) return;
  std::vector<const std::vector<FeLoad>*> l(n);
  std::vector<std::vector<double>*> f(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (which[j] < 0 || which[j] >= lanes() || (j > 0 && which[j] <= which[j - 1]))
      throw std::logic_error("modal lanes: the lanes stepped must be distinct, ascending and exist");
    l[j] = &loads[j], f[j] = &forces[j];
  }
  step_lanes(which.data(), static_cast<int>(n), l.data(), f.data(), errors.data());
}

// One step of the lanes which[0 … n) (header comment): the window (moved for all of them), the
// loads' modal rows and couplings once; each lane's own arithmetic as a lone run does it.
void ModalLanes::step_lanes(const int* which, int n, const std::vector<FeLoad>* const* loads,
                            std::vector<double>* const* forces, std::exception_ptr* errors) {
  auto lane_at = [&](int j) -> Lane& { return *lanes_[static_cast<std::size_t>(which[j])]; };
  const std::vector<FeLoad>& ld0 = *loads[0];
  for (int j = 0; j < n; ++j) {
    errors[j] = nullptr;
    const std::vector<FeLoad>& lj = *loads[j];
    bool same = lane_at(j).t_ == lane_at(0).t_ && lj.size() == ld0.size();
    for (std::size_t k = 0; same && k < lj.size(); ++k) same = lj[k].x == ld0[k].x && lj[k].penalty == ld0[k].penalty;
    if (!same)
      throw std::logic_error("modal lanes: the lanes stepped together must be at the same time, their loads at the same places");
  }
  // Each lane's part, its exception kept for it.
  auto each = [&](auto&& part) {
    for (int j = 0; j < n; ++j)
      if (!errors[j]) try {
          part(j);
        } catch (...) {
          errors[j] = std::current_exception();
        }
  };
  // The shared part: its exception is every lane's.
  auto shared = [&](auto&& part) {
    try {
      part();
      return true;
    } catch (...) {
      for (int j = 0; j < n; ++j)
        if (!errors[j]) errors[j] = std::current_exception();
      return false;
    }
  };
  const double ap = 1 + alpha_;
  if (!shared([&] {
        xs_.clear();
        for (const FeLoad& ld : ld0) xs_.push_back(ld.x);
        if (const int first = first_span_for(xs_); first != win_->first_span) move_to(first, which, n);
        // The loads' modal rows (Φᵀ N(x), Φᵀ N'(x)): the same in every lane.
        mods_.clear(), prescribed_.clear();
        load_p_.resize(ld0.size()), load_px_.resize(ld0.size());
        for (std::size_t k = 0; k < ld0.size(); ++k) {
          Mod m = contact_mod(L_.contact_shape(ld0[k].x), 0, 0, ld0[k].x, &load_px_[k]);
          load_p_[k] = m.p;  // kept for height, height_rate and uplift at this point after the step
          (ld0[k].penalty ? mods_ : prescribed_).push_back(std::move(m));
        }
        last_x_ = xs_;
      }))
    return;
  each([&](int j) {
    Lane& s = lane_at(j);
    s.rhs();
    s.loads(*loads[j], *forces[j]);
  });
  const std::size_t nc = mods_.size(), nd = droppers_.size();
  const Eigen::Index m = A_.size();
  if (!shared([&] {
        // The droppers' rows with every lane's x0 (the step's largest cost: droppers × modes × lanes),
        // each row read once for all of them.
        std::vector<const double*> x0s;
        std::vector<int> alive;
        for (int j = 0; j < n; ++j)
          if (!errors[j]) x0s.push_back(lane_at(j).x0_.data()), alive.push_back(j);
        const int C = static_cast<int>(x0s.size());
        if (C == 0) return;
        d0_all_.resize(nd * static_cast<std::size_t>(C));
        if (C == 1)
          kernels::rows_dot(dropper_p_.data(), m, static_cast<int>(nd), static_cast<int>(m), x0s.data(), 1, d0_all_.data());
        else
          kernels::rows_dot_each(dropper_p_.data(), m, static_cast<int>(nd), static_cast<int>(m), x0s.data(), C, d0_all_.data());
        for (int c = 0; c < C; ++c) {
          Eigen::VectorXd& d0 = lane_at(alive[static_cast<std::size_t>(c)]).d0_;
          d0.resize(static_cast<Eigen::Index>(nd));
          for (std::size_t r = 0; r < nd; ++r) d0[static_cast<Eigen::Index>(r)] = d0_all_[r * static_cast<std::size_t>(C) + static_cast<std::size_t>(c)];
        }
        // Each contact's A⁻¹p − Ω⁻²p/(1+α), its effect on the droppers (from its DOFs' columns, kept
        // per shape), and its coupling G(c, ·) with everything.
        xz_.resize(m, static_cast<Eigen::Index>(nc));
        for (std::size_t c = 0; c < nc; ++c) xz_.col(static_cast<Eigen::Index>(c)) = mods_[c].p.cwiseProduct(dz_);
        dxz_.resize(static_cast<Eigen::Index>(nd), static_cast<Eigen::Index>(nc));
        std::array<int, 8> missing{};
        int nmiss = 0;
        for (std::size_t c = 0; c < nc && nmiss + 4 <= 8; ++c)
          for (int l : mods_[c].l)
            if (l >= 0 && !dropper_columns_.count(l) && std::find(missing.begin(), missing.begin() + nmiss, l) == missing.begin() + nmiss)
              missing[static_cast<std::size_t>(nmiss++)] = l;
        if (nmiss > 0) make_dropper_columns(missing.data(), nmiss);
        for (std::size_t c = 0; c < nc; ++c) {
          auto col = dxz_.col(static_cast<Eigen::Index>(c));
          col.setZero();
          for (int a = 0; a < 4; ++a)
            if (const int l = mods_[c].l[static_cast<std::size_t>(a)]; l >= 0) col += mods_[c].w[static_cast<std::size_t>(a)] * dropper_column(l);
        }
        const std::size_t ns = smods_.size();
        const Eigen::Index N = static_cast<Eigen::Index>(nc + ns);
        gc_.resize(N, static_cast<Eigen::Index>(nc));
        dwc_.resize(static_cast<Eigen::Index>(nd), static_cast<Eigen::Index>(nc));
        for (std::size_t c = 0; c < nc; ++c) {
          const Mod& mc = mods_[c];
          const auto zc = xz_.col(static_cast<Eigen::Index>(c));  // Z part and the modal part of the residual
          Eigen::VectorXd col(N);
          for (std::size_t c2 = 0; c2 < nc; ++c2) col[static_cast<Eigen::Index>(c2)] = mods_[c2].p.dot(mc.p.cwiseProduct(invA_)) + residual(mods_[c2], mc) / ap;
          const auto dz = dxz_.col(static_cast<Eigen::Index>(c));
          for (std::size_t j = 0; j < nd; ++j)
            col[static_cast<Eigen::Index>(nc + j)] = dz[static_cast<Eigen::Index>(j)] + (mc.ks[static_cast<Eigen::Index>(2 * j)] - mc.ks[static_cast<Eigen::Index>(2 * j + 1)]) / ap;
          for (std::size_t e = 0; e < win_->ends.size(); ++e)
            col[static_cast<Eigen::Index>(nc + nd + e)] = smods_[nd + e].p.dot(zc) + mc.ks[static_cast<Eigen::Index>(2 * nd + e)] / ap;
          gc_.col(static_cast<Eigen::Index>(c)) = col;
          dwc_.col(static_cast<Eigen::Index>(c)) = col.segment(static_cast<Eigen::Index>(nc), static_cast<Eigen::Index>(nd));
        }
      }))
    return;
  each([&](int j) {
    Lane& s = lane_at(j);
    s.settle(*forces[j]);
    s.finish(*loads[j], *forces[j]);
  });
}

}  // namespace

std::unique_ptr<FeLineSolver> make_modal_solver(std::shared_ptr<const FeModalLine> modal, double spread) {
  // A group of one that owns its lane: the lone run's solver.
  struct One final : FeLineSolver {
    explicit One(std::unique_ptr<FeLineLanes> g) : g_(std::move(g)), s_(g_->lane(0)) {}
    double dt() const override { return s_.dt(); }
    double time() const override { return s_.time(); }
    void start(const std::vector<double>& x, const std::vector<double>& F, double t) override { s_.start(x, F, t); }
    void step(const std::vector<FeLoad>& loads, std::vector<double>& forces) override { s_.step(loads, forces); }
    double height(double x) const override { return s_.height(x); }
    double height_rate(double x, double speed) const override { return s_.height_rate(x, speed); }
    double uplift(double x) const override { return s_.uplift(x); }
    std::vector<double> support_uplift() const override { return s_.support_uplift(); }
    double energy() const override { return s_.energy(); }
    std::unique_ptr<FeLineLanes> g_;
    FeLineSolver& s_;
  };
  return std::make_unique<One>(std::make_unique<ModalLanes>(std::move(modal), spread, 1));
}

std::unique_ptr<FeLineLanes> make_modal_lanes(std::shared_ptr<const FeModalLine> modal, double spread, int lanes) {
  return std::make_unique<ModalLanes>(std::move(modal), spread, lanes);
}

namespace {
// Solvers that share nothing, stepped one after the other.
class SeparateLanes final : public FeLineLanes {
 public:
  explicit SeparateLanes(std::vector<std::unique_ptr<FeLineSolver>> s) : s_(std::move(s)) {}
  int lanes() const override { return static_cast<int>(s_.size()); }
  FeLineSolver& lane(int i) override {
    if (i < 0 || i >= lanes()) throw InvalidArgument(fmt::format("lanes: lane {} of {}", i, lanes()));
    return *s_[static_cast<std::size_t>(i)];
  }
  void step(const std::vector<int>& which, const std::vector<std::vector<FeLoad>>& loads,
            std::vector<std::vector<double>>& forces, std::vector<std::exception_ptr>& errors) override {
    forces.resize(which.size()), errors.assign(which.size(), nullptr);
    for (std::size_t j = 0; j < which.size(); ++j) try {
        lane(which[j]).step(loads[j], forces[j]);
      } catch (...) {
        errors[j] = std::current_exception();
      }
  }

 private:
  std::vector<std::unique_ptr<FeLineSolver>> s_;
};
}  // namespace

std::unique_ptr<FeLineLanes> make_separate_lanes(std::vector<std::unique_ptr<FeLineSolver>> solvers) {
  return std::make_unique<SeparateLanes>(std::move(solvers));
}

}  // namespace inerta::catenary
