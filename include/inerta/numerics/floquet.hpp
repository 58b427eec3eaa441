#pragma once
// Floquet stability of a linear time-periodic system with a rank-one periodic part (issue 15):
//   Ẋ = (A + b r(t)) X,  r(t + T) = r(t)  (b: column, r(t): row),
// the form of the pantograph–catenary system linearised about its periodic steady state (the
// catenary's stiffness and damping harmonics act through the one wire force, analysis/periodic.hpp).
// The monodromy matrix Φ(T) is built by Strang splitting over n steps of h = T/n:
//   Φ ← e^{hA/2} e^{h b r(t_k+h/2)} e^{hA/2} Φ,  with e^{h b r} = I + h φ(h r b) b r, φ(σ) = (e^σ − 1)/σ,
// second order in h. Its eigenvalues are the Floquet multipliers μ; the periodic solution is
// asymptotically stable when every |μ| < 1.
#include <Eigen/Dense>
#include <functional>

namespace inerta::numerics {

struct FloquetResult {
  Eigen::VectorXcd multipliers;  ///< eigenvalues of Φ(T), largest modulus first
  double largest = 0;            ///< max |μ|
  bool stable() const { return largest < 1.0; }
};

/// Φ(T) of Ẋ = (A + b r(t)) X over one period T > 0 with `steps` ≥ 8 splitting steps (InvalidArgument
/// otherwise, or if the sizes disagree); NumericalError if Φ(T) is not finite.
Eigen::MatrixXd monodromy(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps);

/// Floquet multipliers: the eigenvalues of monodromy(A, b, r, T, steps).
FloquetResult floquet(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                      const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps);

}  // namespace inerta::numerics
