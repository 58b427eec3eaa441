// Central-difference Jacobians against analytic ones: second-order convergence, the two step
// rules (seen through the exact error of a cubic), writing into a block, and the argument checks.
#include "inerta/numerics/finite_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_finite_difference {

using namespace inerta::numerics;

namespace {

// f: R³ → R², smooth and nonlinear in every coordinate.
Eigen::VectorXd f(const Eigen::VectorXd& x) {
  Eigen::VectorXd y(2);
  y << std::sin(x[0]) * x[1] * x[1] + std::exp(0.5 * x[2]), x[0] * x[1] * x[2] + std::cos(x[1]) / (1 + x[0] * x[0]);
  return y;
}

Eigen::MatrixXd df(const Eigen::VectorXd& x) {
  const double r = 1 + x[0] * x[0];
  Eigen::MatrixXd J(2, 3);
  J << std::cos(x[0]) * x[1] * x[1], 2 * std::sin(x[0]) * x[1], 0.5 * std::exp(0.5 * x[2]),  //
      x[1] * x[2] - 2 * x[0] * std::cos(x[1]) / (r * r), x[0] * x[2] - std::sin(x[1]) / r, x[0] * x[1];
  return J;
}

}  // namespace

TEST(FiniteDifference, MatchesTheAnalyticJacobianWithSecondOrderError) {
  const Eigen::Vector3d x(0.7, -1.3, 0.4);
  const Eigen::MatrixXd exact = df(x);
  double previous = 0;
  for (double h : {4e-2, 2e-2, 1e-2, 5e-3}) {
    const Eigen::MatrixXd J = central_difference_jacobian(f, x, h, Step::Absolute);
    ASSERT_EQ(J.rows(), 2);
    ASSERT_EQ(J.cols(), 3);
    const double err = (J - exact).cwiseAbs().maxCoeff();
    EXPECT_LT(err, 2 * h * h) << "h = " << h;  // |f'''|/6 ≲ 1 here
    if (previous > 0) {
      EXPECT_NEAR(previous / err, 4.0, 0.2) << "halving h must quarter the error, h = " << h;
    }
    previous = err;
  }
  // At the usual step the truncation (~1e-12) and rounding (~1e-10) errors are both small.
  EXPECT_LT((central_difference_jacobian(f, x, 1e-6, Step::Relative) - exact).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(FiniteDifference, StepRulesAbsoluteAndRelative) {
  // For y_k = x_k³ the central difference is exactly 3 x_k² + h_k², so the error shows the step:
  // h (absolute) or h · max(1, |x_k|) (relative).
  auto cube = [](const Eigen::VectorXd& x) { return Eigen::VectorXd(x.array().cube()); };
  const Eigen::Vector3d x(0.5, -200.0, 30.0);
  const double h = 1e-3;
  const Eigen::MatrixXd Ja = central_difference_jacobian(cube, x, h, Step::Absolute);
  const Eigen::MatrixXd Jr = central_difference_jacobian(cube, x, h, Step::Relative);
  for (int k = 0; k < 3; ++k) {
    const double exact = 3 * x[k] * x[k], hr = h * std::max(1.0, std::abs(x[k]));
    EXPECT_EQ(hr, difference_step(h, Step::Relative, x[k]));
    EXPECT_EQ(h, difference_step(h, Step::Absolute, x[k]));
    EXPECT_NEAR(Ja(k, k) - exact, h * h, 1e-6 * h * h + 1e-12 * exact / h) << k;
    EXPECT_NEAR(Jr(k, k) - exact, hr * hr, 1e-6 * hr * hr + 1e-12 * exact / hr) << k;
    for (int j = 0; j < 3; ++j) {
      if (j == k) continue;
      EXPECT_EQ(Ja(j, k), 0.0);
      EXPECT_EQ(Jr(j, k), 0.0);
    }
  }
}

TEST(FiniteDifference, FillsABlockAndEvaluatesEachSideOnce) {
  // Written into the left columns of a larger matrix (as the equilibrium Newton's [J_q, −C_qᵀ]):
  // the other columns are untouched; 2n evaluations, none at x itself.
  const Eigen::Vector3d x(0.2, 0.9, -0.6);
  Eigen::MatrixXd big = Eigen::MatrixXd::Constant(2, 5, 7.0);
  int calls = 0;
  auto counted = [&](const Eigen::VectorXd& y) {
    ++calls;
    EXPECT_NE((y - x).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(((y - x).array() != 0).count(), 1);  // one coordinate at a time
    return f(y);
  };
  central_difference_jacobian(counted, x, 1e-6, Step::Relative, big.leftCols(3));
  EXPECT_EQ(calls, 6);
  EXPECT_EQ(big.leftCols(3), central_difference_jacobian(f, x, 1e-6, Step::Relative));
  EXPECT_TRUE((big.rightCols(2).array() == 7.0).all());
  // No coordinates: an empty Jacobian, f never called.
  calls = 0;
  EXPECT_EQ(central_difference_jacobian(counted, Eigen::VectorXd(0), 1e-6, Step::Absolute).size(), 0);
  EXPECT_EQ(calls, 0);
}

TEST(FiniteDifference, RejectsBadArguments) {
  const Eigen::Vector3d x(1, 2, 3);
  EXPECT_THROW(central_difference_jacobian(f, x, 0.0, Step::Absolute), std::invalid_argument);
  EXPECT_THROW(central_difference_jacobian(f, x, -1e-6, Step::Relative), std::invalid_argument);
  Eigen::MatrixXd wrong_cols(2, 2), wrong_rows(3, 3);
  EXPECT_THROW(central_difference_jacobian(f, x, 1e-6, Step::Absolute, wrong_cols), std::invalid_argument);
  EXPECT_THROW(central_difference_jacobian(f, x, 1e-6, Step::Absolute, wrong_rows), std::invalid_argument);
  // A function whose length changes between evaluations.
  int calls = 0;
  auto ragged = [&](const Eigen::VectorXd&) { return Eigen::VectorXd::Zero(++calls > 2 ? 3 : 2).eval(); };
  EXPECT_THROW(central_difference_jacobian(ragged, x, 1e-6, Step::Absolute), std::invalid_argument);
}
}  // namespace test_numerics_finite_difference
