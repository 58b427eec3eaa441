#include "inerta/mbs/model_check.hpp"

#include "inerta/mbs/dynamics.hpp"

namespace inerta::mbs {

ModelCheck check_model(const Model& model) {
  ModelCheck r;
  r.state = assemble(model, 0.0, &r.assembly);
  Workspace ws(model);
  evaluate_constraints(model, 0.0, r.state, ws);
  if (model.n_constraints() > 0) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(ws.Cq);
    lu.setThreshold(1e-10);
    r.rank = static_cast<int>(lu.rank());
  }
  r.dof = model.n_coords() - r.rank;
  r.redundant = model.n_constraints() - r.rank;
  accelerations(model, 0.0, r.state, ws);  // throws if the system matrix is singular
  return r;
}

}  // namespace inerta::mbs
