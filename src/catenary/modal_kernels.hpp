#pragma once
// The modal solve's dense kernels (fe_modal.cpp): products of a row-major block of mode shapes with a
// few vectors at once, reading the block once. Two builds: AVX2 + FMA, taken when the processor has
// them, and Eigen's baseline products otherwise (results differ between the two only by round-off).
#include <cstddef>

namespace inerta::catenary::kernels {

/// y[r·C + c] = Σ_{i<n} A[r·lda + i] · x[c][i]  for r < rows, c < C (1 <= C <= 4).
void rows_dot(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, double* y);

/// The same for any number of vectors C >= 1, each exactly as rows_dot with C = 1 gives it (lanes
/// stepped together give each lane's one-at-a-time numbers), each row read from memory once.
void rows_dot_each(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, double* y);

/// y[c][i] += Σ_{r<rows} coef[r·C + c] · A[r·lda + i]  for i < n, c < C (1 <= C <= 4): Aᵀ·coef.
void rows_axpy(const double* A, std::ptrdiff_t lda, int rows, int n, const double* coef, int C, double* const* y);

/// Several lanes' rows_dot over the same rows: lane l's C vectors x[l·C … l·C + C) into y[l], each as
/// rows_dot gives it, every row read once for all the lanes.
void rows_dot_lanes(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* x, int C, int lanes,
                    double* const* y);

/// Several lanes' rows_axpy: lane l's coefficients coef[l] into its vectors y[l·C … l·C + C).
void rows_axpy_lanes(const double* A, std::ptrdiff_t lda, int rows, int n, const double* const* coef, int C, int lanes,
                     double* const* y);

}  // namespace inerta::catenary::kernels
