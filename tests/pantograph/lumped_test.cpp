// Lumped n-mass pantograph (pantograph/lumped.hpp) and the aerodynamic uplift at a running speed
// (pantograph::at_speed, applied by Catenary::couple). Expected values are derived by hand from the
// chain head–k1–m2–k2–m3–k3–ground.
#include "inerta/pantograph/lumped.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "inerta/analysis/modal.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_pantograph_lumped {

using namespace inerta;

namespace {

// The DSA 380 data of models/pantograph-3mass.yaml.
pantograph::LumpedPantographData dsa380() {
  pantograph::LumpedPantographData d;
  d.mass = {7.12, 6.0, 5.8};
  d.stiffness = {9430, 14100, 0.1};
  d.damping = {0, 0, 70};
  d.static_uplift = 70;
  return d;
}

// Undamped natural frequencies (Hz, ascending) of M ẍ + K x = 0.
std::vector<double> frequencies(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  std::vector<double> f;
  for (int i = 0; i < es.eigenvalues().size(); ++i) f.push_back(std::sqrt(es.eigenvalues()[i]) / (2 * std::numbers::pi));
  std::sort(f.begin(), f.end());
  return f;
}

std::vector<double> model_frequencies(const mbs::Model& m) {
  const analysis::ModalAnalysis ma = analysis::modal_analysis(m);
  std::vector<double> f;
  for (const auto& mode : ma.modes) f.push_back(mode.frequency_hz);
  std::sort(f.begin(), f.end());
  return f;
}

double contact_force_at_start(catenary::Coupled& sys) {
  sys.equilibrate();
  double F = NAN;
  sys.advance(1e-3, 1e-3, {}, [&](const catenary::Sample& s) {
    if (s.t == 0) F = s.force;
  });
  return F;
}

}  // namespace

TEST(LumpedPantograph, FreeChainFrequenciesAreTheEigenvaluesOfTheHandAssembledChain) {
  pantograph::LumpedPantographData d = dsa380();
  d.damping = {0, 0, 0};  // undamped: |λ| is the natural frequency
  d.static_uplift = 0;    // free head: nothing holds a constant uplift
  const double k1 = d.stiffness[0], k2 = d.stiffness[1], k3 = d.stiffness[2];
  Eigen::Matrix3d M = Eigen::Vector3d(d.mass[0], d.mass[1], d.mass[2]).asDiagonal();
  Eigen::Matrix3d K;
  K << k1, -k1, 0,  //
      -k1, k1 + k2, -k2,  //
      0, -k2, k2 + k3;
  const std::vector<double> expected = frequencies(M, K);
  pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
  p.model.remove_joint("rig");
  const std::vector<double> f = model_frequencies(p.model);
  ASSERT_EQ(f.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], expected[i], 1e-5 * expected[i]) << "mode " << i + 1;
  // The lowest mode is the whole pantograph on the 0.1 N/m roof spring: about sqrt(k3 / Σm) / 2π.
  EXPECT_NEAR(f[0], std::sqrt(k3 / (7.12 + 6.0 + 5.8)) / (2 * std::numbers::pi), 1e-3 * f[0]);
}

TEST(LumpedPantograph, HeadHeldByTheRigLeavesTheTwoLowerMassesOnThreeSprings) {
  pantograph::LumpedPantographData d = dsa380();
  d.damping = {0, 0, 0};
  const double k1 = d.stiffness[0], k2 = d.stiffness[1], k3 = d.stiffness[2];
  Eigen::Matrix2d M = Eigen::Vector2d(d.mass[1], d.mass[2]).asDiagonal();
  Eigen::Matrix2d K;
  K << k1 + k2, -k2,  //
      -k2, k2 + k3;
  const std::vector<double> expected = frequencies(M, K);
  const std::vector<double> f = model_frequencies(pantograph::make_lumped_pantograph(d).model);
  ASSERT_EQ(f.size(), 2u);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(f[i], expected[i], 1e-5 * expected[i]);
}

TEST(LumpedPantograph, OneMassIsTheTextbookOscillator) {
  pantograph::LumpedPantographData d;
  d.mass = {4};
  d.stiffness = {900};
  d.damping = {0};
  pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
  p.model.remove_joint("rig");
  const std::vector<double> f = model_frequencies(p.model);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0], 15.0 / (2 * std::numbers::pi), 1e-6);  // sqrt(900 / 4) = 15 rad/s
}

