#pragma once
// Error-controlled time integration of eq. 4.12 with SUNDIALS (spec/02 §2.2).
//   bdf: CVODE, variable-order (1–5) BDF with Newton iterations and a dense difference-quotient
//        Jacobian — the class of MATLAB's ode15s, for stiff models.
//   rk:  ARKODE ERKStep, Dormand–Prince 5(4) — explicit, cheaper per step on non-stiff models.
// The first-order state is y = [q; q̇].
#include <functional>
#include <string>

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
};

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

}  // namespace inerta::solve
