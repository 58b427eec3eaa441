// Lowest modes of a sparse symmetric generalised eigenproblem: spectrum slicing with shift-invert
// Lanczos (numerics/generalised_eigen.hpp).
#include "inerta/numerics/generalised_eigen.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <Spectra/SymEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/numerics/band.hpp"

namespace inerta::numerics {

using Sparse = Eigen::SparseMatrix<double>;

namespace {

// The standard form of K φ = λ M φ with M = L Lᵀ (band Cholesky): A y = λ y, A = L⁻¹ K L⁻ᵀ, φ = L⁻ᵀ y.
// Spectra's shift-invert operator (A − σI)⁻¹ = Lᵀ (K − σM)⁻¹ L: two band products and a sparse LDLᵀ
// solve in the band's own order; the Lanczos vectors then need no M inner products.
using Llt = Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::NaturalOrdering<int>>;
class ShiftInvert {
 public:
  using Scalar = double;
  ShiftInvert(const Sparse& K, const Sparse& M, const Sparse& L) : K_(K), M_(M), L_(L), t_(K.rows()) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  void set_shift(double sigma) { ldlt_ = std::make_unique<BandLdlt>(Sparse(K_ - sigma * M_)); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<const Eigen::VectorXd> in(x, rows());
    t_.noalias() = L_ * in;
    ldlt_->solve(t_.data());
    Eigen::Map<Eigen::VectorXd>(y, rows()).noalias() = L_.transpose() * t_;
  }

 private:
  const Sparse &K_, &M_, &L_;
  std::unique_ptr<BandLdlt> ldlt_;
  mutable Eigen::VectorXd t_;
};

// Eigenvalues a slice, and Lanczos vectors beyond them: reorthogonalisation grows with the square of
// the basis, and smaller slices converge more slowly; 18 and nev + 20 were the fastest measured on
// the bundled line's windows (12…32, docs/benchmarks.md "The FE line's first and stored runs").
constexpr int kSliceModes = 18;
constexpr int kExtraVectors = 20;

}  // namespace

// Eigenvalues of (K, M) below λ (Sylvester's law of inertia: negative pivots of K − λM = LDLᵀ).
int eigenvalues_below(const Sparse& K, const Sparse& M, double lambda) {
  return BandLdlt(Sparse(K - lambda * M)).negative();
}

Modes lowest_modes(const Sparse& K, const Sparse& M, double cutoff_hz) {
  const int n = static_cast<int>(K.rows());
  const double w_max = 2 * std::numbers::pi * cutoff_hz, lambda_max = w_max * w_max;
  const int m = eigenvalues_below(K, M, lambda_max);
  Modes out;
  if (m == 0) {
    out.omega2.resize(0);
    out.phi.resize(n, 0);
    return out;
  }
  if (n <= 200) {  // small: dense
    const Eigen::MatrixXd Kd(K), Md(M);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kd, Md);
    out.omega2 = es.eigenvalues().head(m);
    out.phi = es.eigenvectors().leftCols(m);
    return out;
  }
  // Slices uniform in ω (a wire's modes are about evenly spaced in frequency), each with its count.
  const int S = std::max(1, (m + kSliceModes - 1) / kSliceModes);
  std::vector<double> edge(static_cast<std::size_t>(S) + 1);
  std::vector<int> below(static_cast<std::size_t>(S) + 1);
  for (int k = 0; k <= S; ++k) edge[static_cast<std::size_t>(k)] = lambda_max * (double(k) / S) * (double(k) / S);
  below[0] = 0;
  below[static_cast<std::size_t>(S)] = m;
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(1, S, [&](int k) { below[static_cast<std::size_t>(k)] = eigenvalues_below(K, M, edge[static_cast<std::size_t>(k)]); });
  });
  std::vector<Eigen::VectorXd> vals(static_cast<std::size_t>(S));
  std::vector<Eigen::MatrixXd> vecs(static_cast<std::size_t>(S));
  const Llt mllt(M);
  if (mllt.info() != Eigen::Success) throw NumericalError("finite-element modes: the mass matrix is not positive definite");
  const Sparse Lm = mllt.matrixL();
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, S, [&](int k) {
      const std::size_t s = static_cast<std::size_t>(k);
      const int want = below[s + 1] - below[s];
      if (want == 0) return;
      const double lo = edge[s], hi = edge[s + 1], sigma = 0.5 * (lo + hi);
      ShiftInvert op(K, M, Lm);
      // The `want` eigenvalues nearest σ are those of [lo, hi); ask for a few more, keep those inside.
      const int nev = std::min(n - 2, want + 2);
      const int ncv = std::min(n, nev + kExtraVectors);
      Spectra::SymEigsShiftSolver<ShiftInvert> es(op, nev, ncv, sigma);
      es.init();
      es.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
      if (es.info() != Spectra::CompInfo::Successful)
        throw NumericalError(fmt::format(
            "finite-element modes: the Lanczos iteration did not converge between {:.4g} and {:.4g} Hz",
            std::sqrt(lo) / (2 * std::numbers::pi), std::sqrt(hi) / (2 * std::numbers::pi)));
      const Eigen::VectorXd ev = es.eigenvalues();
      const Eigen::MatrixXd V = es.eigenvectors();
      std::vector<Eigen::Index> keep;
      for (Eigen::Index i = 0; i < ev.size(); ++i)
        if (ev[i] >= lo && ev[i] < hi) keep.push_back(i);
      if (static_cast<int>(keep.size()) != want)
        throw NumericalError(fmt::format(
            "finite-element modes: found {} of the {} modes between {:.4g} and {:.4g} Hz (a cluster at a slice's edge?)",
            keep.size(), want, std::sqrt(lo) / (2 * std::numbers::pi), std::sqrt(hi) / (2 * std::numbers::pi)));
      vals[s].resize(want);
      vecs[s].resize(n, want);
      for (int i = 0; i < want; ++i) vals[s][i] = ev[keep[static_cast<std::size_t>(i)]], vecs[s].col(i) = V.col(keep[static_cast<std::size_t>(i)]);
      vecs[s] = mllt.matrixU().solve(vecs[s]);  // φ = L⁻ᵀ y: M-orthonormal
    });
  });
  out.omega2.resize(m);
  out.phi.resize(n, m);
  std::vector<std::pair<double, std::pair<int, int>>> order;
  for (int s = 0; s < S; ++s)
    for (Eigen::Index i = 0; i < vals[static_cast<std::size_t>(s)].size(); ++i)
      order.push_back({vals[static_cast<std::size_t>(s)][i], {s, static_cast<int>(i)}});
  std::sort(order.begin(), order.end());
  for (int j = 0; j < m; ++j) {
    const auto [s, i] = order[static_cast<std::size_t>(j)].second;
    out.omega2[j] = order[static_cast<std::size_t>(j)].first;
    out.phi.col(j) = vecs[static_cast<std::size_t>(s)].col(i);
  }
  return out;
}

