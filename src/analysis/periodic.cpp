#include "inerta/analysis/periodic.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/numerics/finite_difference.hpp"
#include "inerta/numerics/floquet.hpp"

namespace inerta::analysis {

using cd = std::complex<double>;

// Splitting steps per period of the Floquet check: second order in the step (tests/numerics/floquet_test.cpp);
// the catenary's harmonics up to 3 per span get ≥ 85 steps per cycle.
constexpr int floquet_steps = 256;

std::vector<SpeedResult> sweep_periodic(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                                        const catenary::Contact& contact, const std::vector<double>& speeds, int H) {
  require(harmonics_rule, H, "harmonics");
  for (double v : speeds)
    require(speed_rule, v, "speeds");
  if (pantograph.aero.active()) {  // the aerodynamic uplift depends on the speed: one linearisation per speed
    std::vector<SpeedResult> out(speeds.size());
    tbb::parallel_for(std::size_t{0}, speeds.size(), [&](std::size_t s) {
      out[s] = sweep_periodic(pantograph::at_speed(pantograph, speeds[s]), catenary, contact, {speeds[s]}, H).front();
    });
    return out;
  }
  const catenary::LumpedCatenary* point = catenary.point_model();
  if (!point)
    throw ModelError(fmt::format("the periodic method needs a point model of the catenary (the lumped catenary); the {} "
                                 "has none: use the time method",
                                 catenary.describe()));
  const catenary::LumpedCatenary& cat = *point;
  if (cat.m[1] != 0 || cat.m[2] != 0 || cat.m[3] != 0)
    throw ModelError("the periodic method supports stiffness and damping harmonics only (mc1..mc3 must be 0)");
  catenary::LumpedCatenary mean = cat;
  for (int i = 1; i <= 3; ++i) mean.k[static_cast<std::size_t>(i)] = mean.c[static_cast<std::size_t>(i)] = 0;
  const catenary::LumpedCoupling lc = catenary::couple_lumped(pantograph, mean, contact, 1.0);
  const mbs::Model& m = lc.model;
  const int wire = lc.wire_body, wy = lc.wire_y;
  // The same model with a unit upward probe force on the wire: the input direction B and Λ_f.
  mbs::Model probe = m;
  probe.forces.push_back(std::make_shared<mbs::PointForce>("probe", wire, mbs::Vec2::Zero(), mbs::Vec2(0, 1),
                                                           mbs::TimeFunction::constant(1.0)));
  probe.finalize();

  mbs::State xe = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, xe);
  const mbs::LinearModel L = mbs::linearise(m, xe);
  const int d = L.dof, nz = L.nz, S = 2 * d + nz;
  const double ys = xe.q[wy] - lc.y_unloaded;  // static uplift

  mbs::Workspace ws(m), wp(probe);
  auto state_of = [&](const Eigen::VectorXd& X) {
    return mbs::State{xe.q + L.N * X.head(d), L.N * X.segment(d, d), xe.z + X.tail(nz)};
  };
  auto F_of = [&](const mbs::Model& model, mbs::Workspace& w, const mbs::State& s) {
    mbs::accelerations(model, 0.0, s, w);
    return mbs::evaluate_output(lc.contact_force, model, 0.0, s, w);
  };
  const Eigen::VectorXd X0 = Eigen::VectorXd::Zero(S);
  const double F_s = F_of(m, ws, state_of(X0));
  const Eigen::VectorXd qdd0 = ws.qdd, zd0 = ws.zd;
  const double F_p = F_of(probe, wp, state_of(X0));
  Eigen::VectorXd B(S);  // response of [ξ̇; ξ̈; ż] to a unit wire force
  B << Eigen::VectorXd::Zero(d), L.Nt * (wp.qdd - qdd0), wp.zd - zd0;
  const double Lf = F_p - F_s;
  // Λ = ∂F/∂X at X = 0 (central differences, h = 1e-6).
  const Eigen::RowVectorXd LX = numerics::central_difference_jacobian(
      [&](const Eigen::VectorXd& X) { return Eigen::VectorXd::Constant(1, F_of(m, ws, state_of(X))); }, X0, 1e-6,
      numerics::Step::Absolute);
  // Wire displacement and velocity as rows over X.
  Eigen::RowVectorXd P = Eigen::RowVectorXd::Zero(S), Pd = Eigen::RowVectorXd::Zero(S);
  P.head(d) = L.N.row(wy);
  Pd.segment(d, d) = L.N.row(wy);

