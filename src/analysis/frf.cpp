#include "inerta/analysis/frf.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/numerics/finite_difference.hpp"

namespace inerta::analysis {

using cd = std::complex<double>;
using std::numbers::pi;

namespace {

int output_index(const mbs::Model& m, const std::string& name) {
  for (std::size_t k = 0; k < m.outputs.size(); ++k)
    if (m.outputs[k].name == name) return static_cast<int>(k);
  throw ModelError(fmt::format("{}: no output '{}'", m.source, name));
}

int rig_joint(const pantograph::Pantograph& p) {
  const int j = p.rig_joint;
  if (j < 0 || p.model.joints[static_cast<std::size_t>(j)].type != mbs::JointType::Driving)
    throw ModelError(fmt::format("{}: the FRF needs the pantograph's rig joint (pantograph: rig_joint), a driving joint",
                                 p.model.source));
  return j;
}

}  // namespace

Frf frf_linear(const pantograph::Pantograph& p, const std::vector<std::string>& outputs, const std::vector<double>& f) {
  for (double fk : f) require(frequency_rule, fk, "f");
  const mbs::Model& rig = p.model;
  const int n = rig.n_coords(), m = rig.n_constraints(), nz = rig.n_states();
  const int jr = rig_joint(p), row = rig.joints[static_cast<std::size_t>(jr)].row;
  std::vector<int> outs;
  for (const auto& o : outputs) {
    outs.push_back(output_index(rig, o));
    if (rig.outputs[static_cast<std::size_t>(outs.back())].kind != mbs::Output::Kind::Acceleration)
      throw ModelError(fmt::format("output '{}' is not an acceleration", o));
  }
  const mbs::Output Fo = p.rig_force();

  // Equilibrium with the head held, and its multipliers.
  mbs::State x = mbs::assemble(rig, 0.0);
  mbs::static_equilibrium(rig, 0.0, x);
  mbs::Workspace ws(rig);
  mbs::accelerations(rig, 0.0, x, ws);
  const Eigen::VectorXd lambda0 = ws.lambda;
  const Eigen::MatrixXd M = ws.M, Cq = ws.Cq;
  // Central differences (absolute step 1e-6) of [Q − C_qᵀλ0; ż] in y = [q; q̇; z] (t = 0: the rig's
  // motion is the input): K = −∂R/∂q, D = −∂R/∂q̇, Qz = ∂R/∂z and Zq, Zqd, Az the rows of ż.
  auto eval = [&](const Eigen::VectorXd& y) {
    const mbs::State s{y.head(n), y.segment(n, n), y.tail(nz)};
    mbs::evaluate_forces(rig, 0.0, s, ws);
    mbs::evaluate_constraints(rig, 0.0, s, ws);
    Eigen::VectorXd out(n + nz);
    out << ws.Q - ws.Cq.transpose() * lambda0, ws.zd;
    return out;
  };
  Eigen::VectorXd y0(2 * n + nz);
  y0 << x.q, x.qd, x.z;
  const Eigen::MatrixXd J = numerics::central_difference_jacobian(eval, y0, 1e-6, numerics::Step::Absolute);
  const Eigen::MatrixXd K = -J.block(0, 0, n, n), D = -J.block(0, n, n, n), Qz = J.block(0, 2 * n, n, nz),
                        Zq = J.block(n, 0, nz, n), Zqd = J.block(n, n, nz, n), Az = J.block(n, 2 * n, nz, nz);
  Frf out;
  out.f = f;
  out.outputs = outputs;
  out.H.assign(outputs.size(), std::vector<cd>(f.size()));
  Eigen::MatrixXcd S(n + m, n + m);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(n + m);
  rhs[n + row] = 1.0;  // C_q δq = unit displacement of the rig joint
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double w = 2 * pi * f[k];
    const cd iw(0, w);
    Eigen::MatrixXcd dyn = -w * w * M.cast<cd>() + iw * D.cast<cd>() + K.cast<cd>();
    if (nz > 0) {
      Eigen::MatrixXcd G = (iw * Eigen::MatrixXcd::Identity(nz, nz) - Az.cast<cd>())
                               .partialPivLu()
                               .solve((Zq.cast<cd>() + iw * Zqd.cast<cd>()));
      dyn -= Qz.cast<cd>() * G;
    }
    S.topLeftCorner(n, n) = dyn;
    S.topRightCorner(n, m) = Cq.transpose().cast<cd>();
    S.bottomLeftCorner(m, n) = Cq.cast<cd>();
    S.bottomRightCorner(m, m).setZero();
    Eigen::VectorXcd sol = S.fullPivLu().solve(rhs);
    const Eigen::VectorXcd dq = sol.head(n), dl = sol.tail(m);
    // Contact force: the output's linear part in δλ (reaction on the held body, or the multiplier).
    cd F = 0;
    const auto& jt = rig.joints[static_cast<std::size_t>(Fo.index)];
    mbs::ConstraintRow rows[3];
    const int nr = mbs::evaluate_joint(jt, 0.0, rig.frame(x, jt.body_i), rig.frame(x, jt.body_j), rows);
    for (int r = 0; r < nr; ++r) F -= rows[r].gj[Fo.component] * dl[jt.row + r];
    F *= Fo.scale;
    for (std::size_t i = 0; i < outs.size(); ++i) {
      const auto& o = rig.outputs[static_cast<std::size_t>(outs[i])];
      const auto& mk = rig.markers[static_cast<std::size_t>(o.index)];
      cd r = 0;
      if (mk.body >= 0) {
        const mbs::PointKinematics p = mbs::point_kinematics(rig.frame(x, mk.body), mk.u);
        r = dq[3 * mk.body + o.component] + p.Atu[o.component] * dq[3 * mk.body + 2];
      }
      out.H[i][k] = -w * w * r * o.scale / F;
    }
  }
  return out;
}

