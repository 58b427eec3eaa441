#include "inerta/mbs/linearisation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "inerta/mbs/dynamics.hpp"
#include "inerta/numerics/finite_difference.hpp"

namespace inerta::mbs {

LinearModel linearise(const Model& model, const State& x, double t) {
  const int n = model.n_coords(), nz = model.n_states();
  Workspace ws(model);
  LinearModel L;
  L.equilibrium = x;
  L.t = t;
  evaluate_constraints(model, t, x, ws);
  if (model.n_constraints() > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(ws.Cq, Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    int rank = 0;
    for (int i = 0; i < sv.size(); ++i) rank += sv[i] > 1e-10 * std::max(1.0, sv[0]);
    L.N = svd.matrixV().rightCols(n - rank);
  } else {
    L.N = Eigen::MatrixXd::Identity(n, n);
  }
  const int d = static_cast<int>(L.N.cols());
  L.dof = d, L.nz = nz;
  const int S = 2 * d + nz;
  auto g = [&](const Eigen::VectorXd& X) {
    State s{x.q + L.N * X.head(d), L.N * X.segment(d, d), x.z + X.tail(nz)};
    accelerations(model, t, s, ws);
    Eigen::VectorXd out(S);
    out << X.segment(d, d), L.N.transpose() * ws.qdd, ws.zd;
    return out;
  };
  // A = ∂g/∂X at X = 0; absolute step 1e-6 (X is a perturbation about the equilibrium).
  L.A = numerics::central_difference_jacobian(g, Eigen::VectorXd::Zero(S), 1e-6, numerics::Step::Absolute);
  evaluate_forces(model, t, x, ws);
  L.M = L.N.transpose() * ws.M * L.N;
  L.K = -L.M * L.A.block(d, 0, d, d);
  L.C = -L.M * L.A.block(d, d, d, d);
  return L;
}

std::vector<Mode> modes(const Model& model, const LinearModel& L) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(L.A);
  std::vector<Mode> out;
  const int d = L.dof;
  for (int i = 0; i < L.A.rows(); ++i) {
    const std::complex<double> lam = es.eigenvalues()[i];
    if (std::abs(lam) < 1e-6 || lam.imag() < -1e-9) continue;  // neutral, or the conjugate twin
    Mode m;
    m.eigenvalue = lam;
    m.frequency_hz = std::abs(lam) / (2 * std::numbers::pi);
    m.damping_ratio = -lam.real() / std::abs(lam);
    Eigen::VectorXcd v = es.eigenvectors().col(i);
    Eigen::VectorXcd q = L.N.cast<std::complex<double>>() * v.head(d);
    // Rotate so that the largest component is real, then keep the real part.
    Eigen::Index kmax = 0;
    q.cwiseAbs().maxCoeff(&kmax);
    if (std::abs(q[kmax]) < 1e-14) continue;  // an internal-state mode that does not move the bodies
    q /= q[kmax];
    m.shape = q.real();
    std::vector<std::pair<double, int>> big;
    for (int k = 0; k < m.shape.size(); ++k) big.push_back({std::abs(m.shape[k]), k});
    std::sort(big.begin(), big.end(), [](auto a, auto b) { return a.first > b.first; });
    for (std::size_t j = 0; j < std::min<std::size_t>(3, big.size()); ++j) {
      if (j > 0 && big[j].first < 0.2) break;
      m.description += fmt::format("{}{} {:.0f} %", j ? ", " : "", model.coord_name(big[j].second), 100 * big[j].first);
    }
    out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
  return out;
}

}  // namespace inerta::mbs