  auto coeff = [](const std::array<double, 4>& a, int m) {  // Fourier coefficient of Σ a_i cos(iΩt)
    const int k = std::abs(m);
    return (k >= 1 && k <= 3) ? 0.5 * a[static_cast<std::size_t>(k)] : 0.0;
  };
  // Hill's method reduced to the wire force: X_h = (ihΩ − A)⁻¹ B f_h, so with the transfer
  // functions g_h = P(ihΩ − A)⁻¹B (uplift), gd_h (its rate) and gF_h = Λ(ihΩ − A)⁻¹B + Λ_f (contact
  // force), the harmonics f_h of the wire force solve a (2H+1)² system:
  //   f_h + Σ_j (Δk_{h−j} g_j + Δc_{h−j} gd_j) f_j = −y_s Δk_h,   F_h = gF_h f_h (+ F_s at h = 0).
  const int nh = 2 * H + 1;
  // The Floquet check's A is the same at every speed: decomposed once; r(t) = −(Δk(t) P + Δc(t) Pd).
  const numerics::FloquetBasis basis(L.A);
  Eigen::MatrixXd PPd(2, S);
  PPd << P, Pd;
  std::vector<SpeedResult> out(speeds.size());
  tbb::parallel_for(std::size_t{0}, speeds.size(), [&](std::size_t s) {
    const double W = 2 * std::numbers::pi * speeds[s] / cat.span;
    std::vector<cd> g(static_cast<std::size_t>(nh)), gd(g), gF(g);
    for (int a = 0; a < nh; ++a) {
      const Eigen::VectorXcd x =
          (cd(0, (a - H) * W) * Eigen::MatrixXcd::Identity(S, S) - L.A.cast<cd>()).partialPivLu().solve(B.cast<cd>());
      g[static_cast<std::size_t>(a)] = (P.cast<cd>() * x)(0);
      gd[static_cast<std::size_t>(a)] = (Pd.cast<cd>() * x)(0);
      gF[static_cast<std::size_t>(a)] = (LX.cast<cd>() * x)(0) + Lf;
    }
    Eigen::MatrixXcd Sys = Eigen::MatrixXcd::Identity(nh, nh);
    Eigen::VectorXcd rhs(nh);
    for (int a = 0; a < nh; ++a) {
      const int h = a - H;
      rhs[a] = -ys * coeff(cat.k, h);
      for (int b = 0; b < nh; ++b) {
        const int j = b - H;
        Sys(a, b) += coeff(cat.k, h - j) * g[static_cast<std::size_t>(b)] +
                     coeff(cat.c, h - j) * gd[static_cast<std::size_t>(b)];
      }
    }
    // Stability of the periodic solution (issue 15): the homogeneous part Ẋ = (A − B(Δk(t) P + Δc(t) Pd)) X.
    const numerics::FloquetResult fl = numerics::floquet(
        basis, B, PPd,
        [&](double t) {
          double dk = 0, dc = 0;
          for (std::size_t i = 1; i <= 3; ++i)
            dk += cat.k[i] * std::cos(static_cast<double>(i) * W * t), dc += cat.c[i] * std::cos(static_cast<double>(i) * W * t);
          return Eigen::VectorXd(Eigen::Vector2d(-dk, -dc));
        },
        2 * std::numbers::pi / W, floquet_steps);
    const Eigen::VectorXcd f = Sys.partialPivLu().solve(rhs);
    std::vector<cd> Fh(static_cast<std::size_t>(nh));
    for (int a = 0; a < nh; ++a)
      Fh[static_cast<std::size_t>(a)] = gF[static_cast<std::size_t>(a)] * f[a] + (a == H ? F_s : 0.0);
    // Time history over one period and its statistics.
    SpeedResult r;
    r.speed = speeds[s];
    r.spans = 1;
    const int np = 400;
    std::vector<double> F(np);
    for (int k = 0; k < np; ++k) {
      const double t = k * (2 * std::numbers::pi / W) / np;
      cd v = 0;
      for (int a = 0; a < nh; ++a) v += Fh[static_cast<std::size_t>(a)] * std::exp(cd(0, (a - H) * W * t));
      F[static_cast<std::size_t>(k)] = v.real();
    }
    r.stats = statistics(F);
    r.F = F;
    r.floquet = fl.largest;
    if (!r.stable()) {  // the periodic solution exists but is not reached: no statistics
      const double nan = std::numeric_limits<double>::quiet_NaN();
      r.stats.mean = r.stats.std = r.stats.max = r.stats.min = r.stats.stat_max = r.stats.stat_min = nan;
      r.stats.loss_pct = nan;
    }
    out[s] = std::move(r);
  });
  return out;
}

}  // namespace inerta::analysis
