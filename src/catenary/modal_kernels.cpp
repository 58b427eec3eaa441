// The modal solve's dense kernels (modal_kernels.hpp).
#include "modal_kernels.hpp"

#include <Eigen/Dense>
#include <vector>

namespace inerta::catenary::kernels {

namespace {

using Rows = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>, 0, Eigen::OuterStride<>>;

// Baseline (Eigen's products, SSE2 on x86-64).
void rows_dot_base(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, double* y) {
  const Rows a(A, rows, n, Eigen::OuterStride<>(lda));
  Eigen::VectorXd t(rows);
  for (int c = 0; c < C; ++c) {
    t.noalias() = a * Eigen::Map<const Eigen::VectorXd>(x[c], n);
    for (int r = 0; r < rows; ++r) y[r * C + c] = t[r];
  }
}
void rows_axpy_base(const double* A, std::ptrdiff_t lda, int rows, int n, const double* coef, int C, double* const* y) {
  const Rows a(A, rows, n, Eigen::OuterStride<>(lda));
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> k(coef, rows, C);
  for (int c = 0; c < C; ++c) Eigen::Map<Eigen::VectorXd>(y[c], n).noalias() += a.transpose() * k.col(c);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// AVX2 + FMA: four doubles a vector (GCC vector extensions; unaligned loads).
#define INERTA_HAVE_AVX2 1
typedef double v4 __attribute__((vector_size(32), aligned(8)));
#define INERTA_LD(p) (*reinterpret_cast<const v4*>(p))
#define INERTA_ST(p) (*reinterpret_cast<v4*>(p))

// aᵀx with four sums (half the loads of a pair's pass): rows_dot's one vector, rows_dot_each's every one.
__attribute__((target("arch=x86-64-v3"))) inline double dot_avx2(const double* a, const double* x0, int n) {
  v4 s0 = {}, s1 = {}, s2 = {}, s3 = {};
  const int n16 = n - n % 16;
  int i = 0;
  for (; i < n16; i += 16) {
    s0 += INERTA_LD(a + i) * INERTA_LD(x0 + i);
    s1 += INERTA_LD(a + i + 4) * INERTA_LD(x0 + i + 4);
    s2 += INERTA_LD(a + i + 8) * INERTA_LD(x0 + i + 8);
    s3 += INERTA_LD(a + i + 12) * INERTA_LD(x0 + i + 12);
  }
  for (; i + 4 <= n; i += 4) s0 += INERTA_LD(a + i) * INERTA_LD(x0 + i);
  s0 += s1, s2 += s3, s0 += s2;
  double t0 = (s0[0] + s0[2]) + (s0[1] + s0[3]);
  for (; i < n; ++i) t0 += a[i] * x0[i];
  return t0;
}

// One row a against C vectors (pairs in one pass, an odd last one alone): yr[c] = aᵀx[c].
__attribute__((target("arch=x86-64-v3"))) inline void row_dot_avx2(const double* a, int n, const double* const* x, int C,
                                                                    double* yr) {
  const int n8 = n - n % 8;
  int c0 = 0;
  for (; c0 + 1 < C; c0 += 2) {  // two vectors a pass: the row is read at most twice
    const double *x0 = x[c0], *x1 = x[c0 + 1];
    v4 s0 = {}, s0b = {}, s1 = {}, s1b = {};
    for (int i = 0; i < n8; i += 8) {
      const v4 a0 = INERTA_LD(a + i), a1 = INERTA_LD(a + i + 4);
      s0 += a0 * INERTA_LD(x0 + i);
      s0b += a1 * INERTA_LD(x0 + i + 4);
      s1 += a0 * INERTA_LD(x1 + i);
      s1b += a1 * INERTA_LD(x1 + i + 4);
    }
    s0 += s0b, s1 += s1b;
    double t0 = (s0[0] + s0[2]) + (s0[1] + s0[3]), t1 = (s1[0] + s1[2]) + (s1[1] + s1[3]);
    for (int i = n8; i < n; ++i) t0 += a[i] * x0[i], t1 += a[i] * x1[i];
    yr[c0] = t0, yr[c0 + 1] = t1;
  }
  if (c0 < C) yr[c0] = dot_avx2(a, x[c0], n);  // the last vector alone
}

__attribute__((target("arch=x86-64-v3"))) void rows_dot_avx2(const double* A, std::ptrdiff_t lda, int rows, int n,
                                                               const double* const* x, int C, double* y) {
  for (int r = 0; r < rows; ++r) row_dot_avx2(A + r * lda, n, x, C, y + r * C);
}

// Each lane's C vectors as rows_dot gives them, every row read once for all the lanes.
__attribute__((target("arch=x86-64-v3"))) void rows_dot_lanes_avx2(const double* A, std::ptrdiff_t lda, int rows, int n,
                                                                     const double* const* x, int C, int lanes,
                                                                     double* const* y) {
  for (int r = 0; r < rows; ++r)
    for (int l = 0; l < lanes; ++l) row_dot_avx2(A + r * lda, n, x + l * C, C, y[l] + r * C);
}

// Each vector as rows_dot with C = 1 gives it (dot_avx2), a row read from memory once for all of them.
__attribute__((target("arch=x86-64-v3"))) void rows_dot_each_avx2(const double* A, std::ptrdiff_t lda, int rows, int n,
                                                                    const double* const* x, int C, double* y) {
  for (int r = 0; r < rows; ++r) {
    const double* a = A + r * lda;
    for (int c = 0; c < C; ++c) y[r * C + c] = dot_avx2(a, x[c], n);
  }
}

// y[c] += coef[c] a for one row a (a zero coefficient skipped).
__attribute__((target("arch=x86-64-v3"))) inline void row_axpy_avx2(const double* a, int n, const double* coef, int C,
                                                                     double* const* y) {
  const int n4 = n - n % 4;
  for (int c = 0; c < C; ++c) {
    const double k = coef[c];
    if (k == 0) continue;
    double* yc = y[c];
    const v4 kv = {k, k, k, k};
    for (int i = 0; i < n4; i += 4) INERTA_ST(yc + i) = INERTA_LD(yc + i) + kv * INERTA_LD(a + i);
    for (int i = n4; i < n; ++i) yc[i] += k * a[i];
  }
}

__attribute__((target("arch=x86-64-v3"))) void rows_axpy_avx2(const double* A, std::ptrdiff_t lda, int rows, int n,
                                                                const double* coef, int C, double* const* y) {
  for (int r = 0; r < rows; ++r) row_axpy_avx2(A + r * lda, n, coef + r * C, C, y);
}

__attribute__((target("arch=x86-64-v3"))) void rows_axpy_lanes_avx2(const double* A, std::ptrdiff_t lda, int rows, int n,
                                                                      const double* const* coef, int C, int lanes,
                                                                      double* const* y) {
  for (int r = 0; r < rows; ++r)
    for (int l = 0; l < lanes; ++l) row_axpy_avx2(A + r * lda, n, coef[l] + r * C, C, y + l * C);
}

bool avx2() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return yes;
}
#endif

}  // namespace

void rows_dot(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, double* y) {
#ifdef INERTA_HAVE_AVX2
  if (avx2()) return rows_dot_avx2(A, lda, rows, n, x, C, y);
#endif
  rows_dot_base(A, lda, rows, n, x, C, y);
}

void rows_dot_each(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, double* y) {
#ifdef INERTA_HAVE_AVX2
  if (avx2()) return rows_dot_each_avx2(A, lda, rows, n, x, C, y);
#endif
  std::vector<double> t(static_cast<std::size_t>(rows));
  for (int c = 0; c < C; ++c) {  // rows_dot_base of one vector, as C = 1 gives it
    rows_dot_base(A, lda, rows, n, x + c, 1, t.data());
    for (int r = 0; r < rows; ++r) y[r * C + c] = t[static_cast<std::size_t>(r)];
  }
}

void rows_axpy(const double* A, std::ptrdiff_t lda, int rows, int n, const double* coef, int C, double* const* y) {
#ifdef INERTA_HAVE_AVX2
  if (avx2()) return rows_axpy_avx2(A, lda, rows, n, coef, C, y);
#endif
  rows_axpy_base(A, lda, rows, n, coef, C, y);
}

void rows_dot_lanes(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, int lanes,
                    double* const* y) {
#ifdef INERTA_HAVE_AVX2
  if (avx2()) return rows_dot_lanes_avx2(A, lda, rows, n, x, C, lanes, y);
#endif
  for (int l = 0; l < lanes; ++l) rows_dot_base(A, lda, rows, n, x + l * C, C, y[l]);
}

void rows_axpy_lanes(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* coef, int C, int lanes,
                     double* const* y) {
#ifdef INERTA_HAVE_AVX2
  if (avx2()) return rows_axpy_lanes_avx2(A, lda, rows, n, coef, C, lanes, y);
#endif
  for (int l = 0; l < lanes; ++l) rows_axpy_base(A, lda, rows, n, coef[l], C, y + l * C);
}

}  // namespace inerta::catenary::kernels
