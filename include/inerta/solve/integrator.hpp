#pragma once
// Error-controlled time integration of eq. 4.12 with SUNDIALS (spec/02 §2.2).
//   bdf: CVODE, variable-order (1–5) BDF with Newton iterations and a dense difference-quotient
//        Jacobian — the class of MATLAB's ode15s, for stiff models.
//   rk:  ARKODE ERKStep, Dormand–Prince 5(4) — explicit, cheaper per step on non-stiff models.
// The first-order state is y = [q; q̇].
#include <functional>
#include <memory>
#include <string>

#include "inerta/error.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::solve {

enum class Method { Bdf, Rk };

Method parse_method(const std::string& name);  ///< "bdf" | "rk"; throws std::invalid_argument
const char* method_name(Method m);

struct IntegratorOptions {
  Method method = Method::Rk;  ///< default chosen by measurement: see docs/integrators.md
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = 0;  ///< 0 = unlimited
  long max_steps = 50'000'000;
  /// Stiffness detection of the explicit method (issue 15): after `stiff_after` steps, a mean step
  /// below `stiff_step` (s) stops the run with NumericalError advising bdf (0: off).
  double stiff_step = 1e-6;
  long stiff_after = 20000;
};

/// The rules of rtol, atol and max_step: the CLI's --rtol, --atol, --max-step and Python's
/// arguments of the same names check them with the same words (issue 25).
inline constexpr NumberRule rtol_rule{1e-14, 1, "1e-14 … 1"};
inline constexpr NumberRule atol_rule{1e-300, 1e300, "> 0"};
inline constexpr NumberRule max_step_rule{0, 1e7, ">= 0 s"};

struct RunStats {
  long steps = 0;
  long rhs_evals = 0;
  double wall_s = 0;
  double max_violation = 0;           ///< max |C(q)| over the integrator's steps (m or rad)
  double max_velocity_violation = 0;  ///< max |C_q q̇ + C_t| over the steps
  double t_max_violation = 0;
};

/// Called at t0 and at every sample time (interpolated inside the steps) with ws holding the body
/// frames and, when asked for, the accelerations and multipliers at (t, x).
using Observer = std::function<void(double t, const mbs::State& x, const mbs::Workspace& ws)>;

/// Integrates from (t0, x) to t_end, sampling every dt_sample; x receives the final state.
/// Throws NumericalError with the simulated time when the integrator fails.
RunStats integrate(const mbs::Model& model, mbs::State& x, double t0, double t_end, double dt_sample,
                   const IntegratorOptions& options, const Observer& observer = {},
                   bool observer_needs_accelerations = true);

/// The same integrator kept alive between calls: for co-simulation, where the model's inputs for
/// the next interval are known only when the previous one is done (catenary/fe_catenary.hpp).
/// Each advance stops exactly at t_end (the integrator never evaluates the model beyond it).
class Stepper {
 public:
  Stepper(const mbs::Model& model, const mbs::State& x0, double t0, const IntegratorOptions& options);
  ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;
  /// Integrates from time() to t_end (> time()). NumericalError with the time on failure.
  void advance(double t_end);
  const mbs::State& state() const;
  double time() const;
  RunStats stats() const;  ///< steps and right-hand-side evaluations so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace inerta::solve
