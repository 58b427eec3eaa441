#pragma once
// Equations of motion of the constrained planar system with inerters (eqs. 3.33 and 4.12):
//
//   [ M + M_I   C_qᵀ ] [ q̈ ]   [ Q_e + Q_Iv            ]
//   [ C_q        0   ] [ λ ] = [ Q_d − 2αĊ − β²C       ]
//
// M_I (inerter mass term) and Q_Iv (inerter velocity terms) keep the right-hand side free of q̈.
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

/// Constraint values C, ∂C/∂t, Jacobian C_q and γ = Q_d (eqs. 4.1–4.4) into ws.
void evaluate_constraints(const Model& model, double t, const State& x, Workspace& ws);

/// Mass matrix and generalised forces of all force elements (incl. inerter terms) into ws.M, ws.Q.
void evaluate_forces(const Model& model, double t, const State& x, Workspace& ws);

/// Solves eq. 4.12 for ws.qdd and ws.lambda. Allocates nothing.
/// Throws NumericalError (with t) if the system matrix is singular.
void accelerations(const Model& model, double t, const State& x, Workspace& ws);

/// Reaction of joint `j` on its body j: [Fx, Fy, moment about j's centre of mass] = −C_q,jᵀ λ (eq. 4.6).
Vec3 joint_reaction(const Model& model, int joint, double t, const State& x, const Eigen::VectorXd& lambda);

/// Kinetic energy ½ q̇ᵀ M q̇ of the bodies (inerters count in their own energy()).
double kinetic_energy(const Model& model, const State& x);
/// Σ energy() of the force elements.
double stored_energy(const Model& model, double t, const State& x);
/// Σ power() of the force elements.
double element_power(const Model& model, double t, const State& x);

}  // namespace inerta::mbs
