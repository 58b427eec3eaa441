#pragma once
// What `inerta check` reports of a model, as a library call (the CLI and the Python module): the
// assembly at t = 0, the rank of the constraint Jacobian there (so redundant constraint equations
// show), the degrees of freedom n_coords − rank, and a first evaluation of eq. 4.12 (which throws
// NumericalError if the system matrix is singular).
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

struct ModelCheck {
  State state;              ///< the assembled state at t = 0
  AssemblyReport assembly;  ///< of mbs::assemble
  int rank = 0;             ///< numerical rank of C_q at the assembled state (threshold 1e-10)
  int dof = 0;              ///< n_coords − rank
  int redundant = 0;        ///< n_constraints − rank: constraint equations that repeat others
};

/// Assembles the model at t = 0, computes the rank of C_q (full-pivoting LU, threshold 1e-10) and
/// solves eq. 4.12 once. NumericalError if the assembly does not converge or the system is singular.
ModelCheck check_model(const Model& model);

}  // namespace inerta::mbs
