// The finite-element line: mesh, matrices, form-finding, statics (catenary/fe_catenary.hpp, spec/05 §5.3).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/phase_times.hpp"

namespace inerta::catenary {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

}  // namespace

// Element matrices on [w_i, θ_i, w_j, θ_j] (header comment).
Eigen::Matrix4d beam_stiffness(double EI, double T, double l) {
  Eigen::Matrix4d kb, kg;
  const double l2 = l * l;
  kb << 12, 6 * l, -12, 6 * l, 6 * l, 4 * l2, -6 * l, 2 * l2, -12, -6 * l, 12, -6 * l, 6 * l, 2 * l2, -6 * l, 4 * l2;
  kg << 36, 3 * l, -36, 3 * l, 3 * l, 4 * l2, -3 * l, -l2, -36, -3 * l, 36, -3 * l, 3 * l, -l2, -3 * l, 4 * l2;
  return EI / (l2 * l) * kb + T / (30 * l) * kg;
}

Eigen::Matrix4d beam_mass(double rhoA, double l) {
  Eigen::Matrix4d m;
  const double l2 = l * l;
  m << 156, 22 * l, 54, -13 * l, 22 * l, 4 * l2, 13 * l, -3 * l2, 54, 13 * l, 156, -22 * l, -13 * l, -3 * l2, -22 * l,
      4 * l2;
  return rhoA * l / 420 * m;
}

namespace {

// Hermite cubics and their x-derivatives at ξ ∈ [0, 1] on an element of length l.
void hermite(double xi, double l, std::array<double, 4>& N, std::array<double, 4>& dN) {
  const double x2 = xi * xi, x3 = x2 * xi;
  N = {1 - 3 * x2 + 2 * x3, l * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, l * (-x2 + x3)};
  dN = {(-6 * xi + 6 * x2) / l, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / l, -2 * xi + 3 * x2};
}

void add_block(Triplets& t, const std::array<int, 4>& d, const Eigen::Matrix4d& k) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (d[a] >= 0 && d[b] >= 0 && k(a, b) != 0) t.emplace_back(d[a], d[b], k(a, b));
}

}  // namespace

int FeLine::dof(int wire, int node, int c) const {
  return dof_[static_cast<std::size_t>((node * 2 + wire) * 2 + c)];
}

