#pragma once
// Central-difference Jacobian of a vector function f: Rⁿ → Rᵐ, one coordinate perturbed at a time:
//
//   J(:, k) = (f(x + h_k e_k) − f(x − h_k e_k)) / (2 h_k),   error O(h_k²) for f three times
//   differentiable (the h_k² f'''/6 term of the Taylor series), plus rounding O(ε |f| / h_k),
//
// with h_k = h (Step::Absolute: coordinates of one scale, e.g. perturbations about 0) or
// h_k = h · max(1, |x_k|) (Step::Relative: coordinates of mixed magnitude). f is called 2n times,
// serially, in the order x + h_0 e_0, x − h_0 e_0, x + h_1 e_1, …, so f may use a shared workspace.
// The lower point is formed as (x_k + h_k) − 2 h_k, the form the static-equilibrium Newton has
// always used (it can differ from x_k − h_k in the last bit); at x_k = 0 it is exactly −h_k.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace inerta::numerics {

enum class Step {
  Absolute,  ///< h_k = h
  Relative,  ///< h_k = h · max(1, |x_k|)
};

/// The step h_k for coordinate value x_k.
inline double difference_step(double h, Step rule, double x_k) {
  return rule == Step::Relative ? h * std::max(1.0, std::abs(x_k)) : h;
}

namespace detail {
// The 2n evaluations; sink(k, f(x + h_k e_k), f(x − h_k e_k), h_k) receives column k's pair.
template <class F, class Sink>
void central_differences(F& f, const Eigen::VectorXd& x, double h, Step rule, Sink&& sink) {
  if (!(h > 0)) throw std::invalid_argument("central_difference_jacobian: the step h must be > 0");
  Eigen::VectorXd xk = x;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double hk = difference_step(h, rule, x[k]);
    xk[k] = x[k] + hk;
    const Eigen::VectorXd fp = f(std::as_const(xk));
    xk[k] -= 2 * hk;
    const Eigen::VectorXd fm = f(std::as_const(xk));
    xk[k] = x[k];
    sink(k, fp, fm, hk);
  }
}
}  // namespace detail

/// Writes the m × n Jacobian of f at x into J (already m × n: a matrix or a block of one).
/// f(const Eigen::VectorXd&) returns an Eigen vector of length m. Throws std::invalid_argument if
/// h ≤ 0, if J has not x.size() columns or if a value of f has not J.rows() entries.
template <class F>
void central_difference_jacobian(F&& f, const Eigen::VectorXd& x, double h, Step rule,
                                 Eigen::Ref<Eigen::MatrixXd> J) {
  if (J.cols() != x.size())
    throw std::invalid_argument("central_difference_jacobian: J needs one column per coordinate of x");
  detail::central_differences(f, x, h, rule,
                              [&](Eigen::Index k, const Eigen::VectorXd& fp, const Eigen::VectorXd& fm, double hk) {
                                if (fp.size() != J.rows() || fm.size() != J.rows())
                                  throw std::invalid_argument(
                                      "central_difference_jacobian: a value of f has not J.rows() entries");
                                J.col(k) = (fp - fm) / (2 * hk);
                              });
}

/// The Jacobian of f at x as a new matrix, m taken from f's first value (n = 0: a 0 × 0 matrix).
/// Throws std::invalid_argument if h ≤ 0 or if f's length changes between evaluations.
template <class F>
Eigen::MatrixXd central_difference_jacobian(F&& f, const Eigen::VectorXd& x, double h, Step rule) {
  Eigen::MatrixXd J(0, x.size());
  detail::central_differences(f, x, h, rule,
                              [&](Eigen::Index k, const Eigen::VectorXd& fp, const Eigen::VectorXd& fm, double hk) {
                                if (k == 0) J.resize(fp.size(), x.size());
                                if (fp.size() != J.rows() || fm.size() != J.rows())
                                  throw std::invalid_argument(
                                      "central_difference_jacobian: f's length changes between evaluations");
                                J.col(k) = (fp - fm) / (2 * hk);
                              });
  return J;
}

}  // namespace inerta::numerics
