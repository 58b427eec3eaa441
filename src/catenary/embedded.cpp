#include "inerta/catenary/embedded.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"

namespace inerta::catenary {

ContactId Coupled::contact(int k) const {
  if (k < 0 || k >= n_contacts())
    throw InvalidArgument(fmt::format("contact {} does not exist: the system has {} contact(s)", k, n_contacts()));
  return {k};
}

EmbeddedCoupled::EmbeddedCoupled(std::vector<Part> parts, double speed, double span)
    : parts_(std::move(parts)), speed_(speed), span_(span) {
  for (const Part& p : parts_) x_.push_back(mbs::assemble(p.model, 0.0));
}

const EmbeddedCoupled::Part& EmbeddedCoupled::part(ContactId c) const {
  if (c.index < 0 || c.index >= n_contacts())
    throw InvalidArgument(fmt::format("contact {} does not exist: the system has {} contact(s)", c.index, n_contacts()));
  return parts_[static_cast<std::size_t>(c.index)];
}

const mbs::State& EmbeddedCoupled::state(ContactId c) const {
  part(c);
  return x_[static_cast<std::size_t>(c.index)];
}

void EmbeddedCoupled::equilibrate() {
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    x_[k] = mbs::assemble(parts_[k].model, 0.0);
    mbs::static_equilibrium(parts_[k].model, 0.0, x_[k]);
  }
  t_ = 0;
  sampled_start_ = false;
}

solve::RunStats EmbeddedCoupled::advance(double t_end, double dt, const solve::IntegratorOptions& options,
                                         const SampleObserver& observer, bool accelerations) {
  solve::RunStats total;
  const double t0 = t_;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Part& p = parts_[k];
    const bool acc = accelerations || mbs::needs_accelerations(p.force);
    const ContactId id{static_cast<int>(k)};
    const solve::RunStats st = solve::integrate(
        p.model, x_[k], t0, t_end, dt, options,
        [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
          if (t == t0 && sampled_start_) return;  // delivered as the end of the previous advance
          const double F = mbs::evaluate_output(p.force, p.model, t, s, ws);
          if (p.bilateral && F < 0)
            throw NumericalError(fmt::format(
                "t = {:.6g} s (v = {:.4g} km/h, contact {}): the bilateral contact force is {:.4g} N < 0 — the "
                "head pulls the wire down, so this run is invalid for a bilateral contact; use a penalty contact "
                "or check the static force",
                t, speed_ * 3.6, k + 1, F));
          if (observer) observer(Sample{id, t, p.x0 + speed_ * t, F, p.model, s, ws});
        },
        acc);
    total.steps += st.steps;
    total.rhs_evals += st.rhs_evals;
    total.wall_s += st.wall_s;
    if (st.max_violation > total.max_violation) total.max_violation = st.max_violation, total.t_max_violation = st.t_max_violation;
    total.max_velocity_violation = std::max(total.max_velocity_violation, st.max_velocity_violation);
  }
  t_ = t_end;
  sampled_start_ = true;
  return total;
}

}  // namespace inerta::catenary