FeLine::FeLine(FeCatenaryData data) : d_(std::move(data)) {
  const numerics::PhaseTimer timer("line: mesh, form-finding, matrices");
  d_.validate();
  // Mesh: stations at the masts and droppers, each interval divided into equal elements <= h.
  std::vector<double> marks;
  std::vector<int> dropper_at;  // per dropper, its station (filled below)
  for (int s = 0; s < d_.spans; ++s) {
    marks.push_back(s * d_.span);
    for (double xd : d_.dropper_x) marks.push_back(s * d_.span + xd);
  }
  marks.push_back(d_.spans * d_.span);
  std::vector<int> mark_node;
  for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
    mark_node.push_back(static_cast<int>(x_.size()));
    const int n = std::max(1, static_cast<int>(std::ceil((marks[i + 1] - marks[i]) / d_.element_length - 1e-9)));
    for (int k = 0; k < n; ++k) x_.push_back(marks[i] + (marks[i + 1] - marks[i]) * k / n);
  }
  mark_node.push_back(static_cast<int>(x_.size()));
  x_.push_back(marks.back());
  const int N = n_nodes();

  // DOFs interleaved by station [w_m θ_m w_c θ_c] (a narrow band); w fixed at the line's ends.
  dof_.assign(static_cast<std::size_t>(N) * 4, -1);
  for (int i = 0; i < N; ++i)
    for (int w = 0; w < 2; ++w)
      for (int c = 0; c < 2; ++c)
        if (!(c == 0 && (i == 0 || i == N - 1))) dof_[static_cast<std::size_t>((i * 2 + w) * 2 + c)] = n_dofs_++;

  const std::size_t per_span = d_.dropper_x.size() + 1;
  std::vector<int> mast_nodes;  // interior masts
  for (int s = 1; s < d_.spans; ++s) mast_nodes.push_back(mark_node[s * per_span]);

  // Wire matrices and gravity loads, each wire separately (the form-finding needs them apart).
  const FeWire* wires[2] = {&d_.messenger, &d_.contact_wire};
  Triplets tk[2], tm[2];
  Eigen::VectorXd fg[2];
  for (int w = 0; w < 2; ++w) {
    fg[w] = Eigen::VectorXd::Zero(n_dofs_);
    for (int i = 0; i + 1 < N; ++i) {
      const double l = x_[i + 1] - x_[i];
      const std::array<int, 4> d{dof(w, i, 0), dof(w, i, 1), dof(w, i + 1, 0), dof(w, i + 1, 1)};
      add_block(tk[w], d, beam_stiffness(wires[w]->EI, wires[w]->tension, l));
      add_block(tm[w], d, beam_mass(wires[w]->mass_per_length, l));
      const double q = -wires[w]->mass_per_length * d_.gravity;  // consistent load of a uniform weight
      const std::array<double, 4> f{q * l / 2, q * l * l / 12, q * l / 2, -q * l * l / 12};
      for (int a = 0; a < 4; ++a)
        if (d[a] >= 0) fg[w][d[a]] += f[a];
    }
    for (int n : mast_nodes) {
      const int k = dof(w, n, 0);
      tk[w].emplace_back(k, k, w == 0 ? d_.support_stiffness : d_.registration_stiffness);
      const double m = w == 0 ? d_.support_mass : d_.registration_mass;
      tm[w].emplace_back(k, k, m);
      fg[w][k] -= m * d_.gravity;
    }
  }
  // Each wire alone (form-finding): unit diagonal on the other wire's DOFs.
  Triplets tk_alone[2] = {tk[0], tk[1]};
  for (int i = 0; i < N; ++i)
    for (int c = 0; c < 2; ++c)
      for (int w = 0; w < 2; ++w)
        if (dof(1 - w, i, c) >= 0) tk_alone[w].emplace_back(dof(1 - w, i, c), dof(1 - w, i, c), 1.0);
  auto sparse = [&](const Triplets& t) {
    Eigen::SparseMatrix<double> a(n_dofs_, n_dofs_);
    a.setFromTriplets(t.begin(), t.end());
    return a;
  };

  // Droppers (geometry first; lengths from the form-finding below).
  for (int s = 0; s < d_.spans; ++s)
    for (std::size_t j = 0; j < d_.dropper_x.size(); ++j) {
      const int n = mark_node[s * per_span + 1 + j];
      droppers_.push_back({x_[n], n, dof(0, n, 0), dof(1, n, 0), 0, 0, 0});
    }
  for (int n : mast_nodes) support_x_.push_back(x_[n]), support_dofs_.push_back(dof(1, n, 0));

  // Form-finding (header): unknown upward forces on the contact wire — dropper tensions T_d at the
  // droppers and registration forces at the masts — such that w_c = −presag at the droppers and 0 at
  // the masts; then the messenger under its weight and the dropper tensions, with w_m = 0 at the masts.
  // The droppers' own weight depends on their length: iterate (converges in a few passes).
  const int nd = static_cast<int>(droppers_.size()), nm = static_cast<int>(mast_nodes.size());
  std::vector<int> cdofs, mdofs;  // constrained w DOFs: contact wire at droppers then masts; messenger at masts
  for (const Dropper& dr : droppers_) cdofs.push_back(dr.dof_c);
  for (int n : mast_nodes) cdofs.push_back(dof(1, n, 0)), mdofs.push_back(dof(0, n, 0));
  // K w = f + Σ e_j z_j with w_j prescribed at the constrained DOFs j: eliminate them (K_FF w_F =
  // f_F − K_FC w_C, one sparse factor of K_FF, work linear in the line) and the reactions z_j are
  // (K w − f)_j. The same solution as the influence form w = K⁻¹(f + E z), without its dense n × #j.
  struct Constrained {
    Eigen::SparseMatrix<double> K;  // the whole wire
    std::vector<int> fixed, free_of;  // the constrained DOFs; per DOF its index among the free ones, or −1
    BandLlt llt;
    Constrained(Eigen::SparseMatrix<double> k, std::vector<int> fx) : K(std::move(k)), fixed(std::move(fx)) {
      free_of.assign(static_cast<std::size_t>(K.rows()), 0);
      for (int j : fixed) free_of[static_cast<std::size_t>(j)] = -1;
      int nf = 0;
      for (int& i : free_of)
        if (i == 0) i = nf++;
      Triplets t;
      for (int c = 0; c < K.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
          if (free_of[static_cast<std::size_t>(it.row())] >= 0 && free_of[static_cast<std::size_t>(it.col())] >= 0)
            t.emplace_back(free_of[static_cast<std::size_t>(it.row())], free_of[static_cast<std::size_t>(it.col())], it.value());
      Eigen::SparseMatrix<double> kff(nf, nf);
      kff.setFromTriplets(t.begin(), t.end());
      llt.compute(kff);
    }
    // w with w_j = target_j at the constrained DOFs, and the reactions z (in the order of `fixed`).
    std::pair<Eigen::VectorXd, Eigen::VectorXd> solve(const Eigen::VectorXd& f, const Eigen::VectorXd& target) const {
      Eigen::VectorXd w = Eigen::VectorXd::Zero(K.rows());
      for (std::size_t j = 0; j < fixed.size(); ++j) w[fixed[j]] = target[static_cast<Eigen::Index>(j)];
      const Eigen::VectorXd kc = K * w;
      Eigen::VectorXd rhs(llt.rows());
      for (Eigen::Index i = 0; i < K.rows(); ++i)
        if (const int k = free_of[static_cast<std::size_t>(i)]; k >= 0) rhs[k] = f[i] - kc[i];
      const Eigen::VectorXd wf = llt.solve(rhs);
      for (Eigen::Index i = 0; i < K.rows(); ++i)
        if (const int k = free_of[static_cast<std::size_t>(i)]; k >= 0) w[i] = wf[k];
      const Eigen::VectorXd r = K * w - f;
      Eigen::VectorXd z(static_cast<Eigen::Index>(fixed.size()));
      for (std::size_t j = 0; j < fixed.size(); ++j) z[static_cast<Eigen::Index>(j)] = r[fixed[j]];
      return {std::move(w), std::move(z)};
    }
  };
  const Constrained con_c(sparse(tk_alone[1]), cdofs), con_m(sparse(tk_alone[0]), mdofs);
  if (con_c.llt.info() != Eigen::Success || con_m.llt.info() != Eigen::Success)
    throw NumericalError("finite-element catenary: the wire stiffness matrix is singular (check tensions)");
  Eigen::VectorXd target = Eigen::VectorXd::Zero(nd + nm);
  for (int k = 0; k < nd; ++k) target[k] = -d_.presag[static_cast<std::size_t>(k) % d_.presag.size()];
  const Eigen::VectorXd zero_m = Eigen::VectorXd::Zero(nm);
  std::vector<double> len(static_cast<std::size_t>(nd), d_.encumbrance);
  Eigen::VectorXd wc, wm, T;
  for (int pass = 0; pass < 20; ++pass) {
    Eigen::VectorXd fc = fg[1], fm = fg[0];
    for (int k = 0; k < nd; ++k) {
      const double half = 0.5 * d_.dropper_mass_per_length * len[static_cast<std::size_t>(k)] * d_.gravity;
      fc[droppers_[k].dof_c] -= d_.clamp_mass_contact * d_.gravity + half;
      fm[droppers_[k].dof_m] -= d_.clamp_mass_messenger * d_.gravity + half;
    }
    Eigen::VectorXd z;
    std::tie(wc, z) = con_c.solve(fc, target);
    T = z.head(nd);  // dropper tensions (then the registration forces)
    for (int k = 0; k < nd; ++k) fm[droppers_[k].dof_m] -= T[k];
    wm = con_m.solve(fm, zero_m).first;
    double change = 0;
    for (int k = 0; k < nd; ++k) {
      const double l = d_.encumbrance + wm[droppers_[k].dof_m] - wc[droppers_[k].dof_c];
      change = std::max(change, std::abs(l - len[static_cast<std::size_t>(k)]));
      len[static_cast<std::size_t>(k)] = l;
    }
    if (change < 1e-12) break;
  }
  for (int k = 0; k < nd; ++k) {
    Dropper& dr = droppers_[static_cast<std::size_t>(k)];
    dr.tension = T[k];
    const double stretched = len[static_cast<std::size_t>(k)];
    if (!(dr.tension > 0))
      throw ModelError(fmt::format(
          "finite-element catenary: the form-finding gives dropper {} (x = {:.3f} m) a compression of {:.4g} N — "
          "the pre-sag cannot be held by droppers that only pull; check presag and the wire data",
          k + 1, dr.x, -dr.tension));
    if (!(stretched > 0))
      throw ModelError(fmt::format(
          "finite-element catenary: dropper {} (x = {:.3f} m) would need a length of {:.4g} m — the messenger sags "
          "below the contact wire; increase the encumbrance or the messenger tension",
          k + 1, dr.x, stretched));
    dr.length = stretched / (1 + dr.tension / d_.dropper_EA);
    dr.stiffness = d_.dropper_EA / dr.length;
  }

  // The whole line: both wires, droppers taut, dropper and clamp masses.
  Triplets K = tk[0], Mt = tm[0];
  K.insert(K.end(), tk[1].begin(), tk[1].end());
  Mt.insert(Mt.end(), tm[1].begin(), tm[1].end());
  for (const Dropper& dr : droppers_) {
    K.emplace_back(dr.dof_m, dr.dof_m, dr.stiffness);
    K.emplace_back(dr.dof_c, dr.dof_c, dr.stiffness);
    K.emplace_back(dr.dof_m, dr.dof_c, -dr.stiffness);
    K.emplace_back(dr.dof_c, dr.dof_m, -dr.stiffness);
    const double half = 0.5 * d_.dropper_mass_per_length * dr.length;
    Mt.emplace_back(dr.dof_m, dr.dof_m, half + d_.clamp_mass_messenger);
    Mt.emplace_back(dr.dof_c, dr.dof_c, half + d_.clamp_mass_contact);
  }
  K_ = sparse(K);
  M_ = sparse(Mt);
  C_ = d_.rayleigh_mass * M_ + d_.rayleigh_stiffness * K_;
  K_llt_.compute(K_);
  if (K_llt_.info() != Eigen::Success) throw NumericalError("finite-element catenary: K is not positive definite");

  y_contact_.resize(static_cast<std::size_t>(N));
  s_contact_.resize(static_cast<std::size_t>(N));
  messenger_y_.resize(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    const int dw = dof(1, i, 0), dt = dof(1, i, 1), mw = dof(0, i, 0);
    y_contact_[static_cast<std::size_t>(i)] = dw >= 0 ? wc[dw] : 0.0;
    s_contact_[static_cast<std::size_t>(i)] = dt >= 0 ? wc[dt] : 0.0;
    messenger_y_[static_cast<std::size_t>(i)] = d_.encumbrance + (mw >= 0 ? wm[mw] : 0.0);
  }
}