TEST(LumpedPantograph, TheRigCarriesTheStaticUpliftLessWhatTheRoofSpringTakes) {
  pantograph::LumpedPantographData d = dsa380();
  d.stiffness[2] = 500;  // a stiff roof spring, so that its share shows
  const pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
  ASSERT_TRUE(p.has_rig());
  mbs::State x = mbs::assemble(p.model, 0.0);
  mbs::static_equilibrium(p.model, 0.0, x);
  mbs::Workspace ws(p.model);
  mbs::accelerations(p.model, 0.0, x, ws);
  const double F = mbs::evaluate_output(p.rig_force(), p.model, 0.0, x, ws);
  // Head held: m3 rises by d3 = F (1/k1 + 1/k2) and the roof spring takes k3 d3, so F = U / (1 + k3 s).
  const double s = 1 / d.stiffness[0] + 1 / d.stiffness[1];
  EXPECT_NEAR(F, d.static_uplift / (1 + d.stiffness[2] * s), 1e-6);
  // The y outputs are the displacements: m3 by d3.
  const int y_m3 = [&] {
    for (std::size_t i = 0; i < p.model.outputs.size(); ++i)
      if (p.model.outputs[i].name == "y_m3") return static_cast<int>(i);
    return -1;
  }();
  ASSERT_GE(y_m3, 0);
  EXPECT_NEAR(mbs::evaluate_output(p.model.outputs[static_cast<std::size_t>(y_m3)], p.model, 0.0, x, ws), F * s, 1e-9);
}

TEST(LumpedPantograph, StaticUpliftAndAerodynamicForceReachTheContact) {
  const double v = 250 / 3.6;
  catenary::LumpedCatenary lc;  // the default of models/catenary.yaml
  lc.span = 60;
  lc.k = {7000, 2100, 350, 140};
  lc.m = {177.3, 0, 0, 0};
  lc.c = {111, 0, 0, 0};
  const catenary::Lumped cat(lc);
  const double kc = 7000 + 2100 + 350 + 140;  // k_c(t = 0): at a mast, every cosine is 1
  for (const double k3 : {0.1, 500.0}) {
    pantograph::LumpedPantographData d = dsa380();
    d.stiffness[2] = k3;
    d.aero_a = 1e-3, d.aero_b = 0.05, d.aero_c = 2;
    const double A = d.aero_a * v * v + d.aero_b * v + d.aero_c, U = d.static_uplift;
    const double s = 1 / d.stiffness[0] + 1 / d.stiffness[1];
    const pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
    ASSERT_TRUE(p.aero.active());
    for (const bool penalty : {false, true}) {
      const double ks = 50e3;
      const catenary::Contact contact{penalty ? catenary::Contact::Kind::Penalty : catenary::Contact::Kind::Bilateral,
                                      ks, 0.0};
      // Head up by F/k_eff (wire, and the penalty overlap), m3 by that plus (F − A) s; m3's balance
      // U = (F − A) + k3 d3 gives F (1 + k3/k_eff + k3 s) = U + A + k3 A s.
      const double keff = penalty ? 1 / (1 / kc + 1 / ks) : kc;
      const double expected = (U + A + k3 * A * s) / (1 + k3 / keff + k3 * s);
      auto sys = cat.couple(p, contact, v);
      EXPECT_NEAR(contact_force_at_start(*sys), expected, 1e-6 * expected) << "k3 = " << k3 << ", penalty " << penalty;
      if (k3 == 0.1) {
        EXPECT_NEAR(expected, U + A, 0.01);  // the DSA 380 roof spring takes next to nothing
      }
    }
  }
}

