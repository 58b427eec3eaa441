#include "inerta/numerics/floquet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <unsupported/Eigen/MatrixFunctions>

#include "inerta/error.hpp"

namespace inerta::numerics {

namespace {

void check_arguments(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double T, int steps) {
  if (A.cols() != A.rows() || b.size() != A.rows())
    throw InvalidArgument(fmt::format("floquet: A is {}×{} and b has {} rows (expected a square A and b of its size)",
                                      A.rows(), A.cols(), b.size()));
  if (!(T > 0) || !std::isfinite(T)) throw InvalidArgument(fmt::format("floquet: the period must be > 0, got {}", T));
  if (steps < 8) throw InvalidArgument(fmt::format("floquet: at least 8 steps per period, got {}", steps));
}

// φ(σ) = (e^σ − 1)/σ, so that e^{h b r} = I + h φ(h r b) b r.
template <typename S>
S phi(S s) {
  return std::abs(s) < 1e-8 ? S(1) + S(0.5) * s : (std::exp(s) - S(1)) / s;
}

Eigen::RowVectorXd row_at(const std::function<Eigen::RowVectorXd(double)>& r, double t, Eigen::Index n) {
  Eigen::RowVectorXd rk = r(t);
  if (rk.size() != n) throw InvalidArgument(fmt::format("floquet: r(t) has {} columns, expected {}", rk.size(), n));
  return rk;
}

}  // namespace

Eigen::MatrixXd monodromy(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps) {
  check_arguments(A, b, T, steps);
  const Eigen::Index n = A.rows();
  const double h = T / steps;
  // In the eigenbasis A = V Λ V⁻¹ every e^{hA/2} is diagonal and a step costs O(n²) instead of O(n³);
  // a defective or ill-conditioned V falls back to the dense form.
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() == Eigen::Success) {
    using cd = std::complex<double>;
    const Eigen::MatrixXcd V = es.eigenvectors();
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(V);
    const Eigen::VectorXd sv = svd.singularValues();
    if (sv(sv.size() - 1) > 1e-8 * sv(0)) {
      const Eigen::VectorXcd half = (0.5 * h * es.eigenvalues()).array().exp(), full = half.array().square();
      const Eigen::VectorXcd bt = lu.solve(b.cast<cd>());  // V⁻¹ b
      Eigen::MatrixXcd P = half.asDiagonal();              // Ṽ⁻¹ Φ V, built from the left
      for (int k = 0; k < steps; ++k) {
        const Eigen::RowVectorXcd rt = row_at(r, (k + 0.5) * h, n).cast<cd>() * V;  // r V
        const cd s = h * (rt * bt).value();  // h r b
        P.noalias() += (h * phi(s) * bt) * (rt * P);
        P = (k + 1 < steps ? full : half).asDiagonal() * P;
      }
      const Eigen::MatrixXd Phi = (V * P * lu.inverse()).real();
      if (!Phi.allFinite()) throw NumericalError("floquet: the monodromy matrix is not finite");
      return Phi;
    }
  }
  const Eigen::MatrixXd half = (0.5 * h * A).exp(), full = half * half;
  Eigen::MatrixXd Phi = half;
  for (int k = 0; k < steps; ++k) {
    const Eigen::RowVectorXd rk = row_at(r, (k + 0.5) * h, n);
    Phi.noalias() += (h * phi(h * rk.dot(b)) * b) * (rk * Phi);  // e^{h b r} Φ, rank one
    Phi = (k + 1 < steps ? full : half) * Phi;
  }
  if (!Phi.allFinite()) throw NumericalError("floquet: the monodromy matrix is not finite");
  return Phi;
}

FloquetResult floquet(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                      const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps) {
  const Eigen::MatrixXd Phi = monodromy(A, b, r, T, steps);
  Eigen::VectorXcd mu = Phi.eigenvalues();
  std::sort(mu.data(), mu.data() + mu.size(), [](auto x, auto y) { return std::abs(x) > std::abs(y); });
  FloquetResult f;
  f.multipliers = mu;
  f.largest = mu.size() ? std::abs(mu[0]) : 0.0;
  return f;
}

}  // namespace inerta::numerics
