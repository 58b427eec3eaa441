#include "inerta/optim/model_study.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/solve/integrator.hpp"
#include "evaluable.hpp"
#include "warm_starts.hpp"

namespace inerta::optim {

const char* Objective::name(Kind k) {
  switch (k) {
    case Kind::Rms:
      return "rms";
    case Kind::Hinf:
      return "hinf";
    case Kind::Peak:
      return "peak";
  }
  return "?";
}

mbs::Model with_strut_network(const mbs::Model& model, int strut, const network::Network& bound) {
  if (strut < 0 || strut >= static_cast<int>(model.forces.size()) ||
      !model.forces[static_cast<std::size_t>(strut)]->strut_network())
    throw ModelError(fmt::format("{}: force element {} is not a network strut", model.source, strut));
  const network::Network net = network::simplify(bound);
  const auto& f = model.forces[static_cast<std::size_t>(strut)];
  if (net.kind == network::Network::Kind::Rigid)
    throw ModelError(fmt::format("network '{}' of '{}' is rigid with these values", network::to_string(bound, true), f->name()));
  mbs::Model m = model;
  if (net.kind == network::Network::Kind::Open) {
    m.forces.erase(m.forces.begin() + strut);
    std::erase(m.actuators, strut);
    for (int& a : m.actuators) a -= a > strut;
  } else {
    m.forces[static_cast<std::size_t>(strut)] = f->with_network(net, NAN);
  }
  m.finalize();
  return m;
}

network::Network default_network(const ModelStudy& study) {
  const network::Network* n = study.model.forces.at(static_cast<std::size_t>(study.strut))->strut_network();
  if (!n) throw ModelError(fmt::format("{}: the study's strut is not a network strut", study.source));
  return *n;
}

namespace {

// The inputs and outputs of the linear objectives: the weighted outputs, then the limited ones.
std::vector<std::string> io_outputs(const Objective& o) {
  std::vector<std::string> out;
  for (const auto& w : o.outputs) out.push_back(w.name);
  for (const auto& l : o.limits) out.push_back(l.output);
  return out;
}

void finish(const ModelStudy& study, ModelCost& c) {  // J, the limits and the ranking (ModelCost::penalised)
  const Objective& o = study.objective;
  double J2 = 0, peak = 0;
  for (std::size_t i = 0; i < o.outputs.size(); ++i) {
    const double v = o.outputs[i].weight * c.values[i];
    J2 += v * v;
    peak = std::max(peak, v);
  }
  c.J = o.kind == Objective::Kind::Rms ? std::sqrt(J2) : peak;
  double excess = 0;
  for (std::size_t k = 0; k < o.limits.size(); ++k) excess += std::max(0.0, c.limit_values[k] / o.limits[k].limit - 1);
  c.feasible = excess == 0;
  c.penalised = c.feasible ? c.J : 1e100 * (1 + excess);
}

}  // namespace

ModelCost evaluate(const ModelStudy& study, const network::Network& net) {
  require_evaluable(net);
  const Objective& o = study.objective;
  const mbs::Model m = with_strut_network(study.model, study.strut, net);
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  ModelCost c;
  const std::size_t nw = o.outputs.size();
  switch (o.kind) {
    case Objective::Kind::Rms: {
      const std::vector<std::string> inputs = o.road ? o.road->inputs : o.noise_inputs;
      const analysis::StateSpace ss = analysis::state_space(m, x, inputs, io_outputs(o), 0.0);
      const analysis::RandomResponse r = o.road ? analysis::road_response(ss, *o.road)
                                                : analysis::white_noise_response(ss, Eigen::VectorXd::Map(o.noise_intensity.data(),
                                                                                                         static_cast<Eigen::Index>(o.noise_intensity.size()))
                                                                                          .asDiagonal()
                                                                                          .toDenseMatrix());
      c.values.assign(r.rms.data(), r.rms.data() + nw);
      c.limit_values.assign(r.rms.data() + nw, r.rms.data() + r.rms.size());
      break;
    }
    case Objective::Kind::Hinf: {
      const analysis::StateSpace ss = analysis::state_space(m, x, {o.input}, io_outputs(o), 0.0);
      const auto H = analysis::frequency_response(ss, o.frequencies);
      c.values.assign(nw, 0.0);
      double best = -1;
      for (std::size_t k = 0; k < H.size(); ++k)
        for (std::size_t i = 0; i < nw; ++i) {
          const double a = std::abs(H[k](static_cast<Eigen::Index>(i), 0));
          c.values[i] = std::max(c.values[i], a);
          if (o.outputs[i].weight * a > best) best = o.outputs[i].weight * a, c.frequency = o.frequencies[k];
        }
      break;
    }
    case Objective::Kind::Peak: {
      std::vector<int> idx;
      for (const auto& w : o.outputs)
        for (std::size_t k = 0; k < m.outputs.size(); ++k)
          if (m.outputs[k].name == w.name) idx.push_back(static_cast<int>(k));
      std::vector<double> y0(idx.size(), std::nan("")), peak(idx.size(), 0.0);
      solve::IntegratorOptions opt;
      solve::integrate(m, x, 0.0, o.t_end, o.sample, opt, [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
        for (std::size_t i = 0; i < idx.size(); ++i) {
          const double y = mbs::evaluate_output(m.outputs[static_cast<std::size_t>(idx[i])], m, t, s, ws);
          if (std::isnan(y0[i])) y0[i] = y;
          peak[i] = std::max(peak[i], std::abs(y - y0[i]));
        }
      });
      c.values = peak;
      break;
    }
  }
  finish(study, c);
  return c;
}

ModelLayoutResult optimise_layout(const ModelStudy& study, const std::string& layout, const numerics::Progress& progress,
                                  const std::vector<network::Params>& warm) {
  ModelLayoutResult r;
  r.layout = layout;
  const auto named = network::find_layout(layout);
  r.expression = named ? named->expression : layout;
  const network::Params fixed = named ? named->fixed : network::Params{};
  std::vector<numerics::Variable> vars;
  for (const auto& name : network::parameter_names(network::parse(r.expression)))
    if (!fixed.count(name)) vars.push_back({name, study.lo, study.hi, true, true});
  auto params_of = [&](const std::vector<double>& values) {
    network::Params p;
    for (std::size_t i = 0; i < vars.size(); ++i) p[vars[i].name] = values[i];
    return p;
  };
  auto cost = [&](const std::vector<double>& values) {
    const network::Network net = network::resolve(layout, params_of(values));
    if (network::simplify(net).kind == network::Network::Kind::Rigid) return static_cast<double>(INFINITY);
    try {
      return evaluate(study, net).penalised;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);  // no static equilibrium, an unstable design, a failed run
    }
  };
  numerics::Options search = study.search;
  add_warm_starts(vars, warm, search);
  std::vector<double> best;
  if (vars.empty()) {
    r.evaluations = 1;
  } else {
    const numerics::Result s = numerics::pattern_search(vars, cost, search, progress);
    best = s.values;
    r.evaluations = s.evaluations;
    r.budget_exhausted = s.exhausted;
  }
  r.values = fixed;
  for (const auto& [k, v] : params_of(best)) r.values[k] = v;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const double v = best[i];
    if (v == 0 || std::isinf(v) || std::abs(v - study.lo) <= 1e-9 * study.lo || std::abs(v - study.hi) <= 1e-9 * study.hi)
      r.at_bounds.push_back(vars[i].name);
  }
  r.cost = evaluate(study, network::resolve(layout, params_of(best)));
  return r;
}

}  // namespace inerta::optim