void check(const SteppedSine& o) {
  require(vc_rule, o.vc, "vc");
  require(cycles_rule, o.cycles, "cycles");
  require(analysed_rule, o.analysed, "analysed");
  if (o.analysed > o.cycles)
    throw InvalidArgument(fmt::format("analysed: {} is more than cycles ({}); expected 1 … cycles", o.analysed, o.cycles));
  require(samples_per_cycle_rule, o.samples_per_cycle, "samples_per_cycle");
}

Frf frf_stepped_sine(const pantograph::Pantograph& p, const std::vector<std::string>& outputs,
                     const std::vector<double>& f, const SteppedSine& o) {
  check(o);
  for (double fk : f) require(frequency_rule, fk, "f");
  const mbs::Model& rig = p.model;
  const int jr = rig_joint(p);
  const mbs::Output Fo = p.rig_force();
  std::vector<int> outs;
  for (const auto& name : outputs) outs.push_back(output_index(rig, name));
  mbs::State x0 = mbs::assemble(rig, 0.0);
  mbs::static_equilibrium(rig, 0.0, x0);
  Frf out;
  out.f = f;
  out.outputs = outputs;
  out.H.assign(outputs.size(), std::vector<cd>(f.size()));
  std::exception_ptr error;
  std::mutex mutex;
  tbb::parallel_for(std::size_t{0}, f.size(), [&](std::size_t k) {
    try {
      mbs::Model m = rig;
      const double w = 2 * pi * f[k], T = 1 / f[k];
      m.joints[static_cast<std::size_t>(jr)].motion = mbs::TimeFunction::sine(o.vc / w, f[k]);
      // From the static equilibrium, with velocities consistent with the imposed motion (V_c at t = 0).
      mbs::State x = x0;
      {
        mbs::Workspace ws(m);
        mbs::evaluate_constraints(m, 0.0, x, ws);
        x.qd = -ws.Cq.completeOrthogonalDecomposition().solve(ws.Ct);
      }
      const double t0 = (o.cycles - o.analysed) * T;
      std::vector<cd> acc(outs.size(), 0.0);
      cd F = 0;
      double last_t = -1;
      std::vector<double> prev(outs.size() + 1, 0.0);
      solve::integrate(
          m, x, 0.0, o.cycles * T, T / o.samples_per_cycle, o.integrator,
          [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
            std::vector<double> v(outs.size() + 1);
            for (std::size_t i = 0; i < outs.size(); ++i)
              v[i] = mbs::evaluate_output(m.outputs[static_cast<std::size_t>(outs[i])], m, t, s, ws);
            v.back() = mbs::evaluate_output(Fo, m, t, s, ws);
            if (last_t >= t0 - 1e-12) {  // trapezoid of v e^{−iωt} over whole analysed cycles
              const double dt = t - last_t;
              const cd e1 = std::exp(cd(0, -w * last_t)), e2 = std::exp(cd(0, -w * t));
              for (std::size_t i = 0; i < outs.size(); ++i) acc[i] += 0.5 * dt * (prev[i] * e1 + v[i] * e2);
              F += 0.5 * dt * (prev.back() * e1 + v.back() * e2);
            }
            prev = v;
            last_t = t;
          },
          true);
      for (std::size_t i = 0; i < outs.size(); ++i) out.H[i][k] = acc[i] / F;
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  });
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace inerta::analysis