FeLine::Shape FeLine::contact_shape(double x) const {
  if (!(x >= x_.front() - 1e-9 && x <= x_.back() + 1e-9))
    throw ModelError(fmt::format("finite-element catenary: the contact point x = {:.4g} m is off the line [0, {:g}] m",
                                 x, x_.back()));
  auto it = std::upper_bound(x_.begin(), x_.end(), x);
  int i = static_cast<int>(it - x_.begin()) - 1;
  i = std::clamp(i, 0, n_nodes() - 2);
  const double l = x_[static_cast<std::size_t>(i) + 1] - x_[static_cast<std::size_t>(i)];
  Shape s;
  hermite(std::clamp((x - x_[static_cast<std::size_t>(i)]) / l, 0.0, 1.0), l, s.N, s.dN);
  s.dofs = {dof(1, i, 0), dof(1, i, 1), dof(1, i + 1, 0), dof(1, i + 1, 1)};
  s.node = i;
  return s;
}

double FeLine::contact_displacement(const Eigen::VectorXd& u, double x) const {
  const Shape s = contact_shape(x);
  double w = 0;
  for (int a = 0; a < 4; ++a)
    if (s.dofs[a] >= 0) w += s.N[a] * u[s.dofs[a]];
  return w;
}

double FeLine::static_height(double x) const {
  const Shape s = contact_shape(x);
  const std::size_t i = static_cast<std::size_t>(s.node);
  return s.N[0] * y_contact_[i] + s.N[1] * s_contact_[i] + s.N[2] * y_contact_[i + 1] + s.N[3] * s_contact_[i + 1];
}

