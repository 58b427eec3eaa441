#pragma once
// The lowest modes of a large sparse symmetric generalised eigenproblem K φ = λ M φ (K, M band,
// M positive definite): spectrum slicing with shift-invert Lanczos (Spectra). The number of
// eigenvalues below λ is known beforehand from the inertia of K − λM (Sylvester's law: the negative
// pivots of its LDLᵀ, numerics/band.hpp); the range [0, λ_max) is cut into slices uniform in ω, each
// solved on its own (in parallel) with its count checked. In standard form with M = L Lᵀ:
// A = L⁻¹ K L⁻ᵀ, (A − σI)⁻¹ = Lᵀ (K − σM)⁻¹ L, φ = L⁻ᵀ y (M-orthonormal). Small problems (n <= 200): dense.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <utility>
#include <vector>

namespace inerta::numerics {

/// Modes of the generalised problem K φ = ω² M φ with ω/2π < cutoff_hz (K, M symmetric, K positive
/// definite), M-orthonormal, ascending.
struct Modes {
  Eigen::VectorXd omega2;  ///< ω², (rad/s)²
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> phi;  ///< n × m, a DOF a row
};
/// NumericalError if the slices do not account for every eigenvalue the inertia counts.
Modes lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double cutoff_hz);

/// A signed permutation P, (P x)_i = sign_i · x_{map_i}: the entry i is {map_i, sign_i}.
using SignedPermutation = std::vector<std::pair<int, double>>;

/// The same modes for a problem with a mirror symmetry: P K Pᵀ = K, P M Pᵀ = M, P² = I (a window of
/// identical spans reversed). The modes are those of the symmetric (Pφ = φ) and antisymmetric
/// (Pφ = −φ) subspaces, each about half the unknowns and half the modes — together half the work
/// of one problem. The problem solved is the symmetric part of (K, M), (A + P A Pᵀ)/2.
/// InvalidArgument if P is not an involution of K's size.
Modes lowest_modes_mirrored(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double cutoff_hz,
                            const SignedPermutation& P);

/// Eigenvalues of (K, M) below λ (Sylvester's law of inertia: negative pivots of K − λM = LDLᵀ).
int eigenvalues_below(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double lambda);

}  // namespace inerta::numerics
