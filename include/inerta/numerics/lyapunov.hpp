#pragma once
// Continuous Lyapunov equation A P + P Aᵀ + Q = 0 for a stable (Hurwitz) A, by Bartels–Stewart on the
// complex Schur form A = U T Uᴴ: T P̃ + P̃ Tᴴ = −Uᴴ Q U is solved column by column, last first
// (O(n³)). P is the stationary covariance of Ẋ = A X + w with E[w(t) w(s)ᵀ] = Q δ(t − s).
#include <Eigen/Dense>

namespace inerta::numerics {

/// InvalidArgument if A is not square or Q not of its size; NumericalError if A has an eigenvalue
/// with Re λ >= −1e-9 max(1, |λ|max) (not asymptotically stable: no stationary covariance), naming it.
Eigen::MatrixXd lyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q);

}  // namespace inerta::numerics