#include <tbb/parallel_for.h>

namespace inerta::optim {

ObjectiveMap objective_map(const ModelStudy& study, const std::string& layout, const network::Params& values,
                           const std::string& x_name, const std::string& y_name, int n, double decades) {
  ObjectiveMap m;
  m.layout = layout, m.x_name = x_name, m.y_name = y_name;
  auto axis = [&](const std::string& name) {
    const auto it = values.find(name);
    if (it == values.end()) throw InvalidArgument(fmt::format("objective map: '{}' is not an element of '{}'", name, layout));
    const double v = std::isfinite(it->second) && it->second > 0 ? it->second : std::sqrt(study.lo * study.hi);
    std::vector<double> a;
    for (int i = 0; i < n; ++i) a.push_back(v * std::pow(10.0, decades * (2.0 * i / std::max(1, n - 1) - 1)));
    return a;
  };
  m.x = axis(x_name), m.y = axis(y_name);
  m.J.assign(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n), INFINITY));
  tbb::parallel_for(0, n * n, [&](int k) {
    network::Params p = values;
    p[x_name] = m.x[static_cast<std::size_t>(k / n)];
    p[y_name] = m.y[static_cast<std::size_t>(k % n)];
    try {
      m.J[static_cast<std::size_t>(k / n)][static_cast<std::size_t>(k % n)] = evaluate(study, network::resolve(layout, p)).J;
    } catch (const NumericalError&) {
    } catch (const ModelError&) {
    }
  });
  return m;
}

StudyFrf study_frf(const ModelStudy& study, const network::Network& net, const std::vector<double>& f) {
  const Objective& o = study.objective;
  StudyFrf r;
  if (o.kind == Objective::Kind::Peak) return r;
  r.input = o.kind == Objective::Kind::Hinf ? o.input : o.road ? o.road->inputs[0] : o.noise_inputs[0];
  for (const auto& w : o.outputs) r.outputs.push_back(w.name);
  const mbs::Model m = with_strut_network(study.model, study.strut, net);
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  const analysis::StateSpace ss = analysis::state_space(m, x, {r.input}, r.outputs, 0.0);
  const auto H = analysis::frequency_response(ss, f);
  r.f = f;
  r.magnitude.assign(r.outputs.size(), std::vector<double>(f.size()));
  for (std::size_t k = 0; k < f.size(); ++k)
    for (std::size_t i = 0; i < r.outputs.size(); ++i) r.magnitude[i][k] = std::abs(H[k](static_cast<Eigen::Index>(i), 0));
  return r;
}

}  // namespace inerta::optim