TEST(LumpedPantograph, AtSpeedAddsExactlyTheAerodynamicForceOnTheHeadOnce) {
  pantograph::LumpedPantographData d = dsa380();
  d.aero_a = 0.0025, d.aero_b = -0.1, d.aero_c = 3;
  const pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
  const double v = 80;
  const pantograph::Pantograph q = pantograph::at_speed(p, v);
  EXPECT_FALSE(q.aero.active());  // applied
  EXPECT_EQ(q.model.forces.size(), p.model.forces.size() + 1);
  mbs::State x = mbs::assemble(p.model, 0.0);
  mbs::Workspace wp(p.model), wq(q.model);
  mbs::evaluate_forces(p.model, 0.0, x, wp);
  mbs::evaluate_forces(q.model, 0.0, x, wq);
  Eigen::VectorXd dQ = wq.Q - wp.Q;
  const int head_y = q.model.q_adr(0) + 1;
  EXPECT_NEAR(dQ[head_y], 0.0025 * 80 * 80 - 0.1 * 80 + 3, 1e-12);  // 16 − 8 + 3 = 11 N
  dQ[head_y] = 0;
  EXPECT_EQ(dQ.cwiseAbs().maxCoeff(), 0.0);
  // Applying it again adds nothing; a pantograph without aerodynamics is returned as it is.
  EXPECT_EQ(pantograph::at_speed(q, v).model.forces.size(), q.model.forces.size());
  pantograph::LumpedPantographData still = dsa380();
  const pantograph::Pantograph r = pantograph::make_lumped_pantograph(still);
  EXPECT_FALSE(r.aero.active());
  EXPECT_EQ(pantograph::at_speed(r, v).model.forces.size(), r.model.forces.size());
  EXPECT_THROW(pantograph::at_speed(p, NAN), InvalidArgument);
  EXPECT_THROW(pantograph::at_speed(p, -1), InvalidArgument);
}

TEST(LumpedPantograph, ValidateNamesTheOffendingValueAsInTheFile) {
  auto parameter = [](const pantograph::LumpedPantographData& d) {
    try {
      d.validate();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return std::string("(accepted)");
  };
  pantograph::LumpedPantographData d = dsa380();
  EXPECT_EQ(parameter(d), "(accepted)");
  d.mass[1] = -6;
  EXPECT_EQ(parameter(d), "masses[1]");
  d = dsa380();
  d.mass[0] = 0;
  EXPECT_EQ(parameter(d), "masses[0]");
  d = dsa380();
  d.stiffness[2] = NAN;
  EXPECT_EQ(parameter(d), "stiffness[2]");
  d = dsa380();
  d.damping = {0, 0};
  EXPECT_EQ(parameter(d), "damping");
  d = dsa380();
  d.stiffness.push_back(1);
  EXPECT_EQ(parameter(d), "stiffness");
  d = dsa380();
  d.static_uplift = -70;
  EXPECT_EQ(parameter(d), "static_uplift");
  d = dsa380();
  d.aero_b = INFINITY;
  EXPECT_EQ(parameter(d), "aerodynamic.b");
  d.mass.clear();
  EXPECT_EQ(parameter(d), "masses");
  EXPECT_THROW(pantograph::make_lumped_pantograph(d), InvalidArgument);
}

TEST(LumpedPantograph, ThePeriodicMethodTakesTheAerodynamicUpliftOfEachSpeed) {
  catenary::LumpedCatenary lc;
  lc.span = 60;
  lc.k = {7000, 2100, 350, 140};
  lc.m = {177.3, 0, 0, 0};
  lc.c = {111, 0, 0, 0};
  const catenary::Lumped cat(lc);
  pantograph::LumpedPantographData d = dsa380();
  d.aero_a = 4e-3, d.aero_c = 1;  // 1 + 0.004 v² N: 5 N at 31.6 m/s, 21 N at 70.7 m/s
  const pantograph::Pantograph p = pantograph::make_lumped_pantograph(d);
  const std::vector<double> v{std::sqrt(1000.0), std::sqrt(5000.0)};
  const auto r = analysis::sweep_periodic(p, cat, {}, v, 8);
  ASSERT_EQ(r.size(), 2u);
  // Mean contact force = U + A(v) − k3 · (mean rise of m3, centimetres): within 0.01 N of U + A(v).
  EXPECT_NEAR(r[0].stats.mean, 70 + 5, 0.01);
  EXPECT_NEAR(r[1].stats.mean, 70 + 21, 0.01);
  EXPECT_GT(r[1].stats.std, 0);
}
}  // namespace test_pantograph_lumped
