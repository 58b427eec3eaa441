#include "inerta/mbs/dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/error.hpp"

namespace inerta::mbs {

namespace {
// Stages of `accelerations`; ws.set_state(x) has run.
void constraint_stage_3d(const Model& model, double t, Workspace& ws) {
  ConstraintRow3 rows[6];
  for (const Joint& jt : model.joints) {
    int nr = evaluate_joint_3d(jt, t, ws.sframe(jt.body_i), ws.sframe(jt.body_j), rows);
    for (int r = 0; r < nr; ++r) {
      const int row = jt.row + r;
      ws.C[row] = rows[r].C;
      ws.Ct[row] = rows[r].Ct;
      ws.gamma[row] = rows[r].gamma;
      if (jt.body_i >= 0) ws.Cq.block<1, 7>(row, 7 * jt.body_i) += rows[r].gi.transpose();
      if (jt.body_j >= 0) ws.Cq.block<1, 7>(row, 7 * jt.body_j) += rows[r].gj.transpose();
    }
  }
  // Euler-parameter normalisation pᵀp − 1 = 0: C_q = 2pᵀ, γ = −2ṗᵀṗ.
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const int row = model.norm_row(static_cast<int>(b));
    const SpatialFrame& f = ws.sframes[b];
    ws.C[row] = f.p.squaredNorm() - 1;
    ws.Ct[row] = 0;
    ws.gamma[row] = -2 * f.pd.squaredNorm();
    ws.Cq.block<1, 4>(row, 7 * static_cast<int>(b) + 3) = 2 * f.p.transpose();
  }
}

void constraint_stage(const Model& model, double t, Workspace& ws) {
  ws.Cq.setZero();
  if (model.spatial()) return constraint_stage_3d(model, t, ws);
  ConstraintRow rows[3];
  for (const Joint& jt : model.joints) {
    int nr = evaluate_joint(jt, t, ws.frame(jt.body_i), ws.frame(jt.body_j), rows);
    for (int r = 0; r < nr; ++r) {
      const int row = jt.row + r;
      ws.C[row] = rows[r].C;
      ws.Ct[row] = rows[r].Ct;
      ws.gamma[row] = rows[r].gamma;
      if (jt.body_i >= 0) ws.Cq.block<1, 3>(row, 3 * jt.body_i) += rows[r].gi.transpose();
      if (jt.body_j >= 0) ws.Cq.block<1, 3>(row, 3 * jt.body_j) += rows[r].gj.transpose();
    }
  }
}

// Spatial body with Euler parameters: T = ½ m Ṙ² + 2 ṗᵀ Gᵀ J̄ G ṗ, so M_pp = 4 Gᵀ J̄ G and the
// quadratic-velocity force Q_p = 8 Ġᵀ J̄ Ġ p (Ġ = G(ṗ)). Elimination of the normalisation rows
// 2pᵀp̈ = c_p (Baumgarte form): every joint row, force and M_pp is orthogonal to p (E p = G p = 0), so
// the p-direction decouples; M_pp + 2κ p pᵀ with Q_p projected orthogonal to p plus κ p c_p gives
// exactly the q̈ and joint multipliers of the full system, with a positive definite M and fewer rows.
double kappa(const Body& b) { return 2.0 * b.inertia3.trace() / 3.0; }

void spatial_masses(const Model& model, Workspace& ws) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const int k = 7 * static_cast<int>(b);
    const Body& body = model.bodies[b];
    const SpatialFrame& f = ws.sframes[b];
    ws.M.block<3, 3>(k, k).diagonal().setConstant(body.mass);
    const Mat34 G = G_matrix(f.p), Gd = G_matrix(f.pd);
    ws.M.block<4, 4>(k + 3, k + 3) = 4 * G.transpose() * body.inertia3 * G + 2 * kappa(body) * f.p * f.p.transpose();
    ws.llt_p[b].compute(ws.M.block<4, 4>(k + 3, k + 3));
    ws.Q.segment<4>(k + 3) += 8 * Gd.transpose() * (body.inertia3 * (Gd * f.p));
  }
}

void force_stage(const Model& model, double t, const State& x, Workspace& ws) {
  ws.M.setZero();
  ws.Q.setZero();
  ws.rank1.clear();
  if (model.spatial()) {
    spatial_masses(model, ws);
  } else {
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const int k = 3 * static_cast<int>(b);
      ws.M(k, k) = ws.M(k + 1, k + 1) = model.bodies[b].mass;
      ws.M(k + 2, k + 2) = model.bodies[b].inertia;
    }
  }
  for (const auto& f : model.forces) f->add(model, t, x, ws);
}
}  // namespace

