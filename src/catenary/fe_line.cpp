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

// The height-error profile at x (linear between its points; validate() has checked it covers the line).
double height_error_at(const FeIrregularity& irr, double x) {
  const std::vector<double>& X = irr.height_error_x;
  const auto it = std::upper_bound(X.begin(), X.end(), x);
  const std::size_t i = std::min<std::size_t>(X.size() - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - X.begin())));
  const double t = (x - X[i - 1]) / (X[i] - X[i - 1]);
  return irr.height_error_dz[i - 1] + t * (irr.height_error_dz[i] - irr.height_error_dz[i - 1]);
}

void add_block(Triplets& t, const std::array<int, 4>& d, const Eigen::Matrix4d& k) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (d[a] >= 0 && d[b] >= 0 && k(a, b) != 0) t.emplace_back(d[a], d[b], k(a, b));
}

}  // namespace

int FeLine::dof(int wire, int node, int c) const {
  return dof_[static_cast<std::size_t>((node * kWires + wire) * 2 + c)];
}

double FeLine::stitch_height(int node) const { return stitch_y_[static_cast<std::size_t>(node)]; }

FeLine::FeLine(FeCatenaryData data) : d_(std::move(data)) {
  const numerics::PhaseTimer timer("line: mesh, form-finding, matrices");
  d_.validate();
  // The line's description, as data: per span its marks (mast, droppers, stitch clamps) in order.
  // A stitch wire at every interior mast (FeStitch); the stitch droppers on the line's side of an
  // end mast, and all of them without the stitch wire, hang from the messenger.
  const FeStitch& st = d_.stitch;
  const bool stitched = d_.has_stitch();
  enum class Mark { Mast, SpanDropper, StitchDropper, StitchEnd };
  struct Item {
    double x;  // from the span's first mast
    Mark kind;
    int index;       // droppers.x / stitch.droppers.x
    bool on_stitch;  // a stitch dropper hanging from the stitch wire
  };
  std::vector<std::vector<Item>> items(static_cast<std::size_t>(d_.spans));
  for (int s = 0; s < d_.spans; ++s) {
    std::vector<Item>& it = items[static_cast<std::size_t>(s)];
    it.push_back({0.0, Mark::Mast, 0, false});
    for (std::size_t j = 0; j < d_.dropper_x.size(); ++j) it.push_back({d_.dropper_x[j], Mark::SpanDropper, static_cast<int>(j), false});
    if (st.present) {
      const bool behind_stitch = stitched && s > 0, ahead_stitch = stitched && s + 1 < d_.spans;  // the masts at s, s + 1
      for (std::size_t j = 0; j < st.dropper_x.size(); ++j) {
        const double p = st.dropper_x[j];
        if (p > 0) it.push_back({p, Mark::StitchDropper, static_cast<int>(j), behind_stitch});
        if (p < 0) it.push_back({d_.span + p, Mark::StitchDropper, static_cast<int>(j), ahead_stitch});
      }
      if (behind_stitch) it.push_back({0.5 * st.length, Mark::StitchEnd, 0, false});
      if (ahead_stitch) it.push_back({d_.span - 0.5 * st.length, Mark::StitchEnd, 1, false});
      std::stable_sort(it.begin(), it.end(), [](const Item& a, const Item& b) { return a.x < b.x; });
    }
  }
  // Mesh: stations at the marks, each interval divided into equal elements <= h.
  std::vector<double> marks;
  std::vector<const Item*> mark_item;
  for (int s = 0; s < d_.spans; ++s)
    for (const Item& it : items[static_cast<std::size_t>(s)]) {
      marks.push_back(it.kind == Mark::Mast ? s * d_.span : s * d_.span + it.x);
      mark_item.push_back(&it);
    }
  marks.push_back(d_.spans * d_.span);
  mark_item.push_back(nullptr);
  std::vector<int> mark_node;
  for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
    mark_node.push_back(static_cast<int>(x_.size()));
    const int n = std::max(1, static_cast<int>(std::ceil((marks[i + 1] - marks[i]) / d_.element_length - 1e-9)));
    for (int k = 0; k < n; ++k) x_.push_back(marks[i] + (marks[i + 1] - marks[i]) * k / n);
  }
  mark_node.push_back(static_cast<int>(x_.size()));
  x_.push_back(marks.back());
  const int N = n_nodes();
  std::vector<int> mast_nodes;  // interior masts
  for (std::size_t i = 0; i + 1 < marks.size(); ++i)
    if (mark_item[i]->kind == Mark::Mast && i > 0) mast_nodes.push_back(mark_node[i]);
  std::vector<int> end_nodes;  // anchors on a tensioning device (not pinned): their w is free
  if (!d_.anchor.pinned) end_nodes = {0, N - 1};
  // A tension section's heights (FeCatenaryData::height_at): w is taken from the straight
  // line g between the two anchors' heights (a linear g loads no interior DOF of a tensioned beam),
  // the masts' and droppers' targets relative to it.
  const bool heights = !d_.height_x.empty() || !d_.mast_height.empty();
  const double g_a = d_.height_at(0), g_slope = (d_.height_at(length()) - g_a) / length();
  auto g_of = [&](double x) { return g_a + g_slope * x; };
  auto height_at = [&](double x) { return d_.height_at(x); };
  // The stitch wire's stations: from its clamp behind a mast to its clamp ahead (0: none, 1: inside,
  // 2: a clamp — its w is the messenger's).
  std::vector<char> on_stitch(static_cast<std::size_t>(N), 0);
  if (stitched)
    for (std::size_t i = 0; i + 1 < marks.size(); ++i)
      if (mark_item[i]->kind == Mark::StitchEnd && mark_item[i]->index == 1) {
        std::size_t e = i + 1;
        while (!(mark_item[e]->kind == Mark::StitchEnd && mark_item[e]->index == 0)) ++e;
        for (int n = mark_node[i]; n <= mark_node[e]; ++n) on_stitch[static_cast<std::size_t>(n)] = 1;
        on_stitch[static_cast<std::size_t>(mark_node[i])] = on_stitch[static_cast<std::size_t>(mark_node[e])] = 2;
      }

  // DOFs interleaved by station [w_m θ_m w_c θ_c (w_s θ_s)] (a narrow band); w fixed at the line's ends.
  dof_.assign(static_cast<std::size_t>(N) * 2 * kWires, -1);
  for (int i = 0; i < N; ++i)
    for (int w = 0; w < kWires; ++w)
      for (int c = 0; c < 2; ++c) {
        int& slot = dof_[static_cast<std::size_t>((i * kWires + w) * 2 + c)];
        if (w == 2) {
          const char o = on_stitch[static_cast<std::size_t>(i)];
          if (o == 0) continue;
          if (o == 2 && c == 0) {  // clamped to the messenger: the same vertical displacement
            slot = dof(0, i, 0);
            continue;
          }
        }
        if (!(c == 0 && (i == 0 || i == N - 1) && d_.anchor.pinned)) slot = n_dofs_++;
      }

  // Wire matrices and gravity loads; the messenger and the stitch wires (the upper structure) apart
  // from the contact wire (the form-finding needs them apart).
  const FeWire* wires[3] = {&d_.messenger, &d_.contact_wire, &st.wire};
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
    for (int n : end_nodes) {  // a tensioning device at the anchors: its vertical stiffness and mass
      const int k = dof(w, n, 0);
      tk[w].emplace_back(k, k, d_.anchor.stiffness);
      tm[w].emplace_back(k, k, d_.anchor.mass);
      fg[w][k] -= d_.anchor.mass * d_.gravity;
    }
  }
  if (stitched) {  // stitch wires: part of the upper structure; clamp masses on the messenger
    for (int i = 0; i + 1 < N; ++i) {
      const char a = on_stitch[static_cast<std::size_t>(i)], b = on_stitch[static_cast<std::size_t>(i) + 1];
      if (!a || !b || (a == 2 && b == 2)) continue;  // two clamps in a row: of two stitch wires
      const double l = x_[i + 1] - x_[i];
      const std::array<int, 4> d{dof(2, i, 0), dof(2, i, 1), dof(2, i + 1, 0), dof(2, i + 1, 1)};
      add_block(tk[0], d, beam_stiffness(st.wire.EI, st.wire.tension, l));
      add_block(tm[0], d, beam_mass(st.wire.mass_per_length, l));
      const double q = -st.wire.mass_per_length * d_.gravity;
      const std::array<double, 4> f{q * l / 2, q * l * l / 12, q * l / 2, -q * l * l / 12};
      for (int a = 0; a < 4; ++a)
        if (d[a] >= 0) fg[0][d[a]] += f[a];
    }
    for (int i = 0; i < N; ++i)
      if (on_stitch[static_cast<std::size_t>(i)] == 2) {
        const int k = dof(0, i, 0);
        tm[0].emplace_back(k, k, st.clamp_mass);
        fg[0][k] -= st.clamp_mass * d_.gravity;
      }
  }
  // Each wire alone (form-finding): unit diagonal on the other wire's DOFs.
  Triplets tk_alone[2] = {tk[0], tk[1]};
  for (int i = 0; i < N; ++i)
    for (int c = 0; c < 2; ++c)
      for (int w = 0; w < 2; ++w)
        if (dof(1 - w, i, c) >= 0) tk_alone[w].emplace_back(dof(1 - w, i, c), dof(1 - w, i, c), 1.0);
  for (int i = 0; i < N; ++i)  // the stitch wires' own DOFs belong to the upper structure
    for (int c = 0; c < 2; ++c)
      if (const int k = dof(2, i, c); k >= 0 && !(c == 0 && on_stitch[static_cast<std::size_t>(i)] == 2))
        tk_alone[1].emplace_back(k, k, 1.0);
  auto sparse = [&](const Triplets& t) {
    Eigen::SparseMatrix<double> a(n_dofs_, n_dofs_);
    a.setFromTriplets(t.begin(), t.end());
    return a;
  };

  // Droppers in line order (geometry first; lengths from the form-finding below), each with its data.
  std::vector<double> presag;  // per dropper
  for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
    const Item& it = *mark_item[i];
    if (it.kind != Mark::SpanDropper && it.kind != Mark::StitchDropper) continue;
    const int n = mark_node[i];
    Dropper dr{x_[n], n, dof(it.on_stitch ? 2 : 0, n, 0), dof(1, n, 0), 0, 0, 0};
    dr.index = it.index;
    const std::size_t j = static_cast<std::size_t>(it.index);
    if (it.kind == Mark::SpanDropper) {
      dr.kind = Dropper::Kind::Span;
      dr.EA = d_.dropper_EA, dr.mass_per_length = d_.dropper_mass_per_length;
      dr.clamp_upper = d_.clamp_mass_messenger, dr.clamp_contact = d_.clamp_mass_contact;
      presag.push_back(d_.presag[j]);
    } else {
      dr.kind = Dropper::Kind::Stitch;
      dr.on_stitch_wire = it.on_stitch;
      dr.EA = st.dropper_EA, dr.mass_per_length = st.dropper_mass_per_length;
      dr.clamp_upper = it.on_stitch ? st.clamp_mass_stitch : d_.clamp_mass_messenger;
      dr.clamp_contact = st.clamp_mass_contact;
      presag.push_back(st.dropper_presag.empty() ? 0.0 : st.dropper_presag[j]);
    }
    droppers_.push_back(dr);
  }
  for (int n : mast_nodes) support_x_.push_back(x_[n]), support_dofs_.push_back(dof(1, n, 0));
  const FeIrregularity& irr = d_.irregularity;
  const int nd = static_cast<int>(droppers_.size()), nm = static_cast<int>(mast_nodes.size());
  if (!irr.dropper_length_errors.empty() && irr.dropper_length_errors.size() != droppers_.size())
    throw InvalidArgument("finite-element catenary: irregularity", "dropper_length_errors",
                          fmt::format("needs one value per dropper of the line in line order ({}), got {}", nd,
                                      irr.dropper_length_errors.size()));

  // Form-finding (header): unknown upward forces on the contact wire — dropper tensions T_d at the
  // droppers and registration forces at the masts — such that w_c = −presag (+ the height error) at
  // the droppers and 0 at the masts; then the upper structure (messenger and stitch wires, the
  // stitch's ends on the messenger) under its weight and the dropper tensions, with w_m = 0 at the
  // masts. The droppers' own weight depends on their length: iterate (converges in a few passes).
  std::vector<int> cdofs, mdofs;  // constrained w DOFs: contact wire at droppers then masts; messenger at masts
  for (const Dropper& dr : droppers_) cdofs.push_back(dr.dof_c);
  for (int n : mast_nodes) cdofs.push_back(dof(1, n, 0)), mdofs.push_back(dof(0, n, 0));
  for (int n : end_nodes) cdofs.push_back(dof(1, n, 0)), mdofs.push_back(dof(0, n, 0));
  const int ne = static_cast<int>(end_nodes.size());
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
  Eigen::VectorXd target = Eigen::VectorXd::Zero(nd + nm + ne);
  for (int k = 0; k < nd; ++k) target[k] = -presag[static_cast<std::size_t>(k)];
  Eigen::VectorXd zero_m = Eigen::VectorXd::Zero(nm + ne);
  if (heights) {
    for (int k = 0; k < nd; ++k) {
      const double x = droppers_[static_cast<std::size_t>(k)].x;
      target[k] += height_at(x) - g_of(x);
    }
    for (int j = 0; j < nm; ++j) {
      const double x = x_[static_cast<std::size_t>(mast_nodes[static_cast<std::size_t>(j)])];
      target[nd + j] = zero_m[j] = height_at(x) - g_of(x);
    }
  }
  const Eigen::VectorXd design_target = target;
  if (!irr.height_error_x.empty())  // installation error: added to the target heights at the droppers
    for (int k = 0; k < nd; ++k) target[k] += height_error_at(irr, droppers_[static_cast<std::size_t>(k)].x);
  // The form-finding at the contact-wire targets `tgt`: stretched dropper lengths, wire heights and
  // dropper tensions.
  // The straight line g as DOF values (w: g(x), θ: its slope) and the forces K g of each wire on
  // it: zero inside a wire, but not where a stitch wire ends on the messenger (T_s g′ at its clamps).
  Eigen::VectorXd kg[2];
  if (heights) {
    g_dofs_ = Eigen::VectorXd::Zero(n_dofs_);
    for (int i = 0; i < N; ++i)
      for (int w = 0; w < kWires; ++w) {
        if (const int k = dof(w, i, 0); k >= 0) g_dofs_[k] = g_of(x_[static_cast<std::size_t>(i)]);
        if (const int k = dof(w, i, 1); k >= 0) g_dofs_[k] = g_slope;
      }
    for (int w = 0; w < 2; ++w) kg[w] = sparse(tk[w]) * g_dofs_;
    // A pinned anchor's w is no unknown, but g there (its height) acts on its element's free DOFs
    // too: without it K g is not zero next to an anchor above 0, and the wire's first element is
    // pulled towards 0 (the incoming section of an overlap, its anchor raised).
    if (d_.anchor.pinned) {
      g_anchor_force_ = Eigen::VectorXd::Zero(n_dofs_);
      for (int w = 0; w < 2; ++w)
        for (const auto& [e, b] : {std::pair{0, 0}, std::pair{N - 2, 2}}) {  // (element, the anchor's local w): node 0, node N − 1
          const Eigen::Matrix4d ke = beam_stiffness(wires[w]->EI, wires[w]->tension, x_[e + 1] - x_[e]);
          const std::array<int, 4> dd{dof(w, e, 0), dof(w, e, 1), dof(w, e + 1, 0), dof(w, e + 1, 1)};
          if (dd[b] >= 0) continue;
          const double gb = g_of(x_[static_cast<std::size_t>(e + b / 2)]);
          for (int a = 0; a < 4; ++a)
            if (dd[a] >= 0) kg[w][dd[a]] += ke(a, b) * gb, g_anchor_force_[dd[a]] += ke(a, b) * gb;
        }
    }
  }
  auto form_find = [&](const Eigen::VectorXd& tgt, std::vector<double>& len, Eigen::VectorXd& wc, Eigen::VectorXd& wm,
                       Eigen::VectorXd& T) {
    len.assign(static_cast<std::size_t>(nd), d_.encumbrance);
    for (int pass = 0; pass < 20; ++pass) {
      Eigen::VectorXd fc = fg[1], fm = fg[0];
      if (heights) fc -= kg[1], fm -= kg[0];
      for (int k = 0; k < nd; ++k) {
        const Dropper& dr = droppers_[static_cast<std::size_t>(k)];
        const double half = 0.5 * dr.mass_per_length * len[static_cast<std::size_t>(k)] * d_.gravity;
        fc[dr.dof_c] -= dr.clamp_contact * d_.gravity + half;
        fm[dr.dof_m] -= dr.clamp_upper * d_.gravity + half;
      }
      Eigen::VectorXd z;
      std::tie(wc, z) = con_c.solve(fc, tgt);
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
  };
  std::vector<double> len;
  Eigen::VectorXd wc, wm, T;
  form_find(target, len, wc, wm, T);
  for (int k = 0; k < nd; ++k) {
    Dropper& dr = droppers_[static_cast<std::size_t>(k)];
    dr.tension = T[k];
    const double stretched = len[static_cast<std::size_t>(k)];
    if (!(dr.tension > 0))
      throw ModelError(fmt::format(
          "finite-element catenary: the form-finding gives dropper {} (x = {:.3f} m) a compression of {:.4g} N — "
          "the pre-sag cannot be held by droppers that only pull; check presag and the wire data",
          k + 1, dr.x, -dr.tension));
    if (!(stretched > 0)) {
      if (dr.on_stitch_wire)  // the stitch wire carries its droppers' share of the contact wire alone
        throw ModelError(fmt::format(
            "finite-element catenary: stitch dropper {} (x = {:.3f} m, stitch.droppers.x[{}]) would need a length of "
            "{:.4g} m — the stitch wire sags below the contact wire under its droppers' load; move the stitch "
            "droppers towards the stitch wire's clamps (stitch.droppers.x, within ±stitch.length/2), or raise "
            "stitch.tension",
            k + 1, dr.x, dr.index, stretched));
      throw ModelError(fmt::format(
          "finite-element catenary: dropper {} (x = {:.3f} m) would need a length of {:.4g} m — the messenger sags "
          "below the contact wire; increase the encumbrance or the messenger tension",
          k + 1, dr.x, stretched));
    }
    dr.length = stretched / (1 + dr.tension / dr.EA);
    dr.stiffness = dr.static_stiffness = dr.EA / dr.length;
  }
  // The droppers as designed (the form-finding without height errors): their stiffness EA/L and
  // mass in the line's dynamics (FeIrregularity::exact_dropper_dynamics).
  std::vector<double> design_length(static_cast<std::size_t>(nd));
  for (int k = 0; k < nd; ++k) design_length[static_cast<std::size_t>(k)] = droppers_[static_cast<std::size_t>(k)].length;
  if (!irr.height_error_x.empty()) {
    std::vector<double> dlen;
    Eigen::VectorXd dwc, dwm, dT;
    form_find(design_target, dlen, dwc, dwm, dT);
    for (int k = 0; k < nd; ++k)
      design_length[static_cast<std::size_t>(k)] = dlen[static_cast<std::size_t>(k)] / (1 + dT[k] / droppers_[static_cast<std::size_t>(k)].EA);
  }

  // Irregularities on the form-found line (FeIrregularity): dropper lengths off by δ_k (the dropper
  // now pulls T'_k = EA/L'_k (ℓ_k − L'_k), L'_k = L_k + δ_k, at the form-found geometry) and point
  // masses on the contact wire. Their loads f' move the line to its reference state u_ref = K'⁻¹ f'
  // (droppers bilateral: linear); a dropper whose tension there is negative is slack in the static
  // state, which the solvers' static_displacement finds from the reference state (header).
  std::vector<double> delta(static_cast<std::size_t>(nd), 0.0);
  if (irr.dropper_length_std > 0) delta = dropper_length_errors(irr, static_cast<std::size_t>(nd));
  for (std::size_t k = 0; k < irr.dropper_length_errors.size(); ++k) delta[k] += irr.dropper_length_errors[k];
  Eigen::VectorXd f_irr = Eigen::VectorXd::Zero(n_dofs_);
  bool irregular = !irr.point_masses.empty();
  for (int k = 0; k < nd; ++k) {
    const double dk = delta[static_cast<std::size_t>(k)];
    if (dk == 0) continue;
    irregular = true;
    Dropper& dr = droppers_[static_cast<std::size_t>(k)];
    const double stretched = len[static_cast<std::size_t>(k)], L1 = dr.length + dk;
    if (!(L1 > 0))
      throw ModelError(fmt::format("finite-element catenary: irregularity: dropper {} (x = {:.3f} m) of {:.4g} m "
                                   "with a length error of {:.4g} m has no length left",
                                   k + 1, dr.x, dr.length, dk));
    const double T1 = dr.EA / L1 * (stretched - L1);
    // Its weight changes with its length too (half at each end).
    const double dw = 0.5 * dr.mass_per_length * dk * d_.gravity;
    f_irr[dr.dof_c] += (T1 - dr.tension) - dw;
    f_irr[dr.dof_m] -= (T1 - dr.tension) + dw;
    dr.length = L1, dr.static_stiffness = dr.EA / L1, dr.tension = T1;
  }
  Triplets point_mass_m;
  for (const FeIrregularity::PointMass& pm : irr.point_masses) {
    const Shape sh = contact_shape(pm.x);
    for (int a = 0; a < 4; ++a) {
      if (sh.dofs[a] < 0) continue;
      f_irr[sh.dofs[a]] -= pm.mass * d_.gravity * sh.N[a];
      for (int b = 0; b < 4; ++b)
        if (sh.dofs[b] >= 0) point_mass_m.emplace_back(sh.dofs[a], sh.dofs[b], pm.mass * sh.N[a] * sh.N[b]);
    }
  }

  // The whole line: both wires, droppers taut, dropper and clamp masses.
  Triplets K = tk[0], Mt = tm[0];
  K.insert(K.end(), tk[1].begin(), tk[1].end());
  Mt.insert(Mt.end(), tm[1].begin(), tm[1].end());
  K_wires_ = sparse(K);
  f_gravity_ = fg[0] + fg[1];
  const bool design_dynamics = !irr.exact_dropper_dynamics;
  Triplets Ks = K;
  for (std::size_t k = 0; k < droppers_.size(); ++k) {
    Dropper& dr = droppers_[k];
    const double Ld = design_dynamics ? design_length[k] : dr.length;
    dr.stiffness = dr.EA / Ld;
    for (auto [t, kd] : {std::pair{&K, dr.stiffness}, std::pair{&Ks, dr.static_stiffness}}) {
      t->emplace_back(dr.dof_m, dr.dof_m, kd);
      t->emplace_back(dr.dof_c, dr.dof_c, kd);
      t->emplace_back(dr.dof_m, dr.dof_c, -kd);
      t->emplace_back(dr.dof_c, dr.dof_m, -kd);
    }
    const double half = 0.5 * dr.mass_per_length * Ld;
    Mt.emplace_back(dr.dof_m, dr.dof_m, half + dr.clamp_upper);
    Mt.emplace_back(dr.dof_c, dr.dof_c, half + dr.clamp_contact);
    // The weight the static state carries: the form-finding takes a dropper's weight at its stretched
    // length (a T/EA ≈ 0.1 % approximation of it), an irregular one's changed by its error.
    const double carried = 0.5 * dr.mass_per_length * (len[k] + delta[k]);
    f_gravity_[dr.dof_m] -= (carried + dr.clamp_upper) * d_.gravity;
    f_gravity_[dr.dof_c] -= (carried + dr.clamp_contact) * d_.gravity;
  }
  for (const FeIrregularity::PointMass& pm : irr.point_masses) {
    const Shape sh = contact_shape(pm.x);
    for (int a = 0; a < 4; ++a)
      if (sh.dofs[a] >= 0) f_gravity_[sh.dofs[a]] -= pm.mass * d_.gravity * sh.N[a];
  }
  Mt.insert(Mt.end(), point_mass_m.begin(), point_mass_m.end());
  K_ = sparse(K);
  K_static_ = sparse(Ks);
  M_ = sparse(Mt);
  C_ = d_.rayleigh_mass * M_ + d_.rayleigh_stiffness * K_;
  K_llt_.compute(K_static_);
  if (K_llt_.info() != Eigen::Success) throw NumericalError("finite-element catenary: K is not positive definite");
  w_static_ = wc + wm;
  if (irregular) {
    const Eigen::VectorXd u = K_llt_.solve(f_irr);
    w_static_ += u;
    for (Dropper& dr : droppers_) dr.tension += dr.static_stiffness * (u[dr.dof_m] - u[dr.dof_c]);
  }

  y_contact_.resize(static_cast<std::size_t>(N));
  s_contact_.resize(static_cast<std::size_t>(N));
  messenger_y_.resize(static_cast<std::size_t>(N));
  stitch_y_.assign(static_cast<std::size_t>(N), NAN);
  for (int i = 0; i < N; ++i) {
    const int dw = dof(1, i, 0), dt = dof(1, i, 1), mw = dof(0, i, 0), sw = dof(2, i, 0);
    y_contact_[static_cast<std::size_t>(i)] = dw >= 0 ? w_static_[dw] : 0.0;
    s_contact_[static_cast<std::size_t>(i)] = dt >= 0 ? w_static_[dt] : 0.0;
    messenger_y_[static_cast<std::size_t>(i)] = d_.encumbrance + (mw >= 0 ? w_static_[mw] : 0.0);
    if (sw >= 0) stitch_y_[static_cast<std::size_t>(i)] = d_.encumbrance + w_static_[sw];
    if (heights) {  // from the straight line between the anchors (above)
      const double g = g_of(x_[static_cast<std::size_t>(i)]);
      y_contact_[static_cast<std::size_t>(i)] += g, s_contact_[static_cast<std::size_t>(i)] += g_slope;
      messenger_y_[static_cast<std::size_t>(i)] += g;
      if (sw >= 0) stitch_y_[static_cast<std::size_t>(i)] += g;
    }
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
      const bool want = d.tension + d.static_stiffness * (u[d.dof_m] - u[d.dof_c]) < 0;
      if (want != static_cast<bool>(slack[k])) slack[k] = want, changed = true;
    }
    if (!changed) {
      if (slack_out) *slack_out = slack;
      return u;
    }
    // K with the slack droppers removed, their static tension applied as a load instead.
    Eigen::SparseMatrix<double> Ks = K_static_;
    Eigen::VectorXd fs = f;
    for (std::size_t k = 0; k < droppers_.size(); ++k) {
      if (!slack[k]) continue;
      const Dropper& d = droppers_[k];
      Ks.coeffRef(d.dof_m, d.dof_m) -= d.static_stiffness;
      Ks.coeffRef(d.dof_c, d.dof_c) -= d.static_stiffness;
      Ks.coeffRef(d.dof_m, d.dof_c) += d.static_stiffness;
      Ks.coeffRef(d.dof_c, d.dof_m) += d.static_stiffness;
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
  for (const Dropper& dr : droppers_)
    if (dr.kind == Dropper::Kind::Span)
      e = std::max(e, std::abs(dr.length - d_.nominal_dropper_length[static_cast<std::size_t>(dr.index)]));
  return e;
}

// Equilibrium of the static state on the assembled line (header): heights w = w_ref + u₀ (u₀ the
// static displacement without pantographs, slack droppers found), the residual of
// K_w w − f_g − Σ T_d (e_c − e_upper) at every free DOF but the masts' w (their support forces).
FeLine::Residual FeLine::equilibrium_residual() const {
  std::vector<char> slack;
  const Eigen::VectorXd u0 = static_displacement({}, {}, &slack);
  const Eigen::VectorXd w = w_static_ + u0;
  Eigen::VectorXd r = K_wires_ * (g_dofs_.size() ? Eigen::VectorXd(w + g_dofs_) : w) - f_gravity_;
  if (g_anchor_force_.size()) r += g_anchor_force_;
  Residual out;
  for (std::size_t k = 0; k < droppers_.size(); ++k) {
    const Dropper& dr = droppers_[k];
    const double upper = d_.encumbrance + w[dr.dof_m], lower = w[dr.dof_c];
    const double T = std::max(0.0, dr.EA / dr.length * ((upper - lower) - dr.length));
    if (!slack[k]) {
      const double T_lin = dr.tension + dr.static_stiffness * (u0[dr.dof_m] - u0[dr.dof_c]);
      out.dropper = std::max(out.dropper, std::abs(T - T_lin));
    }
    r[dr.dof_c] -= T;
    r[dr.dof_m] += T;
  }
  std::vector<char> mast(static_cast<std::size_t>(n_dofs_), 0);
  for (int n = 0; n < n_nodes(); ++n)
    for (double xs : support_x_)
      if (std::abs(x_[static_cast<std::size_t>(n)] - xs) < 1e-9) mast[static_cast<std::size_t>(dof(0, n, 0))] = mast[static_cast<std::size_t>(dof(1, n, 0))] = 1;
  if (!d_.anchor.pinned)  // the anchors' devices carry the wires' end forces
    for (int n : {0, n_nodes() - 1}) mast[static_cast<std::size_t>(dof(0, n, 0))] = mast[static_cast<std::size_t>(dof(1, n, 0))] = 1;
  for (int i = 0; i < n_dofs_; ++i) {
    out.load_scale = std::max(out.load_scale, std::abs(f_gravity_[i]));
    if (!mast[static_cast<std::size_t>(i)]) out.force = std::max(out.force, std::abs(r[i]));
  }
  return out;
}

std::string FeLine::describe() const {
  std::string s = fmt::format(
      "finite-element catenary: {} spans of {:g} m ({:g} m), {} droppers, {} elements a wire, {} unknowns; wave speed "
      "contact wire {:.1f} m/s ({:.0f} km/h), messenger {:.1f} m/s",
      d_.spans, d_.span, length(), droppers_.size(), n_nodes() - 1, n_dofs_, d_.contact_wire.wave_speed(),
      3.6 * d_.contact_wire.wave_speed(), d_.messenger.wave_speed());
  if (d_.has_stitch())
    s += fmt::format("; stitch wires of {:g} m at the {} interior masts ({:g} N)", d_.stitch.length, support_x_.size(),
                     d_.stitch.wire.tension);
  if (d_.irregularity.any()) {
    int slack = 0;
    for (const Dropper& dr : droppers_) slack += dr.tension < 0;
    s += fmt::format("; irregular ({} dropper(s) slack in the static state)", slack);
  }
  return s;
}

}  // namespace inerta::catenary
