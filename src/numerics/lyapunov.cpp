#include "inerta/numerics/lyapunov.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <complex>

#include "inerta/error.hpp"

namespace inerta::numerics {

Eigen::MatrixXd lyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q) {
  using cd = std::complex<double>;
  const Eigen::Index n = A.rows();
  if (A.cols() != n || Q.rows() != n || Q.cols() != n)
    throw InvalidArgument(fmt::format("lyapunov: A is {}×{} and Q {}×{}; expected square matrices of one size",
                                      A.rows(), A.cols(), Q.rows(), Q.cols()));
  if (n == 0) return Eigen::MatrixXd(0, 0);
  Eigen::ComplexSchur<Eigen::MatrixXcd> schur(A.cast<cd>());
  const Eigen::MatrixXcd& T = schur.matrixT();
  const Eigen::MatrixXcd& U = schur.matrixU();
  double big = 1;
  for (Eigen::Index i = 0; i < n; ++i) big = std::max(big, std::abs(T(i, i)));
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(T(i, i).real() < -1e-9 * big))
      throw NumericalError(fmt::format("the linear model is not asymptotically stable (eigenvalue {:.6g}{:+.6g}i): "
                                        "a random response has no stationary value",
                                        T(i, i).real(), T(i, i).imag()));
  const Eigen::MatrixXcd Qt = U.adjoint() * Q.cast<cd>() * U;
  Eigen::MatrixXcd P(n, n);
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    Eigen::VectorXcd rhs = -Qt.col(j);
    for (Eigen::Index k = j + 1; k < n; ++k) rhs -= std::conj(T(j, k)) * P.col(k);
    Eigen::MatrixXcd Tj = T;
    Tj.diagonal().array() += std::conj(T(j, j));
    P.col(j) = Tj.triangularView<Eigen::Upper>().solve(rhs);
  }
  const Eigen::MatrixXd R = (U * P * U.adjoint()).real();
  return 0.5 * (R + R.transpose());
}

}  // namespace inerta::numerics