void evaluate_constraints(const Model& model, double t, const State& x, Workspace& ws) {
  ws.set_state(x);
  constraint_stage(model, t, ws);
}

void evaluate_forces(const Model& model, double t, const State& x, Workspace& ws) {
  ws.set_state(x);
  force_stage(model, t, x, ws);
}

namespace {
[[noreturn]] void singular(double t, const char* what, double ratio) {
  throw NumericalError(
      fmt::format("t = {:.6g} s: {} is singular (pivot ratio {:.3g}); check for redundant joints, a body without "
                  "mass or inertia that is not constrained, or a mechanism in a singular position",
                  t, what, ratio));
}

// Full system of eq. 4.12 by LU with partial pivoting (used when M + M_I is not positive definite).
void solve_kkt(const Model& model, double t, Workspace& ws) {
  const int n = model.n_coords(), m = model.n_solved_rows();
  ws.K.topLeftCorner(n, n) = ws.M;
  ws.K.topRightCorner(n, m) = ws.Cq.topRows(m).transpose();
  ws.K.bottomLeftCorner(m, n) = ws.Cq.topRows(m);
  ws.K.bottomRightCorner(m, m).setZero();
  ws.rhs.head(n) = ws.Q;
  ws.rhs.tail(m) = ws.c.head(m);
  ws.lu.compute(ws.K);
  const auto diag = ws.lu.matrixLU().diagonal().cwiseAbs();
  const double pmax = diag.maxCoeff(), pmin = diag.minCoeff();
  if (!(pmin > 1e-13 * pmax)) singular(t, "the system matrix of eq. 4.12", pmax > 0 ? pmin / pmax : 0.0);
  ws.sol.noalias() = ws.lu.solve(ws.rhs);
  ws.qdd = ws.sol.head(n);
  ws.lambda = ws.sol.tail(m);
}
}  // namespace

