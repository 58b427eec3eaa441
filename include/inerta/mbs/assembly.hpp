#pragma once
// Model assembly (Newton solve of C(q) = 0 from the tabulated positions) and static equilibrium
// under all applied loads (spec/02 §2.4).
#include <string>

#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

struct AssemblyReport {
  int iterations = 0;
  double residual = 0;          ///< max |C| after assembly
  double initial_residual = 0;  ///< max |C| of the tabulated positions
  Eigen::VectorXd dq;           ///< correction applied to the tabulated positions
  int largest = -1;             ///< coordinate with the largest correction
};

/// Newton solve of C(q, t0) = 0 from the tabulated positions with Model::held coordinates fixed
/// (minimum-norm correction of the free ones), then consistent_velocities. Throws NumericalError
/// if it does not converge.
State assemble(const Model& model, double t0, AssemblyReport* report = nullptr);

/// The velocity level of the constraints (eq. 4.2): x.qd receives its minimum-norm correction onto
/// C_q q̇ = −C_t at (x.q, t), so that driving joints move at their prescribed f′(t) (from
/// x.qd = 0 after static_equilibrium: the least-norm velocities that the drives impose).
void consistent_velocities(const Model& model, double t, State& x);

struct EquilibriumReport {
  int iterations = 0;
  double force_residual = 0;  ///< max |Q − C_qᵀλ| at the solution
  double max_move = 0;        ///< largest coordinate change from the assembled positions
  int largest = -1;
};

/// Static equilibrium: Q(q, q̇ = 0, t0) − C_qᵀ λ = 0, C(q, t0) = 0 (damped Newton, Jacobian by
/// central differences). x.q is the start and receives the solution; x.qd is set to zero and the
/// internal states x.z to their steady values (ForceElement::relax). Driving joints are held at
/// f(t0); a run from this state calls consistent_velocities for their velocity f′(t0)
/// (analysis::simulate with from_equilibrium).
void static_equilibrium(const Model& model, double t0, State& x, EquilibriumReport* report = nullptr);

}  // namespace inerta::mbs
