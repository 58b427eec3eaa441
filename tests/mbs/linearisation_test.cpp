// Linearisation about the static equilibrium and modes (spec/02 §2.5, spec/06 §6.3).
#include "inerta/mbs/linearisation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "inerta/pantograph/suspension.hpp"
#include "support/reference_models.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_linearisation {

using namespace inerta;

TEST(Linearisation, OneDofMassStiffnessAndFrequencyAreAnalytic) {
  // spec/01 §1.2, appendix A.1: m_eq = m + (Lb/L0)² b, k_eq = k (Lb/L0)².
  mbs::Model m = io::load_model(inerta::testing::model_path("onedof.yaml"));
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  EXPECT_NEAR(x.q[1], 1.0, 1e-9);
  mbs::LinearModel lin = mbs::linearise(m, x);
  ASSERT_EQ(lin.dof, 1);
  const double r2 = 0.5;  // (Lb/L0)²
  EXPECT_NEAR(lin.M(0, 0), 5 + r2 * 100, 1e-9);
  EXPECT_NEAR(lin.K(0, 0), 1e4 * r2, 1e-3);
  EXPECT_NEAR(lin.C(0, 0), 0.0, 1e-6);
  auto ms = mbs::modes(m, lin);
  ASSERT_EQ(ms.size(), 1u);
  EXPECT_NEAR(ms[0].frequency_hz, testref::onedof_linear_frequency_hz(), 1e-6 * ms[0].frequency_hz);
  EXPECT_NEAR(ms[0].damping_ratio, 0.0, 1e-6);
}

TEST(Linearisation, LinearResponseMatchesNonlinearAtSmallAmplitude) {
  // Two-bar (no excitation), released with a small velocity: the linear model's ξ(t), propagated
  // by RK4, against the nonlinear simulation projected on the same coordinates.
  mbs::Model m = io::load_model(inerta::testing::model_path("twobar.yaml"));
  std::erase_if(m.forces, [](const auto& f) { return f->name() == "F_a"; });
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::LinearModel lin = mbs::linearise(m, x);
  const int d = lin.dof;
  Eigen::VectorXd X = Eigen::VectorXd::Zero(lin.A.rows());
  X(d) = 1e-4;  // ξ̇_1
  mbs::Model moving = m;
  mbs::State x0 = x;
  x0.qd = lin.N * X.segment(d, d);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-11;
  opt.atol = 1e-14;
  std::vector<Eigen::VectorXd> xi_nl;
  solve::integrate(moving, x0, 0.0, 3.0, 0.01, opt, [&](double, const mbs::State& s, const mbs::Workspace&) {
    xi_nl.push_back(lin.Nt * (s.q - x.q));
  });
  const double h = 1e-4;
  double err = 0, amp = 0;
  for (std::size_t k = 0; k < xi_nl.size(); ++k) {
    err = std::max(err, (xi_nl[k] - X.head(d)).cwiseAbs().maxCoeff());
    amp = std::max(amp, X.head(d).cwiseAbs().maxCoeff());
    for (int s = 0; s < 100; ++s) {  // RK4 steps to the next sample
      Eigen::VectorXd k1 = lin.A * X, k2 = lin.A * (X + h / 2 * k1), k3 = lin.A * (X + h / 2 * k2),
                      k4 = lin.A * (X + h * k3);
      X += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  EXPECT_GT(amp, 1e-6);
  EXPECT_LT(err, 1e-3 * amp);
}

TEST(Modes, HsxHasFrameHeadAndFlexibleModesInTheThesisBands) {
  mbs::Model m = pantograph::release_head(io::load_pantograph(inerta::testing::model_path("hsx.yaml")));
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  auto ms = mbs::modes(m, mbs::linearise(m, x));
  std::vector<double> f;
  for (const auto& mode : ms)
    if (mode.eigenvalue.imag() > 0 && mode.frequency_hz < 20) f.push_back(mode.frequency_hz);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_GT(f[0], 0.5);
  EXPECT_LT(f[0], 3.0);  // frame mechanism
  EXPECT_GT(f[1], 4.0);
  EXPECT_LT(f[1], 9.0);  // head on its suspension
  EXPECT_GT(f[2], 8.0);
  EXPECT_LT(f[2], 14.0);  // upper-arm flexibility
}

TEST(Linearisation, JacobianPredictsTheNonlinearRightHandSide) {
  // HSX (free head) with its actuator's network state: for random directions X, the change of the
  // nonlinear right-hand side over ±εX (ε independent of the linearisation's own step) is ε A X.
  mbs::Model m = pantograph::release_head(io::load_pantograph(inerta::testing::model_path("hsx.yaml")));
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  mbs::LinearModel lin = mbs::linearise(m, x);
  ASSERT_EQ(lin.nz, 1);
  const int d = lin.dof, S = static_cast<int>(lin.A.rows());
  mbs::Workspace ws(m);
  auto g = [&](const Eigen::VectorXd& X) {
    mbs::State s{x.q + lin.N * X.head(d), lin.N * X.segment(d, d), x.z + X.tail(lin.nz)};
    mbs::accelerations(m, 0.0, s, ws);
    Eigen::VectorXd out(S);
    out << X.segment(d, d), lin.Nt * ws.qdd, ws.zd;
    return out;
  };
  std::srand(3);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd X = Eigen::VectorXd::Random(S);
    const double eps = 1e-4;
    Eigen::VectorXd fd = (g(eps * X) - g(-eps * X)) / (2 * eps), lin_pred = lin.A * X;
    EXPECT_LT((fd - lin_pred).norm(), 1e-4 * lin_pred.norm());
  }
  // The reduced mass includes the actuator's piston (a point mass) and is symmetric positive definite.
  EXPECT_LT((lin.M - lin.M.transpose()).norm(), 1e-9 * lin.M.norm());
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(lin.M).info(), Eigen::Success);
}
}  // namespace test_mbs_linearisation
