// Symmetric band matrices: LDLᵀ, LAPACK band Cholesky and its solves, band of the inverse (numerics/band.hpp).
#include "inerta/numerics/band.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "inerta/error.hpp"

extern "C" {
void dpbtrf_(const char* uplo, const int* n, const int* kd, double* ab, const int* ldab, int* info);
}

namespace inerta::numerics {

using Sparse = Eigen::SparseMatrix<double>;

int band_width(const Sparse& A) {
  int kd = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it) kd = std::max(kd, static_cast<int>(it.row()) - j);
  return kd;
}

std::vector<double> band_lower(const Sparse& A, int kd) {
  const int ld = kd + 1;
  std::vector<double> ab(static_cast<std::size_t>(ld) * static_cast<std::size_t>(A.cols()), 0.0);
  for (int j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) ab[static_cast<std::size_t>(it.row() - j) + static_cast<std::size_t>(j) * ld] = it.value();
  return ab;
}

BandLdlt::BandLdlt(const Sparse& A) : n_(static_cast<int>(A.rows())) {
  for (int j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it) kd_ = std::max(kd_, static_cast<int>(it.row()) - j);
  ld_ = kd_ + 1;
  l_.assign(static_cast<std::size_t>(ld_) * static_cast<std::size_t>(n_), 0.0);
  for (int j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) at(static_cast<int>(it.row()), j) = it.value();
  d_.resize(static_cast<std::size_t>(n_));
  for (int j = 0; j < n_; ++j) {
    const int k0 = std::max(0, j - kd_);
    double dj = at(j, j);
    for (int k = k0; k < j; ++k) dj -= at(j, k) * at(j, k) * d_[static_cast<std::size_t>(k)];
    if (dj == 0 || !std::isfinite(dj)) throw NumericalError(fmt::format("finite-element modes: K − σM is singular (pivot {})", j));
    d_[static_cast<std::size_t>(j)] = dj;
    for (int i = j + 1; i <= std::min(n_ - 1, j + kd_); ++i) {
      double v = at(i, j);
      for (int k = std::max(k0, i - kd_); k < j; ++k) v -= at(i, k) * at(j, k) * d_[static_cast<std::size_t>(k)];
      at(i, j) = v / dj;
    }
  }
}

int BandLdlt::negative() const { return static_cast<int>(std::count_if(d_.begin(), d_.end(), [](double v) { return v < 0; })); }

namespace {
// x ← (L D Lᵀ)⁻¹ x for a unit lower band L of half-bandwidth KD (column j at l + j (KD + 1)). The
// band's pending values are kept in registers, and the back substitution adds the older unknowns
// first, so that one unknown waits on the one before by a single multiply-add (the solve is the
// shift-invert Lanczos operator's: ≈ a third of an eigenproblem).
template <int KD>
void ldlt_solve_kd(const double* l, const double* d, int n, double* x) {
  constexpr int ld = KD + 1;
  int j = 0;
  if (n > KD + 1) {
    double w[KD];  // x[j + 1 … j + KD], updated
    for (int i = 0; i < KD; ++i) w[i] = x[1 + i];
    double y = x[0];
    for (; j + KD + 1 < n; ++j) {
      const double* c = l + static_cast<std::ptrdiff_t>(j) * ld;
      x[j] = y;
      for (int i = 0; i < KD; ++i) w[i] -= c[i + 1] * y;
      y = w[0];
      for (int i = 0; i + 1 < KD; ++i) w[i] = w[i + 1];
      w[KD - 1] = x[j + KD + 1];
    }
    x[j] = y;
    for (int i = 0; i < KD; ++i) x[j + 1 + i] = w[i];
  }
  for (; j < n; ++j) {
    const double* c = l + static_cast<std::ptrdiff_t>(j) * ld;
    const double xj = x[j];
    const int m = std::min(KD, n - 1 - j);
    for (int i = 1; i <= m; ++i) x[j + i] -= c[i] * xj;
  }
  for (int k = 0; k < n; ++k) x[k] /= d[k];
  int k = n - 1;
  for (; k >= 0 && k + KD >= n; --k) {  // the last KD unknowns: a shorter band
    const double* c = l + static_cast<std::ptrdiff_t>(k) * ld;
    double s = x[k];
    for (int i = n - 1 - k; i >= 1; --i) s -= c[i] * x[k + i];
    x[k] = s;
  }
  if (k < 0) return;
  double v[KD];  // x[k + 1 … k + KD], final
  for (int i = 0; i < KD; ++i) v[i] = x[k + 1 + i];
  for (; k >= 0; --k) {
    const double* c = l + static_cast<std::ptrdiff_t>(k) * ld;
    double s = x[k];
    for (int i = KD; i >= 2; --i) s -= c[i] * v[i - 1];
    s -= c[1] * v[0];
    for (int i = KD - 1; i >= 1; --i) v[i] = v[i - 1];
    v[0] = s;
    x[k] = s;
  }
}

void ldlt_solve_any(const double* l, const double* d, int n, int kd, double* x) {
  const int ld = kd + 1;
  for (int j = 0; j < n; ++j) {
    const double* c = l + static_cast<std::ptrdiff_t>(j) * ld;
    const double xj = x[j];
    const int m = std::min(kd, n - 1 - j);
    for (int i = 1; i <= m; ++i) x[j + i] -= c[i] * xj;
  }
  for (int j = 0; j < n; ++j) x[j] /= d[j];
  for (int j = n - 1; j >= 0; --j) {
    const double* c = l + static_cast<std::ptrdiff_t>(j) * ld;
    double s = x[j];
    for (int i = std::min(kd, n - 1 - j); i >= 1; --i) s -= c[i] * x[j + i];
    x[j] = s;
  }
}

template <int... K>
void ldlt_solve(const double* l, const double* d, int n, int kd, double* x, std::integer_sequence<int, K...>) {
  if (!((kd == K + 1 ? (ldlt_solve_kd<K + 1>(l, d, n, x), true) : false) || ...)) ldlt_solve_any(l, d, n, kd, x);
}
}  // namespace

