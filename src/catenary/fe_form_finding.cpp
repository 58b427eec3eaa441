// Pass 5 of compiling a line (fe_compile.hpp): the form-finding (fe_line.hpp's header, spec/05 §5.3).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "fe_compile.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary::compile {

namespace {

// The height-error profile at x (linear between its points; validate() has checked it covers the line).
double height_error_at(const FeIrregularity& irr, double x) {
  const std::vector<double>& X = irr.height_error_x;
  const auto it = std::upper_bound(X.begin(), X.end(), x);
  const std::size_t i = std::min<std::size_t>(X.size() - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - X.begin())));
  const double t = (x - X[i - 1]) / (X[i] - X[i - 1]);
  return irr.height_error_dz[i - 1] + t * (irr.height_error_dz[i] - irr.height_error_dz[i - 1]);
}

Eigen::SparseMatrix<double> sparse(const Triplets& t, int n) {
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

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

}  // namespace

FormFound form_find(const FeCatenaryData& d, const Mesh& mesh, const Wires& wr, const std::vector<double>& presag,
                    std::vector<FeLine::Dropper>& droppers) {
  FormFound out;
  const int N = static_cast<int>(mesh.x.size()), n_dofs = mesh.n_dofs;
  const FeIrregularity& irr = d.irregularity;
  const int nd = static_cast<int>(droppers.size()), nm = static_cast<int>(mesh.mast_nodes.size());
  const int ne = static_cast<int>(mesh.end_nodes.size());
  // A tension section's heights (FeCatenaryData::height_at): w is taken from the straight line g
  // between the two anchors' heights (a linear g loads no interior DOF of a tensioned beam), the
  // masts' and droppers' targets relative to it.
  const double length = d.span * d.spans;
  out.heights = !d.height_x.empty() || !d.mast_height.empty();
  out.g_a = d.height_at(0), out.g_slope = (d.height_at(length) - out.g_a) / length;
  auto g_of = [&](double x) { return out.g_a + out.g_slope * x; };
  // Each wire alone: unit diagonal on the other wire's DOFs; the stitch wires' own DOFs belong to the
  // upper structure.
  Triplets alone[2] = {wr.k[0], wr.k[1]};
  for (int i = 0; i < N; ++i)
    for (int c = 0; c < 2; ++c)
      for (int w = 0; w < 2; ++w)
        if (mesh.at(1 - w, i, c) >= 0) alone[w].emplace_back(mesh.at(1 - w, i, c), mesh.at(1 - w, i, c), 1.0);
  for (int i = 0; i < N; ++i)
    for (int c = 0; c < 2; ++c)
      if (const int k = mesh.at(2, i, c); k >= 0 && !(c == 0 && mesh.on_stitch[static_cast<std::size_t>(i)] == 2))
        alone[1].emplace_back(k, k, 1.0);

  // Unknown upward forces on the contact wire — dropper tensions T_d at the droppers and registration
  // forces at the masts — such that w_c = −presag (+ the height error) at the droppers and 0 at the
  // masts; then the upper structure (messenger and stitch wires, the stitch's ends on the messenger)
  // under its weight and the dropper tensions, with w_m = 0 at the masts. The droppers' own weight
  // depends on their length: iterate (converges in a few passes).
  std::vector<int> cdofs, mdofs;  // constrained w DOFs: contact wire at droppers then masts; messenger at masts
  for (const FeLine::Dropper& dr : droppers) cdofs.push_back(dr.dof_c);
  for (int n : mesh.mast_nodes) cdofs.push_back(mesh.at(1, n, 0)), mdofs.push_back(mesh.at(0, n, 0));
  for (int n : mesh.end_nodes) cdofs.push_back(mesh.at(1, n, 0)), mdofs.push_back(mesh.at(0, n, 0));
  const Constrained con_c(sparse(alone[1], n_dofs), cdofs), con_m(sparse(alone[0], n_dofs), mdofs);
  if (con_c.llt.info() != Eigen::Success || con_m.llt.info() != Eigen::Success)
    throw NumericalError("finite-element catenary: the wire stiffness matrix is singular (check tensions)");
  Eigen::VectorXd target = Eigen::VectorXd::Zero(nd + nm + ne);
  for (int k = 0; k < nd; ++k) target[k] = -presag[static_cast<std::size_t>(k)];
  Eigen::VectorXd zero_m = Eigen::VectorXd::Zero(nm + ne);
  if (out.heights) {
    for (int k = 0; k < nd; ++k) {
      const double x = droppers[static_cast<std::size_t>(k)].x;
      target[k] += d.height_at(x) - g_of(x);
    }
    for (int j = 0; j < nm; ++j) {
      const double x = mesh.x[static_cast<std::size_t>(mesh.mast_nodes[static_cast<std::size_t>(j)])];
      target[nd + j] = zero_m[j] = d.height_at(x) - g_of(x);
    }
  }
  const Eigen::VectorXd design_target = target;
  if (!irr.height_error_x.empty())  // installation error: added to the target heights at the droppers
    for (int k = 0; k < nd; ++k) target[k] += height_error_at(irr, droppers[static_cast<std::size_t>(k)].x);
  // The straight line g as DOF values (w: g(x), θ: its slope) and the forces K g of each wire on
  // it: zero inside a wire, but not where a stitch wire ends on the messenger (T_s g′ at its clamps).
  Eigen::VectorXd kg[2];
  if (out.heights) {
    out.g_dofs = Eigen::VectorXd::Zero(n_dofs);
    for (int i = 0; i < N; ++i)
      for (int w = 0; w < FeLine::kWires; ++w) {
        if (const int k = mesh.at(w, i, 0); k >= 0) out.g_dofs[k] = g_of(mesh.x[static_cast<std::size_t>(i)]);
        if (const int k = mesh.at(w, i, 1); k >= 0) out.g_dofs[k] = out.g_slope;
      }
    for (int w = 0; w < 2; ++w) kg[w] = sparse(wr.k[w], n_dofs) * out.g_dofs;
    // A pinned anchor's w is no unknown, but g there (its height) acts on its element's free DOFs
    // too: without it K g is not zero next to an anchor above 0, and the wire's first element is
    // pulled towards 0 (the incoming section of an overlap, its anchor raised).
    if (d.anchor.pinned) {
      out.g_anchor_force = Eigen::VectorXd::Zero(n_dofs);
      const FeWire* wire[2] = {&d.messenger, &d.contact_wire};
      for (int w = 0; w < 2; ++w)
        for (const auto& [e, b] : {std::pair{0, 0}, std::pair{N - 2, 2}}) {  // (element, the anchor's local w): node 0, node N − 1
          const Eigen::Matrix4d ke = beam_stiffness(wr.EI[w][static_cast<std::size_t>(e)], wire[w]->tension,
                                                    mesh.x[static_cast<std::size_t>(e) + 1] - mesh.x[static_cast<std::size_t>(e)]);
          const std::array<int, 4> dd{mesh.at(w, e, 0), mesh.at(w, e, 1), mesh.at(w, e + 1, 0), mesh.at(w, e + 1, 1)};
          if (dd[b] >= 0) continue;
          const double gb = g_of(mesh.x[static_cast<std::size_t>(e + b / 2)]);
          for (int a = 0; a < 4; ++a)
            if (dd[a] >= 0) kg[w][dd[a]] += ke(a, b) * gb, out.g_anchor_force[dd[a]] += ke(a, b) * gb;
        }
    }
  }
  // The form-finding at the contact-wire targets `tgt`: stretched dropper lengths, wire heights and
  // dropper tensions.
  auto solve = [&](const Eigen::VectorXd& tgt, std::vector<double>& len, Eigen::VectorXd& wc, Eigen::VectorXd& wm,
                   Eigen::VectorXd& T) {
    len.assign(static_cast<std::size_t>(nd), d.encumbrance);
    for (int pass = 0; pass < 20; ++pass) {
      Eigen::VectorXd fc = wr.fg[1], fm = wr.fg[0];
      if (out.heights) fc -= kg[1], fm -= kg[0];
      for (int k = 0; k < nd; ++k) {
        const FeLine::Dropper& dr = droppers[static_cast<std::size_t>(k)];
        const double half = 0.5 * dr.mass_per_length * len[static_cast<std::size_t>(k)] * d.gravity;
        fc[dr.dof_c] -= dr.clamp_contact * d.gravity + half;
        fm[dr.dof_m] -= dr.clamp_upper * d.gravity + half;
      }
      Eigen::VectorXd z;
      std::tie(wc, z) = con_c.solve(fc, tgt);
      T = z.head(nd);  // dropper tensions (then the registration forces)
      for (int k = 0; k < nd; ++k) fm[droppers[static_cast<std::size_t>(k)].dof_m] -= T[k];
      wm = con_m.solve(fm, zero_m).first;
      double change = 0;
      for (int k = 0; k < nd; ++k) {
        const FeLine::Dropper& dr = droppers[static_cast<std::size_t>(k)];
        const double l = d.encumbrance + wm[dr.dof_m] - wc[dr.dof_c];
        change = std::max(change, std::abs(l - len[static_cast<std::size_t>(k)]));
        len[static_cast<std::size_t>(k)] = l;
      }
      if (change < 1e-12) break;
    }
  };
  Eigen::VectorXd T;
  solve(target, out.stretched, out.wc, out.wm, T);
  for (int k = 0; k < nd; ++k) {
    FeLine::Dropper& dr = droppers[static_cast<std::size_t>(k)];
    dr.tension = T[k];
    const double stretched = out.stretched[static_cast<std::size_t>(k)];
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
  out.design_length.resize(static_cast<std::size_t>(nd));
  for (int k = 0; k < nd; ++k) out.design_length[static_cast<std::size_t>(k)] = droppers[static_cast<std::size_t>(k)].length;
  if (!irr.height_error_x.empty()) {
    std::vector<double> dlen;
    Eigen::VectorXd dwc, dwm, dT;
    solve(design_target, dlen, dwc, dwm, dT);
    for (int k = 0; k < nd; ++k)
      out.design_length[static_cast<std::size_t>(k)] =
          dlen[static_cast<std::size_t>(k)] / (1 + dT[k] / droppers[static_cast<std::size_t>(k)].EA);
  }
  return out;
}

}  // namespace inerta::catenary::compile