double FeLine::static_slope(double x) const {
  const Shape s = contact_shape(x);
  const std::size_t i = static_cast<std::size_t>(s.node);
  return s.dN[0] * y_contact_[i] + s.dN[1] * s_contact_[i] + s.dN[2] * y_contact_[i + 1] + s.dN[3] * s_contact_[i + 1];
}

Eigen::VectorXd FeLine::load_vector(double x, double F) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_dofs_);
  const Shape s = contact_shape(x);
  for (int a = 0; a < 4; ++a)
    if (s.dofs[a] >= 0) f[s.dofs[a]] += F * s.N[a];
  return f;
}

double FeLine::elasticity(double x) const {
  const Eigen::VectorXd f = load_vector(x, 1.0);
  return f.dot(K_llt_.solve(f));
}

Eigen::VectorXd FeLine::static_displacement(const std::vector<double>& x, const std::vector<double>& F,
                                            std::vector<char>* slack_out) const {
  if (x.size() != F.size()) throw InvalidArgument("static_displacement: x and F differ in length");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_dofs_);
  for (std::size_t k = 0; k < x.size(); ++k) f += load_vector(x[k], F[k]);
  std::vector<char> slack(droppers_.size(), 0);
  Eigen::VectorXd u = K_llt_.solve(f);
  for (int iter = 0; iter < 100; ++iter) {
    bool changed = false;
    for (std::size_t k = 0; k < droppers_.size(); ++k) {
      const Dropper& d = droppers_[k];
      const bool want = d.tension + d.stiffness * (u[d.dof_m] - u[d.dof_c]) < 0;
      if (want != static_cast<bool>(slack[k])) slack[k] = want, changed = true;
    }
    if (!changed) {
      if (slack_out) *slack_out = slack;
      return u;
    }
    // K with the slack droppers removed, their static tension applied as a load instead.
    Eigen::SparseMatrix<double> Ks = K_;
    Eigen::VectorXd fs = f;
    for (std::size_t k = 0; k < droppers_.size(); ++k) {
      if (!slack[k]) continue;
      const Dropper& d = droppers_[k];
      Ks.coeffRef(d.dof_m, d.dof_m) -= d.stiffness;
      Ks.coeffRef(d.dof_c, d.dof_c) -= d.stiffness;
      Ks.coeffRef(d.dof_m, d.dof_c) += d.stiffness;
      Ks.coeffRef(d.dof_c, d.dof_m) += d.stiffness;
      fs[d.dof_m] += d.tension;
      fs[d.dof_c] -= d.tension;
    }
    BandLlt llt(Ks);
    if (llt.info() != Eigen::Success)
      throw NumericalError("finite-element catenary: the line with its slack droppers has no static equilibrium");
    u = llt.solve(fs);
  }
  throw NumericalError("finite-element catenary: the slack droppers of the static state did not settle in 100 passes");
}

double FeLine::dropper_length_error_max() const {
  double e = 0;
  if (d_.nominal_dropper_length.empty()) return 0;
  for (std::size_t k = 0; k < droppers_.size(); ++k)
    e = std::max(e, std::abs(droppers_[k].length -
                             d_.nominal_dropper_length[k % d_.nominal_dropper_length.size()]));
  return e;
}

std::string FeLine::describe() const {
  return fmt::format(
      "finite-element catenary: {} spans of {:g} m ({:g} m), {} droppers, {} elements a wire, {} unknowns; wave speed "
      "contact wire {:.1f} m/s ({:.0f} km/h), messenger {:.1f} m/s",
      d_.spans, d_.span, length(), droppers_.size(), n_nodes() - 1, n_dofs_, d_.contact_wire.wave_speed(),
      3.6 * d_.contact_wire.wave_speed(), d_.messenger.wave_speed());
}

}  // namespace inerta::catenary
