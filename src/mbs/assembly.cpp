#include "inerta/mbs/assembly.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/numerics/finite_difference.hpp"

namespace inerta::mbs {

namespace {
int argmax_abs(const Eigen::VectorXd& v) {
  Eigen::Index k = 0;
  if (v.size() > 0) v.cwiseAbs().maxCoeff(&k);
  return static_cast<int>(k);
}
}  // namespace

State assemble(const Model& model, double t0, AssemblyReport* report) {
  const int n = model.n_coords(), m = model.n_constraints();
  State x{model.q0(), model.qd0(), Eigen::VectorXd::Zero(model.n_states())};
  Workspace ws(model);
  std::vector<int> free;
  for (int k = 0; k < n; ++k)
    if (std::find(model.held.begin(), model.held.end(), k) == model.held.end()) free.push_back(k);
  const int nf = static_cast<int>(free.size());

  AssemblyReport rep;
  const double tol = 1e-12;
  const int max_iter = 50;
  evaluate_constraints(model, t0, x, ws);
  rep.initial_residual = m ? ws.C.cwiseAbs().maxCoeff() : 0.0;
  Eigen::MatrixXd Jf(m, nf);
  for (int it = 0; m > 0; ++it) {
    evaluate_constraints(model, t0, x, ws);
    rep.residual = ws.C.cwiseAbs().maxCoeff();
    if (rep.residual < tol) break;
    if (it == max_iter || !std::isfinite(rep.residual)) {
      int r = argmax_abs(ws.C);
      throw NumericalError(
          fmt::format("assembly did not converge after {} Newton iterations: max |C| = {:.3g} in {}; "
                      "the tabulated positions may be too far from a configuration that satisfies the joints, "
                      "or the held coordinates over-constrain the mechanism",
                      it, rep.residual, model.constraint_name(r)));
    }
    for (int c = 0; c < nf; ++c) Jf.col(c) = ws.Cq.col(free[static_cast<std::size_t>(c)]);
    Eigen::VectorXd step = Jf.completeOrthogonalDecomposition().solve(-ws.C);  // minimum-norm step
    for (int c = 0; c < nf; ++c) x.q[free[static_cast<std::size_t>(c)]] += step[c];
    rep.iterations = it + 1;
  }
  rep.dq = x.q - model.q0();
  rep.largest = argmax_abs(rep.dq);

  consistent_velocities(model, t0, x);
  if (report) *report = rep;
  return x;
}

void consistent_velocities(const Model& model, double t, State& x) {
  if (model.n_constraints() == 0) return;
  // C_q q̇ + C_t = 0 (eq. 4.2), minimum-norm change of q̇.
  Workspace ws(model);
  evaluate_constraints(model, t, x, ws);
  const Eigen::VectorXd vres = ws.Cq * x.qd + ws.Ct;
  x.qd -= ws.Cq.completeOrthogonalDecomposition().solve(vres);
}

void static_equilibrium(const Model& model, double t0, State& x, EquilibriumReport* report) {
  const int n = model.n_coords(), m = model.n_constraints(), N = n + m;
  Workspace ws(model);
  x.qd.setZero();
  const Eigen::VectorXd q_start = x.q;

  // Residual R(q, λ) = [Q(q) − C_qᵀ λ; C(q)], internal states relaxed for q.
  auto at_rest = [&](const Eigen::VectorXd& q) {
    State s{q, x.qd, Eigen::VectorXd::Zero(model.n_states())};
    for (const auto& f : model.forces) f->relax(model, s);
    return s;
  };
  auto residual = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, Eigen::VectorXd& R) {
    State s = at_rest(q);
    evaluate_forces(model, t0, s, ws);
    evaluate_constraints(model, t0, s, ws);
    R.head(n) = ws.Q - ws.Cq.transpose() * lambda;
    R.tail(m) = ws.C;
  };

  // Initial multipliers: least squares of C_qᵀ λ = Q.
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  {
    State s = at_rest(x.q);
    evaluate_forces(model, t0, s, ws);
    evaluate_constraints(model, t0, s, ws);
    if (m > 0) lambda = ws.Cq.transpose().completeOrthogonalDecomposition().solve(ws.Q);
  }
  double fscale = 1.0;
  for (const Body& b : model.bodies) fscale = std::max(fscale, b.mass * model.options.g.norm());
  fscale = std::max(fscale, ws.Q.cwiseAbs().maxCoeff());

  Eigen::VectorXd R(N), Rp(N), Rtrial(N);
  Eigen::MatrixXd J(N, N);
  EquilibriumReport rep;
  const int max_iter = 100;
  auto norm = [&](const Eigen::VectorXd& r) {
    return std::max(r.head(n).cwiseAbs().maxCoeff() / fscale, m ? r.tail(m).cwiseAbs().maxCoeff() : 0.0);
  };
  for (int it = 0;; ++it) {
    residual(x.q, lambda, R);
    rep.force_residual = R.head(n).cwiseAbs().maxCoeff();
    double Rn = norm(R);
    if (Rn < 1e-11) break;
    if (it == max_iter || !std::isfinite(Rn)) {
      int k = argmax_abs(R.head(n));
      throw NumericalError(
          fmt::format("static equilibrium did not converge after {} iterations: residual force {:.3g} on {}; "
                      "the model may have no stable equilibrium near the assembled configuration "
                      "(a free mechanism, or loads that cannot be balanced)",
                      it, rep.force_residual, model.coord_name(k)));
    }
    // Jacobian: central differences in q, analytic −C_qᵀ in λ.
    // Step 1e-6 · max(1, |q_k|).
    numerics::central_difference_jacobian(
        [&](const Eigen::VectorXd& q) {
          residual(q, lambda, Rp);
          return Rp;
        },
        x.q, 1e-6, numerics::Step::Relative, J.leftCols(n));
    {
      State s = at_rest(x.q);
      evaluate_constraints(model, t0, s, ws);
      J.block(0, n, n, m) = -ws.Cq.transpose();
      J.block(n, n, m, m).setZero();
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
    if (qr.rank() < N) {
      throw NumericalError(
          fmt::format("static equilibrium: the stiffness matrix is singular at the assembled configuration "
                      "(rank {} of {}); a coordinate has no stiffness (free mechanism) or the joints are redundant",
                      qr.rank(), N));
    }
    Eigen::VectorXd dz = qr.solve(-R);
    // Backtracking line search on the scaled residual.
    double s = 1.0;
    for (int ls = 0; ls < 30; ++ls, s *= 0.5) {
      residual(x.q + s * dz.head(n), lambda + s * dz.tail(m), Rtrial);
      if (norm(Rtrial) < Rn) break;
    }
    x.q += s * dz.head(n);
    lambda += s * dz.tail(m);
    rep.iterations = it + 1;
  }
  x = at_rest(x.q);
  Eigen::VectorXd move = x.q - q_start;
  rep.largest = argmax_abs(move);
  rep.max_move = n ? move.cwiseAbs().maxCoeff() : 0.0;
  if (report) *report = rep;
}

}  // namespace inerta::mbs
