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

/// A decomposed once for several Floquet checks with the same A (a speed sweep: only the period and
/// r(t) change): its eigenbasis A = V Λ V⁻¹ when V is well conditioned (σ_min > 1e-8 σ_max), in
/// which a splitting step costs O(n²); otherwise the dense form (a defective A).
class FloquetBasis {
 public:
  explicit FloquetBasis(const Eigen::MatrixXd& A);
  bool diagonal() const { return diagonal_; }

 private:
  friend Eigen::MatrixXd monodromy(const FloquetBasis&, const Eigen::VectorXd&, const Eigen::MatrixXd&,
                                   const std::function<Eigen::VectorXd(double)>&, double, int);
  Eigen::MatrixXd A_;
  bool diagonal_ = false;
  Eigen::VectorXcd lambda_;
  Eigen::MatrixXcd V_, V_inv_;
};

/// Φ(T) of Ẋ = (A + b r(t)) X with r(t) = c(t)ᵀ R, a combination of the fixed rows of R (m × n) with
/// coefficients c(t) (m): R is carried into the eigenbasis once, so a step costs O(n² + mn).
Eigen::MatrixXd monodromy(const FloquetBasis& A, const Eigen::VectorXd& b, const Eigen::MatrixXd& R,
                          const std::function<Eigen::VectorXd(double)>& c, double T, int steps);

/// Floquet multipliers: the eigenvalues of monodromy(A, b, R, c, T, steps).
FloquetResult floquet(const FloquetBasis& A, const Eigen::VectorXd& b, const Eigen::MatrixXd& R,
                      const std::function<Eigen::VectorXd(double)>& c, double T, int steps);

/// Φ(T) of Ẋ = (A + b r(t)) X over one period T > 0 with `steps` ≥ 8 splitting steps (InvalidArgument
/// otherwise, or if the sizes disagree); NumericalError if Φ(T) is not finite.
Eigen::MatrixXd monodromy(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps);

/// Floquet multipliers: the eigenvalues of monodromy(A, b, r, T, steps).
FloquetResult floquet(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                      const std::function<Eigen::RowVectorXd(double)>& r, double T, int steps);

}  // namespace inerta::numerics
