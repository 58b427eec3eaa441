// Pass 6 of compiling a line (fe_compile.hpp): irregularities on the form-found line
// (docs/catenary-fe.md "Irregularities").
#include <fmt/format.h>

#include "fe_compile.hpp"
#include "inerta/catenary/fe_schema.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary::compile {

// Dropper lengths off by δ_k (the dropper now pulls T'_k = EA/L'_k (ℓ_k − L'_k), L'_k = L_k + δ_k, at
// the form-found geometry) and point masses on the contact wire. Their loads f' move the line to its
// reference state u_ref = K'⁻¹ f' (droppers bilateral: linear); a dropper whose tension there is
// negative is slack in the static state, which the solvers' static_displacement finds from the
// reference state (fe_line.hpp).
Irregular irregularities(const FeCatenaryData& d, int n_dofs, const std::vector<double>& stretched,
                         const std::function<FeLine::Shape(double)>& contact_shape, std::vector<FeLine::Dropper>& droppers) {
  const FeIrregularity& irr = d.irregularity;
  const int nd = static_cast<int>(droppers.size());
  if (!irr.dropper_length_errors.empty() && irr.dropper_length_errors.size() != droppers.size())
    throw FeKeyError({-1, "irregularity.dropper_length_errors", -1},
                     fmt::format("needs one value per dropper of the line in line order ({}), got {}", nd,
                                      irr.dropper_length_errors.size()));
  Irregular out;
  out.delta.assign(static_cast<std::size_t>(nd), 0.0);
  if (irr.dropper_length_std > 0) out.delta = dropper_length_errors(irr, static_cast<std::size_t>(nd));
  for (std::size_t k = 0; k < irr.dropper_length_errors.size(); ++k) out.delta[k] += irr.dropper_length_errors[k];
  out.f = Eigen::VectorXd::Zero(n_dofs);
  out.any = !irr.point_masses.empty();
  for (int k = 0; k < nd; ++k) {
    const double dk = out.delta[static_cast<std::size_t>(k)];
    if (dk == 0) continue;
    out.any = true;
    FeLine::Dropper& dr = droppers[static_cast<std::size_t>(k)];
    const double L1 = dr.length + dk;
    if (!(L1 > 0))
      throw ModelError(fmt::format("finite-element catenary: irregularity: dropper {} (x = {:.3f} m) of {:.4g} m "
                                   "with a length error of {:.4g} m has no length left",
                                   k + 1, dr.x, dr.length, dk));
    const double T1 = dr.EA / L1 * (stretched[static_cast<std::size_t>(k)] - L1);
    const double dw = 0.5 * dr.mass_per_length * dk * d.gravity;  // its weight changes with its length (half at each end)
    out.f[dr.dof_c] += (T1 - dr.tension) - dw;
    out.f[dr.dof_m] -= (T1 - dr.tension) + dw;
    dr.length = L1, dr.static_stiffness = dr.EA / L1, dr.tension = T1;
  }
  for (const FeIrregularity::PointMass& pm : irr.point_masses) {
    const FeLine::Shape sh = contact_shape(pm.x);
    for (int a = 0; a < 4; ++a) {
      if (sh.dofs[a] < 0) continue;
      out.f[sh.dofs[a]] -= pm.mass * d.gravity * sh.N[a];
      for (int b = 0; b < 4; ++b)
        if (sh.dofs[b] >= 0) out.point_mass.emplace_back(sh.dofs[a], sh.dofs[b], pm.mass * sh.N[a] * sh.N[b]);
    }
  }
  return out;
}

}  // namespace inerta::catenary::compile
