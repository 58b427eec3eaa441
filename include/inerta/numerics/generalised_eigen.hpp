#pragma once
// The lowest modes of a large sparse symmetric generalised eigenproblem K φ = λ M φ (K, M band,
// M positive definite): spectrum slicing with shift-invert Lanczos (Spectra). The number of
// eigenvalues below λ is known beforehand from the inertia of K − λM (Sylvester's law: the negative
// pivots of its LDLᵀ, numerics/band.hpp); the range [0, λ_max) is cut into slices uniform in ω, each
// solved on its own (in parallel) with its count checked. In standard form with M = L Lᵀ:
// A = L⁻¹ K L⁻ᵀ, (A − σI)⁻¹ = Lᵀ (K − σM)⁻¹ L, φ = L⁻ᵀ y (M-orthonormal). Small problems (n <= 200): dense.
#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace inerta::numerics {

/// Modes of the generalised problem K φ = ω² M φ with ω/2π < cutoff_hz (K, M symmetric, K positive
/// definite), M-orthonormal, ascending.
struct Modes {
  Eigen::VectorXd omega2;  ///< ω², (rad/s)²
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> phi;  ///< n × m, a DOF a row
};
/// NumericalError if the slices do not account for every eigenvalue the inertia counts.
Modes lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double cutoff_hz);

/// Eigenvalues of (K, M) below λ (Sylvester's law of inertia: negative pivots of K − λM = LDLᵀ).
int eigenvalues_below(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double lambda);

}  // namespace inerta::numerics
