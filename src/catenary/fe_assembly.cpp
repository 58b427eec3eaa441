// Pass 7 of compiling a line (fe_compile.hpp): the whole line — both wires, the droppers taut, their
// and the clamps' masses, the point masses — and its static state.
#include "fe_compile.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary {

void FeLine::assemble(const compile::Wires& w, const compile::FormFound& ff, const compile::Irregular& irr) {
  using compile::Triplets;
  auto sparse = [&](const Triplets& t) {
    Eigen::SparseMatrix<double> a(n_dofs_, n_dofs_);
    a.setFromTriplets(t.begin(), t.end());
    return a;
  };
  Triplets K = w.k[0], Mt = w.m[0];
  K.insert(K.end(), w.k[1].begin(), w.k[1].end());
  Mt.insert(Mt.end(), w.m[1].begin(), w.m[1].end());
  K_wires_ = sparse(K);
  f_gravity_ = w.fg[0] + w.fg[1];
  const bool design_dynamics = !d_.irregularity.exact_dropper_dynamics;
  Triplets Ks = K;
  for (std::size_t k = 0; k < droppers_.size(); ++k) {
    Dropper& dr = droppers_[k];
    const double Ld = design_dynamics ? ff.design_length[k] : dr.length;
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
    const double carried = 0.5 * dr.mass_per_length * (ff.stretched[k] + irr.delta[k]);
    f_gravity_[dr.dof_m] -= (carried + dr.clamp_upper) * d_.gravity;
    f_gravity_[dr.dof_c] -= (carried + dr.clamp_contact) * d_.gravity;
  }
  for (const FeIrregularity::PointMass& pm : d_.irregularity.point_masses) {
    const Shape sh = contact_shape(pm.x);
    for (int a = 0; a < 4; ++a)
      if (sh.dofs[a] >= 0) f_gravity_[sh.dofs[a]] -= pm.mass * d_.gravity * sh.N[a];
  }
  Mt.insert(Mt.end(), irr.point_mass.begin(), irr.point_mass.end());
  K_ = sparse(K);
  K_static_ = sparse(Ks);
  M_ = sparse(Mt);
  C_ = d_.rayleigh_mass * M_ + d_.rayleigh_stiffness * K_;
  K_llt_.compute(K_static_);
  if (K_llt_.info() != Eigen::Success) throw NumericalError("finite-element catenary: K is not positive definite");
  w_static_ = ff.wc + ff.wm;
  if (irr.any) {
    const Eigen::VectorXd u = K_llt_.solve(irr.f);
    w_static_ += u;
    for (Dropper& dr : droppers_) dr.tension += dr.static_stiffness * (u[dr.dof_m] - u[dr.dof_c]);
  }
  // The heights at the stations, from the straight line between the anchors (FormFound::g_a).
  const int N = n_nodes();
  y_contact_.resize(static_cast<std::size_t>(N));
  s_contact_.resize(static_cast<std::size_t>(N));
  messenger_y_.resize(static_cast<std::size_t>(N));
  stitch_y_.assign(static_cast<std::size_t>(N), NAN);
  for (int i = 0; i < N; ++i) {
    const std::size_t n = static_cast<std::size_t>(i);
    const int dw = dof(1, i, 0), dt = dof(1, i, 1), mw = dof(0, i, 0), sw = dof(2, i, 0);
    y_contact_[n] = dw >= 0 ? w_static_[dw] : 0.0;
    s_contact_[n] = dt >= 0 ? w_static_[dt] : 0.0;
    messenger_y_[n] = d_.encumbrance + (mw >= 0 ? w_static_[mw] : 0.0);
    if (sw >= 0) stitch_y_[n] = d_.encumbrance + w_static_[sw];
    if (ff.heights) {
      const double g = ff.g_a + ff.g_slope * x_[n];
      y_contact_[n] += g, s_contact_[n] += ff.g_slope;
      messenger_y_[n] += g;
      if (sw >= 0) stitch_y_[n] += g;
    }
  }
}

}  // namespace inerta::catenary