Modes lowest_modes_mirrored(const Sparse& K, const Sparse& M, double cutoff_hz, const SignedPermutation& P) {
  const int n = static_cast<int>(K.rows());
  if (static_cast<int>(P.size()) != n)
    throw InvalidArgument("lowest_modes_mirrored", "P", fmt::format("{} entries for {} unknowns", P.size(), n));
  for (int i = 0; i < n; ++i) {
    const auto [j, s] = P[static_cast<std::size_t>(i)];
    if (j < 0 || j >= n || P[static_cast<std::size_t>(j)].first != i || std::abs(s) != 1 || s * P[static_cast<std::size_t>(j)].second != 1)
      throw InvalidArgument("lowest_modes_mirrored", "P", fmt::format("not a signed involution at {}", i));
  }
  // Orthonormal bases of the two subspaces, a column per orbit {i, j = map_i} (i <= j) in the order
  // of i, so that the projected matrices keep the band: (e_j ± s_i e_i)/√2, or e_i if i = j.
  std::vector<Eigen::Triplet<double>> tp, tm;
  int np = 0, nm = 0;
  const double h = std::sqrt(0.5);
  for (int i = 0; i < n; ++i) {
    const auto [j, s] = P[static_cast<std::size_t>(i)];
    if (j < i) continue;
    if (j == i) {
      if (s > 0) tp.emplace_back(i, np++, 1.0);
      else tm.emplace_back(i, nm++, 1.0);
      continue;
    }
    tp.emplace_back(j, np, h), tp.emplace_back(i, np++, s * h);
    tm.emplace_back(j, nm, h), tm.emplace_back(i, nm++, -s * h);
  }
  Sparse Bp(n, np), Bm(n, nm);
  Bp.setFromTriplets(tp.begin(), tp.end());
  Bm.setFromTriplets(tm.begin(), tm.end());
  Modes halves[2];
  const Sparse* B[2] = {&Bp, &Bm};
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, 2, [&](int k) {
      const Sparse& b = *B[k];
      if (b.cols() == 0) return;
      const Sparse Kk = Sparse(b.transpose() * K * b).pruned(), Mk = Sparse(b.transpose() * M * b).pruned();
      halves[k] = lowest_modes(Kk, Mk, cutoff_hz);
    });
  });
  // Merged in ascending order (a tie: the symmetric mode first), φ = B y.
  const Eigen::Index m0 = halves[0].omega2.size(), m1 = halves[1].omega2.size();
  Modes out;
  out.omega2.resize(m0 + m1);
  out.phi.resize(n, m0 + m1);
  Eigen::MatrixXd full[2];
  for (int k = 0; k < 2; ++k)
    if (halves[k].omega2.size() > 0) full[k] = *B[k] * Eigen::MatrixXd(halves[k].phi);
  for (Eigen::Index a = 0, b = 0, c = 0; c < m0 + m1; ++c) {
    const bool first = b >= m1 || (a < m0 && halves[0].omega2[a] <= halves[1].omega2[b]);
    out.omega2[c] = first ? halves[0].omega2[a] : halves[1].omega2[b];
    out.phi.col(c) = first ? full[0].col(a++) : full[1].col(b++);
  }
  return out;
}

}  // namespace inerta::numerics