namespace {
// Σ a_p b_p, p < n, in four independent sums (the short dot products of the Schur factorisation).
inline double dot4(const double* a, const double* b, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int p = 0;
  for (; p + 4 <= n; p += 4) s0 += a[p] * b[p], s1 += a[p + 1] * b[p + 1], s2 += a[p + 2] * b[p + 2], s3 += a[p + 3] * b[p + 3];
  for (; p < n; ++p) s0 += a[p] * b[p];
  return (s0 + s1) + (s2 + s3);
}

// M + M_I = D + Σ b_k J_kᵀ J_k with D block-diagonal (3D: m I and M_pp per body; 2D: diag(m, m, I)).
// The inerter terms become Schur rows of their own, μ_k = b_k J_k q̈ (eq. 3.33 read backwards):
//   [C_q; J] D⁻¹ [C_q; J]ᵀ [λ; μ] + diag(0, 1/b) [λ; μ] = [C_q; J] D⁻¹ Q − [c; 0],
//   q̈ = D⁻¹ (Q − C_qᵀ λ − Jᵀ μ),
// the same q̈ and λ as the dense solve without factorising the n×n matrix. D = L Lᵀ block by block,
// so the Schur matrix is YᵀY (+ the diagonal) with Y = L⁻¹ [C_qᵀ Jᵀ]. False: use the dense solve.
// B: coordinates a body (3 in 2D, 7 in 3D).
template <int B>
bool solve_blocks(const Model& model, double t, Workspace& ws) {
  const int nb = static_cast<int>(model.bodies.size()), m = model.n_solved_rows();
  const int r = static_cast<int>(ws.rank1.size()), k = m + r;
  if (k + 1 > ws.YB.cols()) return false;
  for (int b = 0; b < nb; ++b) {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (!(body.mass > 0)) return false;
    if constexpr (B == 7) {
      const auto d = ws.llt_p[static_cast<std::size_t>(b)].matrixLLT().diagonal();
      if (ws.llt_p[static_cast<std::size_t>(b)].info() != Eigen::Success || !(d.minCoeff() > 1e-7 * d.maxCoeff()))
        return false;
    } else {  // the dense solve's pivot test on L = diag(√m, √m, √I)
      if (!(body.inertia > 0) || !(std::sqrt(std::min(body.mass, body.inertia) / std::max(body.mass, body.inertia)) > 1e-7))
        return false;
    }
  }
  // Each row of [C_q; J] touches at most two bodies: Y is built, and every product below runs, over
  // those blocks only (the other blocks of Y are never read).
  for (int i = 0; i < r; ++i)
    ws.row_bodies[static_cast<std::size_t>(m + i)] = {ws.rank1[static_cast<std::size_t>(i)].body_i,
                                                      ws.rank1[static_cast<std::size_t>(i)].body_j};
  auto YZ = ws.YB.leftCols(k + 1);
  auto L_solve = [&](auto&& v, int b) {  // v (the block of body b) ← L_b⁻¹ v
    if constexpr (B == 7) {
      v.template head<3>() /= std::sqrt(model.bodies[static_cast<std::size_t>(b)].mass);
      ws.llt_p[static_cast<std::size_t>(b)].matrixL().solveInPlace(v.template tail<4>());
    } else {
      v = v.cwiseProduct(ws.inv_sqrt_d.template segment<3>(3 * b));
    }
  };
  for (int i = 0; i < k; ++i) {
    const Workspace::Rank1* R = i < m ? nullptr : &ws.rank1[static_cast<std::size_t>(i - m)];
    const auto& bodies = ws.row_bodies[static_cast<std::size_t>(i)];
    for (int e = 0; e < 2; ++e) {
      const int b = bodies[static_cast<std::size_t>(e)];
      if (b < 0) continue;
      auto v = YZ.col(i).template segment<B>(B * b);
      if (R)
        v = R->J.template segment<B>(B * e);
      else
        v = ws.Cq.row(i).template segment<B>(B * b).transpose();
      L_solve(v, b);
    }
  }
  YZ.col(k) = ws.Q;
  for (int b = 0; b < nb; ++b) L_solve(YZ.col(k).template segment<B>(B * b), b);
  const auto Y = YZ.leftCols(k);
  auto z = YZ.col(k);
  if (k > 0) {
    // S in ws.SB's storage as a row-major k × k lower triangle, factorised in place (S = L Lᵀ): at
    // this size a plain Cholesky beats the library's blocked one by its call overheads.
    double* S = ws.SB.data();
    auto at = [&](int i, int j) -> double& { return S[static_cast<std::ptrdiff_t>(i) * k + j]; };
    // S(i, j) = Σ over the bodies both rows touch of Y_ib · Y_jb: body by body over its rows (a
    // row touches at most two bodies, so most pairs share none and are never visited).
    for (int i = 0; i < k; ++i) std::fill(S + static_cast<std::ptrdiff_t>(i) * k, S + static_cast<std::ptrdiff_t>(i) * k + i + 1, 0.0);
    for (int i = m; i < k; ++i) {  // the inerter rows of this evaluation join their bodies' lists
      const auto& bi = ws.row_bodies[static_cast<std::size_t>(i)];
      if (bi[0] >= 0) ws.body_rows[static_cast<std::size_t>(bi[0])].push_back(i);
      if (bi[1] >= 0 && bi[1] != bi[0]) ws.body_rows[static_cast<std::size_t>(bi[1])].push_back(i);
    }
    for (int b = 0; b < nb; ++b) {
      const std::vector<int>& rows = ws.body_rows[static_cast<std::size_t>(b)];  // ascending
      for (std::size_t p = 0; p < rows.size(); ++p)
        for (std::size_t q = 0; q <= p; ++q)
          at(rows[p], rows[q]) += Y.col(rows[p]).template segment<B>(B * b).dot(Y.col(rows[q]).template segment<B>(B * b));
    }
    for (int b = 0; b < nb; ++b) {  // back to the joint rows only
      std::vector<int>& rows = ws.body_rows[static_cast<std::size_t>(b)];
      while (!rows.empty() && rows.back() >= m) rows.pop_back();
    }
    for (int i = 0; i < r; ++i) at(m + i, m + i) += 1.0 / ws.rank1[static_cast<std::size_t>(i)].b;
    // Right-looking: column j scaled, then the trailing triangle updated by the outer product of its
    // nonzero entries only (rows of a mechanism's joints couple few others: S is sparse, and the
    // zero products the dense update would add change nothing).
    double dmin = 0, dmax = 0;
    double* cj = ws.lm.data();  // scratch until the right-hand side is formed below
    int* nz = ws.column_nz.data();
    for (int j = 0; j < k; ++j) {
      double d = at(j, j);
      if (!(d > 0)) singular(t, "the constraint Jacobian C_q", 0.0);
      d = std::sqrt(d);
      at(j, j) = d;
      dmin = j == 0 ? d : std::min(dmin, d), dmax = std::max(dmax, d);
      const double inv = 1 / d;
      int cnt = 0;
      for (int i = j + 1; i < k; ++i)
        if (double& v = at(i, j); v != 0) cj[i] = v *= inv, nz[cnt++] = i;
      for (int a2 = 0; a2 < cnt; ++a2) {
        const int i = nz[a2];
        double* li = S + static_cast<std::ptrdiff_t>(i) * k;
        const double lij = cj[i];
        for (int b2 = 0; b2 <= a2; ++b2) li[nz[b2]] -= lij * cj[nz[b2]];
      }
    }
    if (!(dmin > 1e-7 * dmax)) singular(t, "the constraint Jacobian C_q", dmax > 0 ? std::pow(dmin / dmax, 2) : 0.0);
    auto lm = ws.lm.head(k);
    for (int i = 0; i < k; ++i) {
      double s = 0;
      for (int b : ws.row_bodies[static_cast<std::size_t>(i)])
        if (b >= 0) s += Y.col(i).template segment<B>(B * b).dot(z.template segment<B>(B * b));
      lm[i] = s;
    }
    lm.head(m) -= ws.c.head(m);
    for (int i = 0; i < k; ++i) {  // L y = b, then Lᵀ x = y
      lm[i] = (lm[i] - dot4(S + static_cast<std::ptrdiff_t>(i) * k, lm.data(), i)) / at(i, i);
    }
    for (int i = k - 1; i >= 0; --i) {
      double v = lm[i];
      for (int p = i + 1; p < k; ++p) v -= at(p, i) * lm[p];
      lm[i] = v / at(i, i);
    }
    for (int i = 0; i < k; ++i)
      for (int b : ws.row_bodies[static_cast<std::size_t>(i)])
        if (b >= 0) z.template segment<B>(B * b) -= Y.col(i).template segment<B>(B * b) * lm[i];
    ws.lambda = lm.head(m);
  }
  ws.qdd = z;
  for (int b = 0; b < nb; ++b) {
    if constexpr (B == 7) {
      ws.qdd.template segment<3>(7 * b) /= std::sqrt(model.bodies[static_cast<std::size_t>(b)].mass);
      ws.llt_p[static_cast<std::size_t>(b)].matrixU().solveInPlace(ws.qdd.template segment<4>(7 * b + 3));
    } else {
      ws.qdd.template segment<3>(3 * b) = ws.qdd.template segment<3>(3 * b).cwiseProduct(ws.inv_sqrt_d.template segment<3>(3 * b));
    }
  }
  return true;
}
}  // namespace

