#include "inerta/optim/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "evaluable.hpp"
#include "warm_starts.hpp"

namespace inerta::optim {

std::vector<double> operating_lengths(const Study& s) {
  int act = -1;
  for (std::size_t k = 0; k < s.pantograph.model.forces.size(); ++k)
    if (std::dynamic_pointer_cast<const mbs::Actuator>(s.pantograph.model.forces[k])) act = static_cast<int>(k);
  if (act < 0)
    throw ModelError(fmt::format("{}: the pantograph has no actuator whose suspension the study replaces", s.source));
  std::vector<double> L;
  for (const auto& cat : s.catenaries) {
    auto sys = cat->couple(s.pantograph, s.contact, 1.0);
    sys->equilibrate();
    const catenary::ContactId c = sys->contact(0);
    L.push_back(sys->model(c).forces[static_cast<std::size_t>(act)]->length(sys->model(c), sys->state(c)));
  }
  return L;
}

network::Network default_suspension(const Study& study) {
  for (const auto& f : study.pantograph.model.forces)
    if (auto a = std::dynamic_pointer_cast<const mbs::Actuator>(f)) return a->network();
  throw ModelError(
      fmt::format("{}: the pantograph has no actuator whose suspension the study could replace", study.source));
}

StudyCost evaluate(const Study& study, const network::Network& net) {
  require_evaluable(net);
  StudyCost c;
  c.J = -1;
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {
    pantograph::Pantograph p = study.pantograph;
    p.model = pantograph::with_suspension(p.model, net, study.operating_length[i]);
    auto r = analysis::sweep_periodic(p, *study.catenaries[i], study.contact, study.speeds, study.harmonics);
    for (const auto& x : r) {
      if (!x.stable()) {  // no steady state: infeasible (issue 15)
        c.J = INFINITY, c.speed = x.speed, c.mean = NAN, c.catenary = static_cast<int>(i), c.unstable_speed = x.speed;
        return c;
      }
      if (x.stats.std > c.J)
        c.J = x.stats.std, c.speed = x.speed, c.mean = x.stats.mean, c.catenary = static_cast<int>(i);
    }
  }
  return c;
}

StudyCost evaluate_time(const Study& study, const network::Network& net) {
  StudyCost c;
  c.J = -1;
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {
    pantograph::Pantograph p = study.pantograph;
    p.model = pantograph::with_suspension(p.model, net, study.operating_length[i]);
    auto r = analysis::sweep(p, *study.catenaries[i], study.contact, study.speeds, analysis::RunOptions{});
    for (const auto& x : r)
      if (x.stats.std > c.J)
        c.J = x.stats.std, c.speed = x.speed, c.mean = x.stats.mean, c.catenary = static_cast<int>(i);
  }
  return c;
}

std::vector<std::string> free_parameters(const std::string& layout) {
  auto named = network::find_layout(layout);
  std::vector<std::string> names;
  for (const auto& name : network::parameter_names(network::parse(named ? named->expression : layout)))
    if (!named || !named->fixed.count(name)) names.push_back(name);
  return names;
}

LayoutResult optimise_layout(const Study& study, const std::string& layout, const numerics::Progress& progress,
                             const std::vector<network::Params>& warm) {
  LayoutResult r;
  r.layout = layout;
  auto named = network::find_layout(layout);
  r.expression = named ? named->expression : layout;
  const network::Params fixed = named ? named->fixed : network::Params{};
  std::vector<numerics::Variable> vars;
  for (const auto& name : free_parameters(layout)) vars.push_back({name, study.lo, study.hi, true, true});
  auto params_of = [&](const std::vector<double>& values) {
    network::Params p;
    for (std::size_t i = 0; i < vars.size(); ++i) p[vars[i].name] = values[i];
    return p;
  };
  std::atomic<int> unstable{0};
  auto J = [&](const std::vector<double>& values) {
    const network::Network net = network::resolve(layout, params_of(values));
    // A rigid suspension locks the pantograph (with_suspension refuses it): no design.
    if (network::simplify(net).kind == network::Network::Kind::Rigid) return static_cast<double>(INFINITY);
    try {
      const StudyCost c = evaluate(study, net);
      if (c.unstable_speed > 0) ++unstable;
      return c.J;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);  // no static equilibrium or steady state for these values
    }
  };
  std::vector<double> best;
  if (vars.empty()) {
    r.evaluations = 1;
  } else {
    numerics::Options search = study.search;
    add_warm_starts(vars, warm, search);
    numerics::Result s = numerics::pattern_search(vars, J, search, progress);
    best = s.values;
    r.evaluations = s.evaluations;
    r.budget_exhausted = s.exhausted;
  }
  r.unstable = unstable;
  r.values = fixed;
  for (const auto& [k, v] : params_of(best)) r.values[k] = v;
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (const double v = best[i]; v == 0 || std::isinf(v) || std::abs(v - study.lo) <= 1e-9 * study.lo ||
                                  std::abs(v - study.hi) <= 1e-9 * study.hi)
      r.at_bounds.push_back(vars[i].name);
  r.cost = evaluate(study, network::resolve(layout, params_of(best)));
  return r;
}

}  // namespace inerta::optim
