// Floquet multipliers of a rank-one periodic system (numerics/floquet.hpp), on Mathieu's equation
//   x'' + (δ + ε cos t) x = 0,  A = [0 1; −δ 0],  b = [0; 1],  r(t) = [−ε cos t, 0],  T = 2π.
#include "inerta/numerics/floquet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "inerta/error.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_floquet {

namespace {

using inerta::numerics::floquet;
using inerta::numerics::monodromy;

constexpr double T = 2 * std::numbers::pi;

struct Mathieu {
  Eigen::MatrixXd A = Eigen::MatrixXd(2, 2);
  Eigen::VectorXd b = Eigen::Vector2d(0, 1);
  double eps;
  Mathieu(double delta, double e) : eps(e) { A << 0, 1, -delta, 0; }
  Eigen::RowVectorXd r(double t) const { return Eigen::RowVector2d(-eps * std::cos(t), 0); }
  Eigen::MatrixXd At(double t) const { return A + b * r(t); }
};

// The reference: classical RK4 on Φ' = A(t) Φ with many steps (an independent formulation).
Eigen::MatrixXd rk4_monodromy(const Mathieu& m, int steps) {
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(2, 2);
  const double h = T / steps;
  for (int k = 0; k < steps; ++k) {
    const double t = k * h;
    const Eigen::MatrixXd k1 = m.At(t) * Phi, k2 = m.At(t + h / 2) * (Phi + h / 2 * k1),
                          k3 = m.At(t + h / 2) * (Phi + h / 2 * k2), k4 = m.At(t + h) * (Phi + h * k3);
    Phi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return Phi;
}

TEST(Floquet, MonodromyAgreesWithRungeKutta) {
  for (auto [delta, eps] : {std::pair{0.5, 0.1}, {0.25, 0.1}, {1.3, 0.6}, {2.0, 0.05}}) {
    const Mathieu m(delta, eps);
    const Eigen::MatrixXd P = monodromy(m.A, m.b, [&](double t) { return m.r(t); }, T, 4096);
    const Eigen::MatrixXd R = rk4_monodromy(m, 20000);
    EXPECT_LT((P - R).norm(), 1e-5 * R.norm()) << "delta " << delta << " eps " << eps;
    // Liouville: det Φ(T) = exp(∫ tr A) = 1 (tr A(t) = 0).
    EXPECT_NEAR(P.determinant(), 1.0, 1e-10);
  }
}

TEST(Floquet, DefectiveMatrixTakesTheDenseFormAndAgrees) {
  // A Jordan block (no eigenbasis) with a periodic coupling: against RK4 on Φ' = (A + b r(t)) Φ.
  Eigen::MatrixXd A(2, 2);
  A << -0.2, 1, 0, -0.2;
  const Eigen::Vector2d b(0, 1);
  auto r = [](double t) { return Eigen::RowVector2d(-0.3 * std::cos(t), 0.1 * std::sin(2 * t)).eval(); };
  Eigen::MatrixXd R = Eigen::MatrixXd::Identity(2, 2);
  const int n = 20000;
  const double h = T / n;
  auto At = [&](double t) { return Eigen::MatrixXd(A + b * r(t)); };
  for (int k = 0; k < n; ++k) {
    const double t = k * h;
    const Eigen::MatrixXd k1 = At(t) * R, k2 = At(t + h / 2) * (R + h / 2 * k1), k3 = At(t + h / 2) * (R + h / 2 * k2),
                          k4 = At(t + h) * (R + h * k3);
    R += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_LT((monodromy(A, b, r, T, 4096) - R).norm(), 1e-5 * R.norm());
}

TEST(Floquet, SecondOrderInTheStep) {
  const Mathieu m(0.7, 0.4);
  const Eigen::MatrixXd R = rk4_monodromy(m, 40000);
  auto err = [&](int n) { return (monodromy(m.A, m.b, [&](double t) { return m.r(t); }, T, n) - R).norm(); };
  const double e1 = err(64), e2 = err(128);
  EXPECT_NEAR(e1 / e2, 4.0, 0.4);  // halving h quarters the error
}

TEST(Floquet, MathieuStabilityChart) {
  // Inside the first instability tongue |δ − 1/4| < ε/2 (small ε): a multiplier > 1.
  EXPECT_FALSE(floquet(Mathieu(0.25, 0.1).A, Mathieu(0.25, 0.1).b, [](double t) { return Mathieu(0.25, 0.1).r(t); }, T, 256)
                   .stable());
  EXPECT_FALSE(floquet(Mathieu(1.0, 0.3).A, Mathieu(1.0, 0.3).b, [](double t) { return Mathieu(1.0, 0.3).r(t); }, T, 256)
                   .stable());  // second tongue, around δ = 1
  // Between the tongues the undamped equation is marginally stable: |μ| = 1 to rounding, so with a
  // little damping (x'' + 0.02 x' + ...) every |μ| < 1.
  Mathieu m(0.5, 0.1);
  m.A(1, 1) = -0.02;
  const auto f = floquet(m.A, m.b, [&](double t) { return m.r(t); }, T, 256);
  EXPECT_TRUE(f.stable());
  EXPECT_NEAR(f.largest, std::exp(-0.01 * T), 1e-3);  // |μ|² = det Φ = e^{−0.02 T} for complex multipliers
  // Sorted by modulus, largest first.
  const auto g = floquet(Mathieu(0.25, 0.1).A, Mathieu(0.25, 0.1).b, [](double t) { return Mathieu(0.25, 0.1).r(t); }, T, 256);
  EXPECT_GE(std::abs(g.multipliers[0]), std::abs(g.multipliers[1]));
  EXPECT_DOUBLE_EQ(g.largest, std::abs(g.multipliers[0]));
}

TEST(Floquet, ConstantSystemGivesTheExponential) {
  // r = 0: Φ(T) = e^{AT}, multipliers e^{λT}.
  Eigen::MatrixXd A(2, 2);
  A << -0.3, 0, 0, -1.2;
  const auto f = floquet(A, Eigen::Vector2d(1, 1), [](double) { return Eigen::RowVectorXd::Zero(2).eval(); }, 2.0, 16);
  EXPECT_NEAR(f.largest, std::exp(-0.6), 1e-12);
}

TEST(Floquet, BadArgumentsAreRefused) {
  const Mathieu m(0.5, 0.1);
  auto r = [&](double t) { return m.r(t); };
  EXPECT_THROW(monodromy(m.A, m.b, r, 0.0, 64), inerta::InvalidArgument);
  EXPECT_THROW(monodromy(m.A, m.b, r, NAN, 64), inerta::InvalidArgument);
  EXPECT_THROW(monodromy(m.A, m.b, r, T, 4), inerta::InvalidArgument);
  EXPECT_THROW(monodromy(m.A, Eigen::Vector3d(0, 1, 0), r, T, 64), inerta::InvalidArgument);
  EXPECT_THROW(monodromy(m.A, m.b, [](double) { return Eigen::RowVector3d(0, 0, 0).eval(); }, T, 64),
               inerta::InvalidArgument);
  EXPECT_THROW(monodromy(m.A, m.b, [](double) { return Eigen::RowVector2d(NAN, 0).eval(); }, T, 64),
               inerta::NumericalError);
}

}  // namespace

TEST(Floquet, SharedBasisWithFixedRowsAgreesWithRungeKutta) {
  // The sweep form: A decomposed once (FloquetBasis) and r(t) = c(t)ᵀ R over fixed rows, reused for
  // several periods, against RK4 on the same system; and a defective A through the same call.
  const Mathieu m(0.5, 0.0);
  const inerta::numerics::FloquetBasis basis(m.A);
  EXPECT_TRUE(basis.diagonal());
  Eigen::MatrixXd R(2, 2);
  R << 1, 0, 0, 1;  // r = [c0, c1]
  for (double eps : {0.1, 0.6}) {
    const Mathieu me(0.5, eps);
    const Eigen::MatrixXd P = inerta::numerics::monodromy(
        basis, m.b, R, [&](double t) { return Eigen::VectorXd(Eigen::Vector2d(-eps * std::cos(t), 0)); }, T, 4096);
    const Eigen::MatrixXd ref = rk4_monodromy(me, 20000);
    EXPECT_LT((P - ref).norm(), 1e-5 * ref.norm()) << "eps " << eps;
    // The multipliers at the sweep's 256 steps against those of the RK4 monodromy (second order: 1e-3).
    const auto f = inerta::numerics::floquet(
        basis, m.b, R, [&](double t) { return Eigen::VectorXd(Eigen::Vector2d(-eps * std::cos(t), 0)); }, T, 256);
    EXPECT_NEAR(f.largest, ref.eigenvalues().cwiseAbs().maxCoeff(), 1e-3) << "eps " << eps;
  }
  Eigen::MatrixXd J(2, 2);
  J << -0.2, 1, 0, -0.2;
  EXPECT_FALSE(inerta::numerics::FloquetBasis(J).diagonal());
  // c(t) of the wrong size is an error, not a read past the end.
  EXPECT_THROW(inerta::numerics::monodromy(basis, m.b, R, [](double) { return Eigen::VectorXd(Eigen::Vector3d(1, 2, 3)); }, T, 16),
               inerta::InvalidArgument);
}
}  // namespace test_numerics_floquet