void accelerations(const Model& model, double t, const State& x, Workspace& ws) {
  // Stages: kinematics → force elements and inerter mass term → constraint terms → Baumgarte → solve.
  ws.set_state(x);
  force_stage(model, t, x, ws);
  constraint_stage(model, t, ws);
  // Baumgarte, eq. 4.11: C_q q̈ = Q_d − 2α Ċ − β² C, with Ċ = C_q q̇ + C_t.
  const double a = model.options.alpha, b = model.options.beta;
  ws.c.noalias() = ws.gamma - 2 * a * ws.Ct - b * b * ws.C;
  if (model.spatial()) {
    ws.c.noalias() -= 2 * a * (ws.Cq * x.qd);
  } else if (a != 0) {  // a row of C_q touches at most its joint's two bodies
    for (int i = 0; i < static_cast<int>(ws.c.size()); ++i) {
      double s = 0;
      for (int body : ws.row_bodies[static_cast<std::size_t>(i)])
        if (body >= 0) s += ws.Cq.row(i).segment<3>(3 * body).dot(x.qd.segment<3>(3 * body));
      ws.c[i] -= 2 * a * s;
    }
  }
  if (model.spatial())  // the normalisation rows, eliminated (spatial_masses)
    for (std::size_t k = 0; k < model.bodies.size(); ++k) {
      const SpatialFrame& f = ws.sframes[k];
      auto Qp = ws.Q.segment<4>(7 * static_cast<int>(k) + 3);
      Qp -= f.p * (f.p.dot(Qp) / f.p.squaredNorm());
      Qp += kappa(model.bodies[k]) * f.p * ws.c[model.norm_row(static_cast<int>(k))];
    }
  const int m = model.n_solved_rows();
  if (model.spatial() ? solve_blocks<7>(model, t, ws) : solve_blocks<3>(model, t, ws)) return;

  // Schur complement: (M + M_I) = L Lᵀ, S = C_q (M + M_I)⁻¹ C_qᵀ, S λ = C_q (M + M_I)⁻¹ Q − c,
  // q̈ = (M + M_I)⁻¹ (Q − C_qᵀ λ).
  ws.llt_M.compute(ws.M);
  const auto dM = ws.llt_M.matrixLLT().diagonal();
  if (ws.llt_M.info() != Eigen::Success || !(dM.minCoeff() > 1e-7 * dM.maxCoeff())) {
    solve_kkt(model, t, ws);
    return;
  }
  // One triangular solve for [Y z] = L⁻¹ [C_qᵀ Q].
  ws.YZ.leftCols(m) = ws.Cq.topRows(m).transpose();
  ws.YZ.col(m) = ws.Q;
  ws.llt_M.matrixL().solveInPlace(ws.YZ);
  const auto Y = ws.YZ.leftCols(m);
  auto z = ws.YZ.col(m);
  if (m > 0) {
    ws.S.noalias() = Y.transpose().lazyProduct(Y);  // coefficient-based: faster than GEMM at this size
    ws.llt_S.compute(ws.S);
    const auto dS = ws.llt_S.matrixLLT().diagonal();
    if (ws.llt_S.info() != Eigen::Success) singular(t, "the constraint Jacobian C_q", 0.0);
    if (!(dS.minCoeff() > 1e-7 * dS.maxCoeff()))
      singular(t, "the constraint Jacobian C_q", dS.maxCoeff() > 0 ? std::pow(dS.minCoeff() / dS.maxCoeff(), 2) : 0.0);
    ws.lambda.noalias() = Y.transpose() * z;
    ws.lambda -= ws.c.head(m);
    ws.llt_S.solveInPlace(ws.lambda);
    z.noalias() -= Y * ws.lambda;
  }
  ws.qdd = z;
  ws.llt_M.matrixU().solveInPlace(ws.qdd);
}

