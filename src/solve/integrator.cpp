#include "inerta/solve/integrator.hpp"

#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/mbs/dynamics.hpp"

namespace inerta::solve {

Method parse_method(const std::string& name) {
  if (name == "bdf") return Method::Bdf;
  if (name == "rk") return Method::Rk;
  throw std::invalid_argument("unknown integrator '" + name + "' (expected bdf or rk)");
}

const char* method_name(Method m) { return m == Method::Bdf ? "bdf (CVODE BDF)" : "rk (ARKODE Dormand-Prince 5(4))"; }

namespace {

struct Problem {
  const mbs::Model& model;
  mbs::State x;
  mbs::Workspace ws;
  int n, nz;
  std::exception_ptr error;
  std::string solver_message;
};

void load_state(const double* y, int n, int nz, mbs::State& x) {
  x.q = Eigen::Map<const Eigen::VectorXd>(y, n);
  x.qd = Eigen::Map<const Eigen::VectorXd>(y + n, n);
  x.z = Eigen::Map<const Eigen::VectorXd>(y + 2 * n, nz);
}

// ẏ = [q̇; q̈(q, q̇, t)]
int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* p = static_cast<Problem*>(user);
  try {
    load_state(N_VGetArrayPointer(y), p->n, p->nz, p->x);
    mbs::accelerations(p->model, t, p->x, p->ws);
    double* yd = N_VGetArrayPointer(ydot);
    Eigen::Map<Eigen::VectorXd>(yd, p->n) = p->x.qd;
    Eigen::Map<Eigen::VectorXd>(yd + p->n, p->n) = p->ws.qdd;
    Eigen::Map<Eigen::VectorXd>(yd + 2 * p->n, p->nz) = p->ws.zd;
    return 0;
  } catch (const NumericalError& e) {  // with the simulated time, when the message has none
    const std::string m = e.what();
    p->error = m.starts_with("t = ") ? std::current_exception()
                                     : std::make_exception_ptr(NumericalError(fmt::format("t = {:.6g} s: {}", t, m)));
    return -1;
  } catch (...) {
    p->error = std::current_exception();
    return -1;  // unrecoverable
  }
}

void error_handler(int, const char*, const char*, char* msg, void* user) {
  static_cast<Problem*>(user)->solver_message = msg ? msg : "";
}

// RAII owner of the SUNDIALS objects.
struct Sundials {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  Method method;
  explicit Sundials(Method m) : method(m) {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  }
  ~Sundials() {
    if (mem) (method == Method::Bdf) ? CVodeFree(&mem) : ERKStepFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

// Struts passing through zero length between two steps (issue 15): the terminal vector r reverses
// (r_before · r_after < 0), which a strut's own length check at the evaluated points can miss.
class StrutWatch {
 public:
  StrutWatch(const mbs::Model& model, const mbs::State& x, double t) : model_(model), t_(t) {
    Eigen::Vector3d r;
    for (const auto& f : model.forces)
      if (f->strut_vector(model, x, r)) struts_.push_back({f.get(), r});
  }
  void check(const mbs::State& x, double t) {
    Eigen::Vector3d r;
    for (auto& [f, prev] : struts_) {
      f->strut_vector(model_, x, r);
      // Reversed, and the chord from r_before to r_after passes close to 0 (a rotation by less than
      // ~174° between two steps does not count).
      const Eigen::Vector3d d = r - prev;
      const double s = d.squaredNorm() > 0 ? std::clamp(-prev.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      if (prev.dot(r) < 0 && (prev + s * d).norm() < 0.05 * std::max(prev.norm(), r.norm()))
        throw NumericalError(fmt::format(
            "strut '{}' passed through zero length between t = {:.6g} s and t = {:.6g} s (its terminals crossed: "
            "l = {:.3g} m before, {:.3g} m after), which would flip its axis and force; check its markers, free length "
            "and the loads that compress it",
            f->name(), t_, t, prev.norm(), r.norm()));
      prev = r;
    }
    t_ = t;
  }
  bool empty() const { return struts_.empty(); }

 private:
  const mbs::Model& model_;
  std::vector<std::pair<const mbs::ForceElement*, Eigen::Vector3d>> struts_;
  double t_;
};

// The explicit method's steps collapsing: a stiff model (IntegratorOptions::stiff_step).
void check_stiff(const IntegratorOptions& opt, long steps, double t0, double t) {
  if (opt.stiff_step > 0 && steps >= opt.stiff_after && (t - t0) / static_cast<double>(steps) < opt.stiff_step)
    throw NumericalError(fmt::format(
        "integrator (rk) at t = {:.6g} s: {} steps of {:.3g} s on average, below {:g} s: the model is stiff (a very "
        "large stiffness, damping or inerter value, or Baumgarte alpha/beta); use --integrator bdf",
        t, steps, (t - t0) / static_cast<double>(steps), opt.stiff_step));
}

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(fmt::format("SUNDIALS: {} failed (flag {})", what, flag));
}

// Creates the SUNDIALS integrator for p at (t0, x) (the vector s.y holds [q; q̇; z]).
void setup(Sundials& s, Problem& p, const mbs::State& x, double t0, const IntegratorOptions& opt) {
  const int n = p.n, nz = p.nz, N = 2 * n + nz;
  s.y = N_VNew_Serial(N, s.ctx);
  double* y = N_VGetArrayPointer(s.y);
  Eigen::Map<Eigen::VectorXd>(y, n) = x.q;
  Eigen::Map<Eigen::VectorXd>(y + n, n) = x.qd;
  Eigen::Map<Eigen::VectorXd>(y + 2 * n, nz) = x.z;

  if (opt.method == Method::Bdf) {
    s.mem = CVodeCreate(CV_BDF, s.ctx);
    check(CVodeInit(s.mem, rhs, t0, s.y), "CVodeInit");
    check(CVodeSStolerances(s.mem, opt.rtol, opt.atol), "CVodeSStolerances");
    check(CVodeSetUserData(s.mem, &p), "CVodeSetUserData");
    check(CVodeSetErrHandlerFn(s.mem, error_handler, &p), "CVodeSetErrHandlerFn");
    check(CVodeSetMaxNumSteps(s.mem, opt.max_steps), "CVodeSetMaxNumSteps");
    if (opt.max_step > 0) check(CVodeSetMaxStep(s.mem, opt.max_step), "CVodeSetMaxStep");
    s.A = SUNDenseMatrix(N, N, s.ctx);
    s.LS = SUNLinSol_Dense(s.y, s.A, s.ctx);
    check(CVodeSetLinearSolver(s.mem, s.LS, s.A), "CVodeSetLinearSolver");
  } else {
    s.mem = ERKStepCreate(rhs, t0, s.y, s.ctx);
    if (!s.mem) throw std::runtime_error("ERKStepCreate failed");
    check(ERKStepSetTableNum(s.mem, ARKODE_DORMAND_PRINCE_7_4_5), "ERKStepSetTableNum");
    // Cubic Hermite output interpolation uses the FSAL derivatives only: no extra RHS evaluations.
    check(ERKStepSetInterpolantDegree(s.mem, 3), "ERKStepSetInterpolantDegree");
    check(ERKStepSStolerances(s.mem, opt.rtol, opt.atol), "ERKStepSStolerances");
    check(ERKStepSetUserData(s.mem, &p), "ERKStepSetUserData");
    check(ERKStepSetErrHandlerFn(s.mem, error_handler, &p), "ERKStepSetErrHandlerFn");
    check(ERKStepSetMaxNumSteps(s.mem, opt.max_steps), "ERKStepSetMaxNumSteps");
    if (opt.max_step > 0) check(ERKStepSetMaxStep(s.mem, opt.max_step), "ERKStepSetMaxStep");
  }
}

// The run has left the constraint manifold (docs/assumptions.md#constraint-drift).
// `v0`: max |C_q q̇ + C_t| of the initial state, < 0 if the initial state itself violates the bound.
[[noreturn]] void violation_error(const mbs::Model& model, double t, int row, double v, double v0) {
  const std::string why =
      v0 < 0 ? "the initial state does not satisfy the joints (start from an assembled state, mbs::assemble)"
      : v0 > 1e-6
          ? fmt::format("the initial velocities violate C_q q̇ = −C_t by {:.3g} (start from an assembled state or "
                        "mbs::consistent_velocities)",
                        v0)
          : "a driving function that is not smooth (corners, a linear table) or too loose tolerances make the "
            "constraints drift";
  throw NumericalError(fmt::format(
      "constraint violation {:.3g} (m or rad) at t = {:.6g} s in {} exceeds the bound {:g} (options.max_violation): "
      "the coordinates no longer satisfy the joints; {}",
      v, t, model.constraint_name(row), model.options.max_violation, why));
}

void check_arguments(const mbs::Model& model, const mbs::State& x, const IntegratorOptions& opt) {
  if (!(opt.rtol > 0) || !(opt.atol > 0)) throw std::invalid_argument("rtol and atol must be > 0");
  if (x.z.size() != model.n_states()) throw std::invalid_argument("state has the wrong number of internal states");
}

void counters(const Sundials& s, Method method, RunStats& stats) {
  if (method == Method::Bdf) {
    CVodeGetNumSteps(s.mem, &stats.steps);
    CVodeGetNumRhsEvals(s.mem, &stats.rhs_evals);
    long fe_ls = 0;
    CVodeGetNumLinRhsEvals(s.mem, &fe_ls);
    stats.rhs_evals += fe_ls;
  } else {
    ERKStepGetNumSteps(s.mem, &stats.steps);
    ERKStepGetNumRhsEvals(s.mem, &stats.rhs_evals);
  }
}

}  // namespace

RunStats integrate(const mbs::Model& model, mbs::State& x, double t0, double t_end, double dt_sample,
                   const IntegratorOptions& opt, const Observer& observer, bool observer_needs_accelerations) {
  const auto wall0 = std::chrono::steady_clock::now();
  const int n = model.n_coords(), nz = model.n_states();
  if (!(dt_sample > 0)) throw std::invalid_argument("sample interval must be > 0");
  if (!(t_end >= t0)) throw std::invalid_argument("t_end must be >= t0");
  check_arguments(model, x, opt);
  Problem p{model, x, mbs::Workspace(model), n, nz, nullptr, {}};
  Sundials s(opt.method);
  setup(s, p, x, t0, opt);
  double* y = N_VGetArrayPointer(s.y);

  RunStats stats;
  mbs::Workspace ws(model);  // for the observer and the constraint report
  // Constraint drift of the integrator's own solution, checked after every step.
  double v0 = 0;  // initial velocity violation, for the message
  auto drift = [&](double t, const double* yv) {
    if (model.n_constraints() == 0) return;
    load_state(yv, n, nz, x);
    mbs::evaluate_constraints(model, t, x, ws);
    Eigen::Index row = 0;
    double v = ws.C.cwiseAbs().maxCoeff(&row);
    if (v > stats.max_violation) stats.max_violation = v, stats.t_max_violation = t;
    ws.c.noalias() = ws.Cq * x.qd;
    ws.c += ws.Ct;
    stats.max_velocity_violation = std::max(stats.max_velocity_violation, ws.c.cwiseAbs().maxCoeff());
    if (t == t0) v0 = stats.max_velocity_violation;
    if (v > model.options.max_violation) violation_error(model, t, static_cast<int>(row), v, t == t0 ? -1 : v0);
  };
  auto sample = [&](double t, const double* yv) {
    if (!observer) return;
    load_state(yv, n, nz, x);
    if (observer_needs_accelerations)
      mbs::accelerations(model, t, x, ws);
    else
      ws.set_state(x);
    observer(t, x, ws);
  };

  StrutWatch watch(model, x, t0);
  drift(t0, y);
  sample(t0, y);
  // One step at a time up to t_end; samples are interpolated inside each step (no step is forced).
  if (opt.method == Method::Bdf)
    check(CVodeSetStopTime(s.mem, t_end), "CVodeSetStopTime");
  else
    check(ERKStepSetStopTime(s.mem, t_end), "ERKStepSetStopTime");
  N_Vector yi = N_VClone(s.y);
  std::unique_ptr<std::remove_pointer_t<N_Vector>, void (*)(N_Vector)> yi_owner(yi, N_VDestroy);
  const long n_samples = std::lround(std::floor((t_end - t0) / dt_sample + 1e-9));
  const double eps = 1e-12 * std::max(1.0, std::abs(t_end));
  long k = 1, steps = 0;
  double t = t0, t_last_sample = t0;
  while (t < t_end - eps) {
    if (++steps > opt.max_steps) {
      throw NumericalError(fmt::format(
          "integrator ({}) failed at t = {:.6g} s: more than {} steps (the model may be stiff: try --integrator bdf)",
          method_name(opt.method), t, opt.max_steps));
    }
    int flag = opt.method == Method::Bdf ? CVode(s.mem, t_end, s.y, &t, CV_ONE_STEP)
                                         : ERKStepEvolve(s.mem, t_end, s.y, &t, ARK_ONE_STEP);
    if (p.error) std::rethrow_exception(p.error);
    if (flag < 0) {
      throw NumericalError(fmt::format("integrator ({}) failed at t = {:.6g} s (flag {}): {}", method_name(opt.method),
                                       t, flag, p.solver_message));
    }
    if (opt.method == Method::Rk) check_stiff(opt, steps, t0, t);
    if (!watch.empty()) load_state(y, n, nz, x), watch.check(x, t);
    drift(t, y);
    for (; k <= n_samples; ++k) {
      double tout = t0 + static_cast<double>(k) * dt_sample;
      if (tout > t + eps) break;
      tout = std::min(tout, t);
      int f = opt.method == Method::Bdf ? CVodeGetDky(s.mem, tout, 0, yi) : ERKStepGetDky(s.mem, tout, 0, yi);
      check(f, "GetDky");
      sample(tout, N_VGetArrayPointer(yi));
      t_last_sample = tout;
    }
  }
  if (t_end - t_last_sample > eps) sample(t_end, y);  // t_end off the sampling grid
  load_state(y, n, nz, x);

  counters(s, opt.method, stats);
  stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return stats;
}

// Stepper --------------------------------------------------------------------------------------
struct Stepper::Impl {
  Problem p;
  Sundials s;
  mbs::State x;
  double t;
  Method method;
  long max_steps;
  IntegratorOptions opt;
  double t0;
  StrutWatch watch;
  Impl(const mbs::Model& model, const mbs::State& x0, double t0_, const IntegratorOptions& opt_)
      : p{model, x0, mbs::Workspace(model), model.n_coords(), model.n_states(), nullptr, {}},
        s(opt_.method),
        x(x0),
        t(t0_),
        method(opt_.method),
        max_steps(opt_.max_steps),
        opt(opt_),
        t0(t0_),
        watch(model, x0, t0_) {
    check_arguments(model, x0, opt);
    setup(s, p, x0, t0, opt);
  }
};

Stepper::Stepper(const mbs::Model& model, const mbs::State& x0, double t0, const IntegratorOptions& options)
    : impl_(std::make_unique<Impl>(model, x0, t0, options)) {}
Stepper::~Stepper() = default;

const mbs::State& Stepper::state() const { return impl_->x; }
double Stepper::time() const { return impl_->t; }

void Stepper::advance(double t_end) {
  Impl& m = *impl_;
  if (!(t_end > m.t)) throw std::invalid_argument("Stepper::advance: t_end must be after the current time");
  double t = m.t;
  int flag;
  if (m.method == Method::Bdf) {
    check(CVodeSetStopTime(m.s.mem, t_end), "CVodeSetStopTime");
    flag = CVode(m.s.mem, t_end, m.s.y, &t, CV_NORMAL);
  } else {
    check(ERKStepSetStopTime(m.s.mem, t_end), "ERKStepSetStopTime");
    flag = ERKStepEvolve(m.s.mem, t_end, m.s.y, &t, ARK_NORMAL);
  }
  if (m.p.error) std::rethrow_exception(m.p.error);
  if (flag < 0)
    throw NumericalError(fmt::format("integrator ({}) failed at t = {:.6g} s (flag {}): {}", method_name(m.method), t,
                                     flag, m.p.solver_message));
  load_state(N_VGetArrayPointer(m.s.y), m.p.n, m.p.nz, m.x);
  if (m.method == Method::Rk) {
    long steps = 0;
    ERKStepGetNumSteps(m.s.mem, &steps);
    check_stiff(m.opt, steps, m.t0, t_end);
  }
  m.watch.check(m.x, t_end);
  m.t = t_end;
  if (m.p.model.n_constraints() > 0) {  // the bound of integrate(), at the end of each advance
    mbs::evaluate_constraints(m.p.model, t_end, m.x, m.p.ws);
    Eigen::Index row = 0;
    const double v = m.p.ws.C.cwiseAbs().maxCoeff(&row);
    if (v > m.p.model.options.max_violation) violation_error(m.p.model, t_end, static_cast<int>(row), v, 0.0);
  }
}

RunStats Stepper::stats() const {
  RunStats st;
  counters(impl_->s, impl_->method, st);
  return st;
}

}  // namespace inerta::solve
