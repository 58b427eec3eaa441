#pragma once
// Symmetric band matrices (the finite-element line's K, M and K − σM; docs/catenary-fe.md "Modal
// solver"): the lower band in LAPACK's storage, a column a run of kd + 1 entries from the diagonal
// down, ab[(i − j) + j (kd + 1)] = A(i, j) for j <= i <= j + kd.
//  - BandLdlt: A = L D Lᵀ without pivoting (indefinite A allowed: K − σM of the shift-invert steps
//    and of the inertia counts, Sylvester's law of inertia from the signs of D).
//  - band_cholesky: A = L Lᵀ (LAPACK dpbtrf) and its solves, one right-hand side or several side by side.
//  - band_inverse: the band of A⁻¹ from its Cholesky factor (Takahashi's recurrence).
#include <Eigen/Sparse>
#include <vector>

namespace inerta::numerics {

/// Lower half-bandwidth of a symmetric sparse matrix (max i − j over its stored lower entries).
int band_width(const Eigen::SparseMatrix<double>& A);

/// The lower band of A (entries i >= j) in LAPACK storage with half-bandwidth kd.
std::vector<double> band_lower(const Eigen::SparseMatrix<double>& A, int kd);

/// LDLᵀ of a symmetric band matrix, no pivoting (as a sparse LDLᵀ in the band's own order).
/// NumericalError for a zero or non-finite pivot.
class BandLdlt {
 public:
  explicit BandLdlt(const Eigen::SparseMatrix<double>& A);
  int negative() const;          ///< negative pivots: eigenvalues of A below 0 (Sylvester)
  void solve(double* x) const;   ///< x ← A⁻¹ x (n values)

 private:
  double& at(int i, int j) { return l_[static_cast<std::size_t>(i - j) + static_cast<std::size_t>(j) * static_cast<std::size_t>(ld_)]; }
  int n_, kd_ = 0, ld_ = 1;
  std::vector<double> l_, d_;
};

/// In place: the band `ab` (n × n, half-bandwidth kd, LAPACK lower storage) ← its Cholesky factor L.
/// Returns LAPACK dpbtrf's info (0: done; > 0: not positive definite).
int band_cholesky(std::vector<double>& ab, int n, int kd);

/// x ← A⁻¹ x from A's band Cholesky factor (forward then back substitution; n values). `first`:
/// x is zero before it (the forward substitution starts there; the same numbers).
void band_cholesky_solve(const double* ab, int n, int kd, double* x, int first = 0);

/// X ← A⁻¹ X for ns right-hand sides side by side: X is n × ns row-major (a DOF a row).
void band_cholesky_solve_rows(const double* ab, int n, int kd, double* X, int ns);

/// The band of A⁻¹ (entries |i − j| <= kd) of a symmetric positive definite band matrix, from its
/// band Cholesky factor (Takahashi's recurrence Lᵀ Z = L⁻¹).
struct BandInverse {
  int n = 0, kd = 0;
  std::vector<double> z;  ///< (kd + 1) × n: z[(i − j) + j (kd + 1)] = Z(i, j), i >= j
  double operator()(int i, int j) const;  ///< |i − j| <= kd
};
BandInverse band_inverse(const std::vector<double>& L, int n, int kd);

}  // namespace inerta::numerics