Vec3 joint_reaction(const Model& model, int joint, double t, const State& x, const Eigen::VectorXd& lambda) {
  const Joint& jt = model.joints[static_cast<std::size_t>(joint)];
  if (model.spatial()) {  // force on body j: −(C_q,R_j)ᵀ λ
    ConstraintRow3 rows[6];
    int nr = evaluate_joint_3d(jt, t, model.sframe(x, jt.body_i), model.sframe(x, jt.body_j), rows);
    Vec3 f = Vec3::Zero();
    for (int r = 0; r < nr; ++r) f -= rows[r].gj.head<3>() * lambda[jt.row + r];
    return f;
  }
  ConstraintRow rows[3];
  int nr = evaluate_joint(jt, t, model.frame(x, jt.body_i), model.frame(x, jt.body_j), rows);
  Vec3 f = Vec3::Zero();
  for (int r = 0; r < nr; ++r) f -= rows[r].gj * lambda[jt.row + r];
  return f;
}

double kinetic_energy(const Model& model, const State& x) {
  double T = 0;
  if (model.spatial()) {
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const SpatialFrame f = model.sframe(x, static_cast<int>(b));
      const Vec3 wb = 2 * G_matrix(f.p) * f.pd;  // body-frame angular velocity
      T += 0.5 * model.bodies[b].mass * f.Rd.squaredNorm() + 0.5 * wb.dot(model.bodies[b].inertia3 * wb);
    }
    return T;
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    Vec3 v = model.qd_of(x, static_cast<int>(b));
    T += 0.5 * model.bodies[b].mass * v.head<2>().squaredNorm() + 0.5 * model.bodies[b].inertia * v.z() * v.z();
  }
  return T;
}

double stored_energy(const Model& model, double t, const State& x) {
  double E = 0;
  for (const auto& f : model.forces) E += f->energy(model, t, x);
  return E;
}

double element_power(const Model& model, double t, const State& x) {
  double P = 0;
  for (const auto& f : model.forces) P += f->power(model, t, x);
  return P;
}

}  // namespace inerta::mbs
