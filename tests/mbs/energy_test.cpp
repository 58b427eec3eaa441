// Energy balance (design.md, invariants): T + Σ stored energy − ∫ Σ power dt is constant for a
// spring–damper–inerter system, with and without the centripetal correction.
#include <gtest/gtest.h>

#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_energy {

using namespace inerta;

namespace {
struct Balance {
  double max_error = 0;     ///< max |E(t) − E(0) − W(t)|
  double energy_scale = 0;  ///< max |E(t) − E(0)|
  double dissipated = 0;
};

Balance balance(const mbs::Model& model, double t_end) {
  solve::IntegratorOptions opt;
  opt.rtol = 1e-11;
  opt.atol = 1e-13;
  Balance b;
  double E0 = 0, W = 0, t_prev = 0, P_prev = 0;
  bool first = true;
  mbs::State x = mbs::assemble(model, 0.0);
  solve::integrate(model, x, 0.0, t_end, 1e-4, opt, [&](double t, const mbs::State& s, const mbs::Workspace&) {
    double E = mbs::kinetic_energy(model, s) + mbs::stored_energy(model, t, s);
    double P = mbs::element_power(model, t, s);
    if (first) {
      E0 = E, first = false;
    } else {
      W += 0.5 * (P + P_prev) * (t - t_prev);  // trapezoid
    }
    b.max_error = std::max(b.max_error, std::abs(E - E0 - W));
    b.energy_scale = std::max(b.energy_scale, std::abs(E - E0));
    b.dissipated = std::min(b.dissipated, W);
    t_prev = t, P_prev = P;
  });
  return b;
}

mbs::Model twobar_with(bool centripetal, bool forced_and_damped) {
  mbs::Model m = io::load_model(inerta::testing::model_path("twobar.yaml"));
  m.options.centripetal = centripetal;
  m.bodies[1].qd0.z() = 2.0;  // start moving
  m.bodies[0].qd0.z() = -1.0;
  if (!forced_and_damped) {
    std::erase_if(m.forces, [](const auto& f) { return f->name() == "c" || f->name() == "F_a"; });
  }
  return m;
}
}  // namespace

TEST(Energy, ConservativeSpringInerterSystemConservesEnergy) {
  // With the correction the inerter stores ½ b l̇² and the system is conservative.
  Balance b = balance(twobar_with(true, false), 5);
  EXPECT_GT(b.energy_scale, 0.0);  // energy moves between bodies, springs and inerter
  EXPECT_LT(b.max_error, 1e-8);
}

TEST(Energy, DampedForcedSystemBalancesWorkAndDissipation) {
  for (bool corr : {true, false}) {
    Balance b = balance(twobar_with(corr, true), 5);
    EXPECT_LT(b.dissipated, -0.1);  // the damper does take energy out
    EXPECT_GT(b.energy_scale, 0.1);
    EXPECT_LT(b.max_error, 1e-5 * b.energy_scale) << "centripetal " << corr;
  }
}

TEST(Energy, WithoutCorrectionTheInerterIsNotConservative) {
  // The 1D form's spurious term does work (that is the error the correction removes).
  mbs::Model m = twobar_with(false, false);
  double E0 = -1, drift = 0;
  mbs::State x = mbs::assemble(m, 0.0);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-12;
  solve::integrate(m, x, 0, 5, 1e-3, opt, [&](double t, const mbs::State& s, const mbs::Workspace&) {
    double E = mbs::kinetic_energy(m, s) + mbs::stored_energy(m, t, s);
    if (E0 < 0) E0 = E;
    drift = std::max(drift, std::abs(E - E0));
  });
  EXPECT_GT(drift, 1e-3);
}
}  // namespace test_mbs_energy
