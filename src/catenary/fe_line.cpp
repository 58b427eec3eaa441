// The finite-element line (catenary/fe_line.hpp, spec/05 §5.3): the pipeline of its compile passes
// (fe_compile.hpp), the shape functions and the statics of the compiled line.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "fe_compile.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/phase_times.hpp"

namespace inerta::catenary {

namespace {

// Hermite cubics and their x-derivatives at ξ ∈ [0, 1] on an element of length l.
void hermite(double xi, double l, std::array<double, 4>& N, std::array<double, 4>& dN) {
  const double x2 = xi * xi, x3 = x2 * xi;
  N = {1 - 3 * x2 + 2 * x3, l * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, l * (-x2 + x3)};
  dN = {(-6 * xi + 6 * x2) / l, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / l, -2 * xi + 3 * x2};
}

}  // namespace

int FeLine::dof(int wire, int node, int c) const {
  return dof_[static_cast<std::size_t>((node * kWires + wire) * 2 + c)];
}

double FeLine::stitch_height(int node) const { return stitch_y_[static_cast<std::size_t>(node)]; }

// The pipeline of passes that compiles the data into the line (fe_compile.hpp).
FeLine::FeLine(FeCatenaryData data) : d_(std::move(data)) {
  const numerics::PhaseTimer timer("line: mesh, form-finding, matrices");
  d_.validate();
  compile::Mesh mesh = compile::mesh(d_);
  compile::Wires wires = compile::wires(d_, mesh);
  compile::stitch_wires(d_, mesh, wires);
  std::vector<double> presag;
  droppers_ = compile::droppers(d_, mesh, presag);
  for (int n : mesh.mast_nodes) support_x_.push_back(mesh.x[static_cast<std::size_t>(n)]), support_dofs_.push_back(mesh.at(1, n, 0));
  x_ = mesh.x, dof_ = mesh.dof, n_dofs_ = mesh.n_dofs;
  const compile::FormFound ff = compile::form_find(d_, mesh, wires, presag, droppers_);
  g_dofs_ = ff.g_dofs, g_anchor_force_ = ff.g_anchor_force;
  const compile::Irregular irr =
      compile::irregularities(d_, n_dofs_, ff.stretched, [this](double x) { return contact_shape(x); }, droppers_);
  assemble(wires, ff, irr);
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
  if (d_.wear.any())
    s += d_.wear.x.empty() ? fmt::format("; contact wire worn to {:g} % of its section", d_.wear.uniform)
                           : fmt::format("; contact wire worn as {} gives ({} points)", d_.wear.file, d_.wear.x.size());
  if (d_.irregularity.any()) {
    int slack = 0;
    for (const Dropper& dr : droppers_) slack += dr.tension < 0;
    s += fmt::format("; irregular ({} dropper(s) slack in the static state)", slack);
  }
  return s;
}

}  // namespace inerta::catenary