void BandLdlt::solve(double* x) const {
  ldlt_solve(l_.data(), d_.data(), n_, kd_, x, std::make_integer_sequence<int, 16>{});
}

int band_cholesky(std::vector<double>& ab, int n, int kd) {
  const int ld = kd + 1;
  int info = 0;
  if (n > 0) dpbtrf_("L", &n, &kd, ab.data(), &ld, &info);
  return info;
}

void band_cholesky_solve(const double* ab, int n, int kd, double* x, int first) {
  const int ld = kd + 1;
  for (int j = std::max(first, 0); j < n; ++j) {
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    const double xj = x[j] / c[0];
    x[j] = xj;
    const int m = std::min(kd, n - 1 - j);
    for (int i = 1; i <= m; ++i) x[j + i] -= c[i] * xj;
  }
  for (int j = n - 1; j >= 0; --j) {
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    double s = x[j];
    const int m = std::min(kd, n - 1 - j);
    for (int i = 1; i <= m; ++i) s -= c[i] * x[j + i];
    x[j] = s / c[0];
  }
}

void band_cholesky_solve_rows(const double* ab, int n, int kd, double* X, int ns) {
  const int ld = kd + 1;
  auto row = [&](int i) { return X + static_cast<std::ptrdiff_t>(i) * ns; };
  for (int j = 0; j < n; ++j) {  // L y = b
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    double* xj = row(j);
    const double inv = 1 / c[0];
    for (int k = 0; k < ns; ++k) xj[k] *= inv;
    for (int i = 1; i <= std::min(kd, n - 1 - j); ++i) {
      double* xi = row(j + i);
      const double l = c[i];
      for (int k = 0; k < ns; ++k) xi[k] -= l * xj[k];
    }
  }
  for (int j = n - 1; j >= 0; --j) {  // Lᵀ x = y
    const double* c = ab + static_cast<std::ptrdiff_t>(j) * ld;
    double* xj = row(j);
    for (int i = 1; i <= std::min(kd, n - 1 - j); ++i) {
      const double* xi = row(j + i);
      const double l = c[i];
      for (int k = 0; k < ns; ++k) xj[k] -= l * xi[k];
    }
    const double inv = 1 / c[0];
    for (int k = 0; k < ns; ++k) xj[k] *= inv;
  }
}

// Takahashi: Lᵀ Z = L⁻¹ row by row from the last, within the band (K = L Lᵀ).
BandInverse band_inverse(const std::vector<double>& L, int n, int kd) {
  BandInverse Z;
  Z.n = n, Z.kd = kd;
  const int ld = kd + 1;
  Z.z.assign(L.size(), 0.0);
  auto l = [&](int i, int j) { return L[static_cast<std::size_t>(i - j) + static_cast<std::size_t>(j) * ld]; };
  for (int j = n - 1; j >= 0; --j) {
    const int last = std::min(n - 1, j + kd);
    for (int i = last; i >= j; --i) {
      double s = i == j ? 1 / l(j, j) : 0.0;
      for (int k = j + 1; k <= last; ++k) s -= l(k, j) * Z(k, i);
      Z.z[static_cast<std::size_t>(i - j) + static_cast<std::size_t>(j) * ld] = s / l(j, j);
    }
  }
  return Z;
}

double BandInverse::operator()(int i, int j) const {
  if (i < j) std::swap(i, j);
  return z[static_cast<std::size_t>(i - j) + static_cast<std::size_t>(j) * (kd + 1)];
}

}  // namespace inerta::numerics
