// The band Cholesky solves and the band of the inverse against a dense factorisation of the same
// matrix (numerics/band.hpp): the modal solver's K₀⁻¹ (docs/catenary-fe.md "Modal solver").
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "inerta/numerics/band.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_band {

using namespace inerta::numerics;

namespace {
// A symmetric positive definite band matrix (diagonally dominant), n × n, half-bandwidth kd.
Eigen::SparseMatrix<double> spd_band(int n, int kd, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    t.emplace_back(j, j, 2.0 * kd + 1 + u(g));
    for (int i = j + 1; i <= std::min(n - 1, j + kd); ++i) {
      const double v = u(g);
      t.emplace_back(i, j, v), t.emplace_back(j, i, v);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
}  // namespace

TEST(Band, CholeskySolveAndInverseAgreeWithADenseFactorisation) {
  const int n = 60, kd = 4;
  const Eigen::SparseMatrix<double> A = spd_band(n, kd, 3);
  ASSERT_EQ(band_width(A), kd);
  std::vector<double> L = band_lower(A, kd);
  ASSERT_EQ(band_cholesky(L, n, kd), 0);
  const Eigen::MatrixXd inv = Eigen::MatrixXd(A).inverse();
  for (int j : {0, 17, 59}) {  // a column of A⁻¹, far entries included
    Eigen::VectorXd x = Eigen::VectorXd::Unit(n, j);
    band_cholesky_solve(L.data(), n, kd, x.data());
    EXPECT_LT((x - inv.col(j)).lpNorm<Eigen::Infinity>(), 1e-13 * inv.cwiseAbs().maxCoeff()) << j;
  }
  const BandInverse Z = band_inverse(L, n, kd);
  for (int j = 0; j < n; ++j)
    for (int i = j; i <= std::min(n - 1, j + kd); ++i) {
      EXPECT_NEAR(Z(i, j), inv(i, j), 1e-13 * inv.cwiseAbs().maxCoeff()) << i << "," << j;
      EXPECT_EQ(Z(i, j), Z(j, i));
    }
}

TEST(Band, ASolveFromTheFirstNonzeroGivesTheSameNumbers) {
  // band_cholesky_solve(…, first): x zero before `first`, the forward substitution starts there
  // (the modal solver's K₀⁻¹ columns); the result is the full solve's, bit for bit.
  const int n = 200, kd = 7;
  std::vector<double> L = band_lower(spd_band(n, kd, 11), kd);
  ASSERT_EQ(band_cholesky(L, n, kd), 0);
  for (int first : {0, 1, 50, 120, 199}) {
    Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
    for (int i = first; i < std::min(n, first + 3); ++i) a[i] = 1.0 + i;
    Eigen::VectorXd b = a;
    band_cholesky_solve(L.data(), n, kd, a.data());
    band_cholesky_solve(L.data(), n, kd, b.data(), first);
    for (int i = 0; i < n; ++i) EXPECT_EQ(a[i], b[i]) << first << ": " << i;
  }
}

TEST(Band, LdltSolvesAnIndefiniteBandMatrixAndCountsItsNegativeEigenvalues) {
  // A − σI with σ inside the spectrum (the shift-invert operator of the eigensolver): the solve
  // against a dense one, the count of negative pivots against the dense eigenvalues; half-bandwidths
  // with a solve of their own (1…16), beyond them (20), and matrices smaller than the band's reach.
  for (const int kd : {1, 3, 7, 11, 16, 20})
    for (const int n : {1, 2, kd, kd + 2, 2 * kd + 3, 97}) {
      const Eigen::SparseMatrix<double> A0 = spd_band(n, kd, static_cast<unsigned>(7 * kd + n));
      const Eigen::MatrixXd dense(A0);
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues();
      const double sigma = n > 1 ? 0.5 * (ev[n / 2] + ev[n / 2 - 1]) : ev[0] - 1;
      Eigen::SparseMatrix<double> I(n, n);
      I.setIdentity();
      const Eigen::SparseMatrix<double> A = A0 - sigma * I;
      const BandLdlt f(A);
      EXPECT_EQ(f.negative(), n / 2) << kd << " " << n;
      Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2), x = b;
      f.solve(x.data());
      const Eigen::VectorXd ref = Eigen::MatrixXd(A).fullPivLu().solve(b);
      EXPECT_LT((x - ref).lpNorm<Eigen::Infinity>(), 1e-9 * std::max(1.0, ref.lpNorm<Eigen::Infinity>())) << kd << " " << n;
    }
}

}  // namespace test_numerics_band
