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

}  // namespace

FloquetBasis::FloquetBasis(const Eigen::MatrixXd& A) : A_(A) {
  if (A.cols() != A.rows()) throw InvalidArgument(fmt::format("floquet: A is {}×{}, expected a square matrix", A.rows(), A.cols()));
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() != Eigen::Success || A.rows() == 0) return;
  const Eigen::MatrixXcd V = es.eigenvectors();
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXcd>(V).singularValues();
  if (!(sv(sv.size() - 1) > 1e-8 * sv(0))) return;  // defective or ill-conditioned: the dense form
  diagonal_ = true;
  lambda_ = es.eigenvalues();
  V_ = V;
  V_inv_ = V.partialPivLu().inverse();
}

Eigen::MatrixXd monodromy(const FloquetBasis& basis, const Eigen::VectorXd& b, const Eigen::MatrixXd& R,
                          const std::function<Eigen::VectorXd(double)>& c, double T, int steps) {
  const Eigen::MatrixXd& A = basis.A_;
  check_arguments(A, b, T, steps);
  const Eigen::Index n = A.rows();
  if (R.cols() != n) throw InvalidArgument(fmt::format("floquet: R has {} columns, expected {}", R.cols(), n));
  auto coefficients = [&](double t) {
    Eigen::VectorXd ck = c(t);
    if (ck.size() != R.rows())
      throw InvalidArgument(fmt::format("floquet: c(t) has {} entries, expected {} (the rows of R)", ck.size(), R.rows()));
    return ck;
  };
  const double h = T / steps;
  if (basis.diagonal_) {  // every e^{hA/2} diagonal
    using cd = std::complex<double>;
    const Eigen::VectorXcd half = (0.5 * h * basis.lambda_).array().exp(), full = half.array().square();
    const Eigen::VectorXcd bt = basis.V_inv_ * b.cast<cd>();  // V⁻¹ b
    const Eigen::MatrixXcd RV = R.cast<cd>() * basis.V_;      // R V
    Eigen::MatrixXcd P = half.asDiagonal();                   // V⁻¹ Φ V, built from the left
    for (int k = 0; k < steps; ++k) {
      const Eigen::RowVectorXcd rt = coefficients((k + 0.5) * h).cast<cd>().transpose() * RV;  // r V
      const cd s = h * (rt * bt).value();                                                      // h r b
      P.noalias() += (h * phi(s) * bt) * (rt * P);
      P = (k + 1 < steps ? full : half).asDiagonal() * P;
    }
    const Eigen::MatrixXd Phi = (basis.V_ * P * basis.V_inv_).real();
    if (!Phi.allFinite()) throw NumericalError("floquet: the monodromy matrix is not finite");
    return Phi;
  }
  const Eigen::MatrixXd half = (0.5 * h * A).exp(), full = half * half;
  Eigen::MatrixXd Phi = half;
  for (int k = 0; k < steps; ++k) {
    const Eigen::RowVectorXd rk = coefficients((k + 0.5) * h).transpose() * R;
    Phi.noalias() += (h * phi(h * rk.dot(b)) * b) * (rk * Phi);  // e^{h b r} Φ, rank one
    Phi = (k + 1 < steps ? full : half) * Phi;
  }
  if (!Phi.allFinite()) throw NumericalError("floquet: the monodromy matrix is not finite");
  return Phi;
}

Eigen::MatrixXd monodromy(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps) {
  check_arguments(A, b, T, steps);
  // r(t) itself as the coefficients of the identity's rows.
  const Eigen::Index n = A.rows();
  return monodromy(FloquetBasis(A), b, Eigen::MatrixXd::Identity(n, n),
                   [&](double t) -> Eigen::VectorXd {
                     Eigen::RowVectorXd rk = r(t);
                     if (rk.size() != n)
                       throw InvalidArgument(fmt::format("floquet: r(t) has {} columns, expected {}", rk.size(), n));
                     return rk.transpose();
                   },
                   T, steps);
}

namespace {
FloquetResult multipliers(const Eigen::MatrixXd& Phi) {
  Eigen::VectorXcd mu = Phi.eigenvalues();
  std::sort(mu.data(), mu.data() + mu.size(), [](auto x, auto y) { return std::abs(x) > std::abs(y); });
  FloquetResult f;
  f.multipliers = mu;
  f.largest = mu.size() ? std::abs(mu[0]) : 0.0;
  return f;
}
}  // namespace

FloquetResult floquet(const FloquetBasis& A, const Eigen::VectorXd& b, const Eigen::MatrixXd& R,
                      const std::function<Eigen::VectorXd(double)>& c, double T, int steps) {
  return multipliers(monodromy(A, b, R, c, T, steps));
}

FloquetResult floquet(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                      const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps) {
  return multipliers(monodromy(A, b, r, T, steps));
}

}  // namespace inerta::numerics
