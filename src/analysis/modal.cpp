#include "inerta/analysis/modal.hpp"

#include <fmt/format.h>

#include "inerta/mbs/assembly.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::analysis {

namespace {
ModalAnalysis about_equilibrium(mbs::Model model, mbs::State x, std::string setting) {
  ModalAnalysis r;
  r.setting = std::move(setting);
  r.model = std::move(model);
  r.equilibrium = std::move(x);
  r.linear = mbs::linearise(r.model, r.equilibrium, 0.0);
  r.modes = mbs::modes(r.model, r.linear);
  return r;
}
}  // namespace

ModalAnalysis modal_analysis(const mbs::Model& model) {
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  return about_equilibrium(model, x, "");
}

ModalAnalysis modal_analysis(const pantograph::Pantograph& p, const catenary::Catenary& catenary,
                             const catenary::Contact& contact) {
  const auto mean = catenary.mean();
  auto sys = mean->couple(p, contact, 1.0);  // time-invariant: the speed does not matter
  sys->equilibrate();
  const catenary::ContactId c = sys->contact(0);
  return about_equilibrium(sys->model(c), sys->state(c), fmt::format("under the mean of the {}", mean->describe()));
}

ModalAnalysis modal_analysis_free_head(const pantograph::Pantograph& p) {
  double F = 0;
  mbs::Model m = pantograph::release_head(p, &F);
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  return about_equilibrium(std::move(m), std::move(x),
                           fmt::format("head free under its static contact force {:.2f} N", F));
}

}  // namespace inerta::analysis
