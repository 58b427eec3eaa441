#include "inerta/optim/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <optional>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "evaluable.hpp"
#include "warm_starts.hpp"

namespace inerta::optim {

std::vector<double> operating_lengths(const Study& s) {
  std::vector<double> L;
  for (const auto& cat : s.catenaries) try {
      L.push_back(analysis::operating_length(s.pantograph, *cat, s.contact));
    } catch (const ModelError& e) {
      throw ModelError(fmt::format("{}: {}", s.source, e.what()));
    }
  return L;
}

const char* objective_unit(const Study& study) { return study.objective == Study::Objective::J2 ? "N" : ""; }
const char* objective_name(const Study& study) { return study.objective == Study::Objective::J2 ? "J2" : "sigma/F_m"; }

DesignPantographs design_pantographs(const Study& study, const network::Network& net) {
  DesignPantographs d;
  if (study.commissioned()) {  // once, on the reference line; every catenary takes it as it is
    if (!study.reference) throw InvalidArgument(study.source + ": a commissioned study (trim:) needs its reference line");
    analysis::Commissioned c = analysis::commission(study.pantograph, &net, *study.reference, study.contact, *study.trim,
                                                    study.pantograph.rig_joint >= 0 ? &study.working_range : nullptr);
    d.pantographs.assign(study.catenaries.size(), c.pantograph);
    d.commissioning = std::move(c.record);
    return d;
  }
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {  // the thesis's: relaxed under each catenary
    pantograph::Pantograph p = study.pantograph;
    p.model = pantograph::with_suspension(p.model, net, study.operating_length[i]);
    d.pantographs.push_back(std::move(p));
  }
  return d;
}

network::Network default_suspension(const Study& study) {
  const mbs::Model& m = study.pantograph.model;
  try {
    return *m.forces[static_cast<std::size_t>(pantograph::suspension_index(m))]->strut_network();
  } catch (const ModelError& e) {
    throw ModelError(fmt::format("{}: {}", study.source, e.what()));
  }
}

StudyCost cost_of(const Study& study, const std::vector<std::vector<analysis::SpeedResult>>& sweeps,
                  const std::optional<analysis::Commissioning>& commissioning) {
  if (std::all_of(sweeps.begin(), sweeps.end(), [](const auto& s) { return s.empty(); }))
    throw InvalidArgument(fmt::format("study '{}': no speed to judge a design at (speeds: empty)", study.name));
  const ContactLimits& lim = study.limits;
  StudyCost c;
  c.J = -1;
  c.commissioning = commissioning;
  const bool ratio = study.objective == Study::Objective::SigmaOverMean;
  double excess = 0, worst = 0;
  auto breach = [&](double rel, const std::string& what) {  // rel: relative excess > 0
    excess += rel;
    if (rel > worst) worst = rel, c.violation = what;
  };
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    const std::string where = sweeps.size() > 1 ? fmt::format(" under {}", study.catenary_labels[i]) : "";
    for (const analysis::SpeedResult& x : sweeps[i]) {
      if (!x.stable()) {  // no steady state: infeasible (issue 15)
        c.J = INFINITY, c.speed = x.speed, c.mean = NAN, c.catenary = static_cast<int>(i);
        c.unstable_speed = x.speed;  // J = ∞ ranks it after every design (not a limit: feasible stays)
        c.violation = fmt::format("no stable periodic solution at {:.0f} km/h{}", x.speed * 3.6, where);
        return c;
      }
      c.floquet = std::max(c.floquet, x.floquet);
      const std::vector<analysis::ContactStatistics> one{x.stats};
      const auto& contacts = x.contacts.empty() ? one : x.contacts;
      const std::string at = fmt::format(" at {:.0f} km/h{}", x.speed * 3.6, where);
      for (std::size_t k = 0; k < contacts.size(); ++k) {
        const analysis::ContactStatistics& st = contacts[k];
        // The objective: σ, or σ/F_m of the statistics the σ criterion reads (20 Hz where the line gives them).
        const analysis::ContactStatistics& sf = k < x.filtered.size() ? x.filtered[k] : st;
        const double j = ratio ? sf.std / sf.mean : st.std;
        if (j > c.J || std::isnan(j))
          c.J = std::isnan(j) ? INFINITY : j, c.speed = x.speed, c.mean = ratio ? sf.mean : st.mean,
          c.sigma = ratio ? sf.std : st.std, c.catenary = static_cast<int>(i);
        c.mean_min = std::isnan(c.mean_min) ? st.mean : std::min(c.mean_min, st.mean);
        c.mean_max = std::isnan(c.mean_max) ? st.mean : std::max(c.mean_max, st.mean);
        c.loss_pct = std::max(c.loss_pct, st.loss_pct);
        c.statistical_min = std::isnan(c.statistical_min) ? st.stat_min : std::min(c.statistical_min, st.stat_min);
        if (st.mean < lim.mean_min)
          breach((lim.mean_min - st.mean) / std::abs(lim.mean_min), fmt::format("mean force {:.4g} N < {:.4g} N{}", st.mean, lim.mean_min, at));
        if (st.mean > lim.mean_max)
          breach((st.mean - lim.mean_max) / std::abs(lim.mean_max), fmt::format("mean force {:.4g} N > {:.4g} N{}", st.mean, lim.mean_max, at));
        if (st.loss_pct > lim.loss_max)
          breach((st.loss_pct - lim.loss_max) / std::max(1.0, lim.loss_max), fmt::format("contact loss {:.3g} % > {:.3g} %{}", st.loss_pct, lim.loss_max, at));
        if (st.stat_min < lim.statistical_min)
          breach((lim.statistical_min - st.stat_min) / std::max(1.0, std::abs(lim.statistical_min)),
                 fmt::format("statistical minimum F_m − 3σ {:.4g} N < {:.4g} N{}", st.stat_min, lim.statistical_min, at));
      }
      for (double u : x.support_uplift) {
        c.uplift = std::isnan(c.uplift) ? u : std::max(c.uplift, u);
        if (u > lim.uplift_max)
          breach((u - lim.uplift_max) / lim.uplift_max, fmt::format("support uplift {:.4g} m > {:.4g} m{}", u, lim.uplift_max, at));
      }
      if (lim.acceptance)  // every criterion a hard limit; the one with the least relative margin binds
        for (const analysis::VerdictInput& in : analysis::verdict_inputs(x))
          for (const analysis::CriterionResult& r : analysis::assess(*lim.acceptance, in)) {
            if (!r.assessed) continue;
            const double rel = analysis::relative_margin(r);
            if (std::isnan(c.binding_margin) || rel < c.binding_margin)
              c.binding_margin = rel, c.binding = fmt::format("{} at {:.0f} km/h{}", r.criterion, x.speed * 3.6, where);
            if (!r.passed)
              breach(-rel, fmt::format("{} {:.4g} {} {} {:.4g} {} ({}){}", r.criterion, r.value, r.unit, r.upper ? ">" : "<",
                                       r.limit, r.unit, lim.acceptance->name, at));
          }
    }
  }
  const analysis::AcceptanceCriteria* statics = lim.acceptance ? lim.acceptance.get() : study.static_criteria.get();
  if (statics && commissioning)  // the static contact force over the working range (issue 49)
    for (const analysis::CriterionResult& r : analysis::assess_static(*statics, *commissioning)) {
      if (!r.assessed) continue;
      const double rel = analysis::relative_margin(r);
      if (std::isnan(c.binding_margin) || rel < c.binding_margin) c.binding_margin = rel, c.binding = r.criterion + " at standstill";
      if (!r.passed)
        breach(-rel, fmt::format("{} {:.4g} {} {} {:.4g} {} ({}) over the working range", r.criterion, r.value, r.unit,
                                 r.upper ? ">" : "<", r.limit, r.unit, statics->name));
    }
  c.feasible = excess == 0;
  c.excess = excess;
  return c;
}

StudyCost evaluate(const Study& study, const network::Network& net) {
  if (study.method == Study::Method::Time) return evaluate_time(study, net);
  require_evaluable(net);
  const DesignPantographs d = design_pantographs(study, net);
  std::vector<std::vector<analysis::SpeedResult>> sweeps;
  for (std::size_t i = 0; i < study.catenaries.size(); ++i) {
    sweeps.push_back(analysis::sweep_periodic(d.pantographs[i], *study.catenaries[i], study.contact, study.speeds, study.harmonics));
    if (std::any_of(sweeps.back().begin(), sweeps.back().end(), [](const auto& x) { return !x.stable(); })) break;
  }
  return cost_of(study, sweeps, d.commissioning);
}

double estimated_evaluation_seconds(const Study& study) {
  if (study.method != Study::Method::Time) return 0;
  std::vector<catenary::PantographOnLine> train;
  for (double x0 : study.positions) train.push_back({study.pantograph, x0, study.contact});
  double serial = 0;  // every (catenary, speed) run, then shared among the cores
  for (const auto& c : study.catenaries) {
    const double once = c->estimated_setup_seconds(train);  // built once for the whole study
    for (double v : study.speeds) serial += c->estimated_seconds(train, v, -1) - once;
  }
  const auto runs = static_cast<int>(study.catenaries.size() * study.speeds.size());
  return serial / std::max(1, std::min(tbb::info::default_concurrency(), runs));
}

namespace {
// A time-domain study's run options: the criteria's filter for the 20 Hz statistics.
analysis::RunOptions run_options(const Study& study) {
  analysis::RunOptions o;
  if (study.limits.acceptance)
    o.filter_cutoff = study.limits.acceptance->filter_cutoff, o.filter_order = study.limits.acceptance->filter_order;
  return o;
}

// A design's train under catenary i: a copy of its pantograph at each of the study's positions.
std::vector<catenary::PantographOnLine> train_of(const Study& study, const DesignPantographs& d, std::size_t i) {
  std::vector<catenary::PantographOnLine> train;
  for (double x0 : study.positions) train.push_back({d.pantographs[i], x0, study.contact});
  return train;
}
}  // namespace

StudyCost evaluate_time(const Study& study, const network::Network& net) {
  // Every (catenary, speed) run in parallel: the catenaries here, their speeds in analysis::sweep.
  const DesignPantographs d = design_pantographs(study, net);
  std::vector<std::vector<analysis::SpeedResult>> sweeps(study.catenaries.size());
  std::vector<std::exception_ptr> errors(study.catenaries.size());
  tbb::parallel_for(std::size_t{0}, study.catenaries.size(), [&](std::size_t i) {
    try {
      sweeps[i] = analysis::sweep(train_of(study, d, i), *study.catenaries[i], study.speeds, run_options(study));
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)  // the first catenary's, whichever thread failed first
    if (e) std::rethrow_exception(e);
  return cost_of(study, sweeps, d.commissioning);
}

const StudyCost& BatchEvaluation::get() const {
  if (error) std::rethrow_exception(error);
  return cost;
}

std::vector<BatchEvaluation> evaluate_batch(const Study& study, const std::vector<network::Network>& nets) {
  if (study.method == Study::Method::Time) return evaluate_time_batch(study, nets);
  std::vector<BatchEvaluation> out(nets.size());
  for (std::size_t k = 0; k < nets.size(); ++k) try {  // the periodic path: nothing to share between designs
      out[k].cost = evaluate(study, nets[k]);
    } catch (...) {
      out[k].error = std::current_exception();
    }
  return out;
}

EarlyStop EarlyStop::behind(const StudyCost& incumbent) {
  EarlyStop e;
  if (!incumbent.feasible || !std::isfinite(incumbent.J)) return e;
  e.above = incumbent.J, e.catenary = incumbent.catenary, e.speed = incumbent.speed;
  return e;
}

namespace {
// Runs of one catenary at some of the study's speeds (indices, in the study's order).
struct Piece {
  std::size_t catenary = 0;
  std::vector<std::size_t> speeds;
};
using Round = std::vector<Piece>;

// A design's rounds: without a bound every run at once; with one, the incumbent's worst run, the other
// catenaries at its speed, then each other speed (the fastest first) on every catenary.
std::vector<Round> rounds_of(const Study& study, const EarlyStop& stop) {
  const std::size_t nc = study.catenaries.size(), ns = study.speeds.size();
  std::vector<Round> rounds;
  if (!std::isfinite(stop.above)) {
    Round all;
    for (std::size_t i = 0; i < nc; ++i) {
      all.push_back({i, {}});
      for (std::size_t s = 0; s < ns; ++s) all.back().speeds.push_back(s);
    }
    return {all};
  }
  std::vector<std::size_t> order(ns);
  for (std::size_t s = 0; s < ns; ++s) order[s] = s;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return study.speeds[a] > study.speeds[b]; });
  const auto hint = std::find(study.speeds.begin(), study.speeds.end(), stop.speed);
  const bool worst = hint != study.speeds.end() && stop.catenary >= 0 && static_cast<std::size_t>(stop.catenary) < nc;
  const std::size_t first = worst ? static_cast<std::size_t>(hint - study.speeds.begin()) : order.front();
  if (worst) rounds.push_back({{static_cast<std::size_t>(stop.catenary), {first}}});
  Round rest;
  for (std::size_t i = 0; i < nc; ++i)
    if (!worst || i != static_cast<std::size_t>(stop.catenary)) rest.push_back({i, {first}});
  if (!rest.empty()) rounds.push_back(rest);
  for (std::size_t s : order) {
    if (s == first) continue;
    Round r;
    for (std::size_t i = 0; i < nc; ++i) r.push_back({i, {s}});
    rounds.push_back(r);
  }
  return rounds;
}
}  // namespace

std::vector<BatchEvaluation> evaluate_time_batch(const Study& study, const std::vector<network::Network>& nets,
                                                 const std::vector<EarlyStop>& stops) {
  const std::size_t n = nets.size(), nc = study.catenaries.size(), ns = study.speeds.size();
  if (!stops.empty() && stops.size() != n)
    throw InvalidArgument(fmt::format("evaluate_time_batch: {} early stops for {} designs", stops.size(), n));
  auto stop_of = [&](std::size_t k) { return stops.empty() ? EarlyStop{} : stops[k]; };
  std::vector<BatchEvaluation> out(n);
  std::vector<std::optional<DesignPantographs>> designs(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {  // commissioning: each design on its own
    try {
      designs[k] = design_pantographs(study, nets[k]);
    } catch (...) {
      out[k].error = std::current_exception();
    }
  });
  std::vector<std::size_t> live;
  std::vector<std::vector<Round>> rounds(n);
  std::size_t most = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (designs[k]) live.push_back(k), rounds[k] = rounds_of(study, stop_of(k)), most = std::max(most, rounds[k].size());
  // Per design and catenary: each speed's result, and the exception of its first failing speed (as sweep).
  struct Runs {
    std::vector<std::optional<analysis::SpeedResult>> at;
    std::exception_ptr error;
    std::size_t error_at = 0;
  };
  std::vector<std::vector<Runs>> runs(n, std::vector<Runs>(nc));
  for (auto& d : runs)
    for (Runs& r : d) r.at.resize(ns);
  auto failed = [&](std::size_t k) {
    return std::any_of(runs[k].begin(), runs[k].end(), [](const Runs& r) { return r.error != nullptr; });
  };
  // The runs done so far in the study's order (moved out; put_back returns them).
  auto take = [&](std::size_t k) {
    std::vector<std::vector<analysis::SpeedResult>> sweeps(nc);
    for (std::size_t i = 0; i < nc; ++i)
      for (auto& x : runs[k][i].at)
        if (x) sweeps[i].push_back(std::move(*x));
    return sweeps;
  };
  auto put_back = [&](std::size_t k, std::vector<std::vector<analysis::SpeedResult>>& sweeps) {
    for (std::size_t i = 0; i < nc; ++i) {
      std::size_t q = 0;
      for (auto& x : runs[k][i].at)
        if (x) *x = std::move(sweeps[i][q++]);
    }
  };
  for (std::size_t r = 0; r < most; ++r) {
    // The round's pieces, each with the designs that run it: lanes of at most lane_chunk designs, and at least
    // as many lanes groups as cores while designs remain to share them.
    std::map<std::pair<std::size_t, std::vector<std::size_t>>, std::vector<std::size_t>> groups;
    for (std::size_t k : live)
      if (!out[k].stopped && r < rounds[k].size())
        for (const Piece& p : rounds[k][r]) groups[{p.catenary, p.speeds}].push_back(k);
    if (groups.empty()) break;
    struct Task {
      std::size_t catenary;
      const std::vector<std::size_t>* speeds;
      std::vector<std::size_t> designs;
      std::vector<analysis::LaneSweep> got;
    };
    std::vector<Task> tasks;
    const std::size_t cores = static_cast<std::size_t>(std::max(1, tbb::info::default_concurrency()));
    const std::size_t per_group = (cores + groups.size() - 1) / groups.size();
    for (const auto& [piece, ks] : groups) {
      const std::size_t chunks = std::max((ks.size() + lane_chunk - 1) / lane_chunk, std::min(ks.size(), per_group));
      for (std::size_t c = 0; c < chunks; ++c) {
        Task t{piece.first, &piece.second, {}, {}};
        for (std::size_t j = c * ks.size() / chunks; j < (c + 1) * ks.size() / chunks; ++j) t.designs.push_back(ks[j]);
        tasks.push_back(std::move(t));
      }
    }
    tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t q) {
      Task& t = tasks[q];
      std::vector<std::vector<catenary::PantographOnLine>> trains;
      for (std::size_t k : t.designs) trains.push_back(train_of(study, *designs[k], t.catenary));
      std::vector<double> speeds;
      for (std::size_t s : *t.speeds) speeds.push_back(study.speeds[s]);
      t.got = analysis::sweep_lanes(trains, *study.catenaries[t.catenary], speeds, run_options(study));
    });
    for (Task& t : tasks)
      for (std::size_t j = 0; j < t.designs.size(); ++j) {
        analysis::LaneSweep& s = t.got[j];
        Runs& x = runs[t.designs[j]][t.catenary];
        if (s.error) {  // its first speed's (the speeds in the study's order)
          if (!x.error || t.speeds->front() < x.error_at) x.error = s.error, x.error_at = t.speeds->front();
          continue;
        }
        for (std::size_t q = 0; q < t.speeds->size(); ++q) x.at[(*t.speeds)[q]] = std::move(s.results[q]);
      }
    for (std::size_t k : live) {  // the stop rule: J over the runs done is a lower bound of J
      const EarlyStop stop = stop_of(k);
      if (out[k].stopped || r + 1 >= rounds[k].size() || !std::isfinite(stop.above) || failed(k)) continue;
      auto sweeps = take(k);
      StudyCost c = cost_of(study, sweeps, designs[k]->commissioning);
      put_back(k, sweeps);
      if (!c.feasible || !(c.J <= stop.above)) out[k].cost = std::move(c), out[k].stopped = true;
    }
  }
  for (std::size_t k : live) {
    if (out[k].stopped) continue;
    for (std::size_t i = 0; i < nc && !out[k].error; ++i) out[k].error = runs[k][i].error;  // the first catenary's
    if (out[k].error) continue;
    try {
      auto sweeps = take(k);
      out[k].cost = cost_of(study, sweeps, designs[k]->commissioning);
    } catch (...) {
      out[k].error = std::current_exception();
    }
  }
  return out;
}

network::Network design_network(const std::string& layout, const network::Params& values) {
  network::Params free;
  for (const auto& name : free_parameters(layout))
    if (const auto it = values.find(name); it != values.end()) free[name] = it->second;
  return network::resolve(layout, free);
}

std::vector<numerics::Variable> search_variables(const Study& study, const std::string& layout) {
  std::vector<numerics::Variable> vars;
  for (const auto& name : free_parameters(layout)) {
    const auto b = study.bounds.find(name.empty() ? ' ' : name[0]);
    if (b == study.bounds.end())
      vars.push_back({name, study.lo, study.hi, true, true});
    else
      vars.push_back({name, b->second.lo, std::isinf(b->second.hi) ? study.hi : b->second.hi, true, std::isinf(b->second.hi)});
  }
  return vars;
}

std::vector<std::string> free_parameters(const std::string& layout) {
  auto named = network::find_layout(layout);
  std::vector<std::string> names;
  for (const auto& name : network::parameter_names(network::parse(named ? named->expression : layout)))
    if (!named || !named->fixed.count(name)) names.push_back(name);
  return names;
}

namespace {
// What the search minimises of a design's evaluation.
DesignCost design_cost_of(const StudyCost& c) { return {c.penalised(), c.unstable_speed > 0, c.J, c.excess}; }
// A rigid suspension locks the pantograph (with_suspension refuses it): no design.
bool rigid(const network::Network& net) { return network::simplify(net).kind == network::Network::Kind::Rigid; }
}  // namespace

DesignCost design_cost(const Study& study, const std::string& layout, const network::Params& params) {
  const network::Network net = network::resolve(layout, params);
  if (rigid(net)) return {static_cast<double>(INFINITY), false};
  try {
    return design_cost_of(evaluate(study, net));
  } catch (const NumericalError&) {
    return {static_cast<double>(INFINITY), false};  // no static equilibrium or steady state for these values
  }
}

std::vector<DesignCost> design_costs(const Study& study, const std::string& layout,
                                     const std::vector<network::Params>& params, const BatchEvaluator& evaluate) {
  std::vector<DesignCost> out(params.size(), DesignCost{static_cast<double>(INFINITY), false});
  std::vector<network::Network> nets;
  std::vector<std::size_t> which;
  for (std::size_t k = 0; k < params.size(); ++k) {
    network::Network net = network::resolve(layout, params[k]);
    if (!rigid(net)) nets.push_back(std::move(net)), which.push_back(k);
  }
  const std::vector<BatchEvaluation> got = evaluate ? evaluate(nets) : evaluate_batch(study, nets);
  if (got.size() != nets.size()) throw std::logic_error("design_costs: the evaluator gave a wrong number of results");
  for (std::size_t j = 0; j < got.size(); ++j) try {
      out[which[j]] = design_cost_of(got[j].get());
    } catch (const NumericalError&) {  // as design_cost: no design (INFINITY)
    }
  return out;
}

namespace {
// optimise_layout's body: with `coarse`, the refinement from that coarse result (study.coarse set).
LayoutResult search_layout(const Study& study, const std::string& layout, const numerics::Progress& progress,
                           const std::vector<network::Params>& warm, const DesignBatch& batch, const LayoutResult* coarse) {
  LayoutResult r;
  r.layout = layout;
  auto named = network::find_layout(layout);
  r.expression = named ? named->expression : layout;
  const network::Params fixed = named ? named->fixed : network::Params{};
  const std::vector<numerics::Variable> vars = search_variables(study, layout);
  auto params_of = [&](const std::vector<double>& values) {
    network::Params p;
    for (std::size_t i = 0; i < vars.size(); ++i) p[vars[i].name] = values[i];
    return p;
  };
  std::atomic<int> unstable{0};
  // The search's cost on study `s` (this one, or its worst speed alone): what evaluate penalises,
  // the designs refused as unstable counted.
  auto cost_on = [&](const Study& s) {
    return [&](const std::vector<double>& values) {
      const DesignCost c = design_cost(s, layout, params_of(values));
      if (c.unstable) ++unstable;
      return c.cost;
    };
  };
  // The same through `batch` (the time domain only: the periodic path's evaluations are too short to
  // send away); it evaluates study `s`, which must be this study (the worst-speed stage stays here).
  numerics::BatchCost polls;
  if (batch && study.method == Study::Method::Time)
    polls = [&](const std::vector<std::vector<double>>& values) {
      std::vector<network::Params> designs;
      for (const auto& v : values) designs.push_back(params_of(v));
      const std::vector<DesignCost> c = batch(designs);
      if (c.size() != values.size()) throw std::invalid_argument("optimise_layout: the batch gave a wrong number of costs");
      std::vector<double> out;
      for (const DesignCost& d : c) {
        if (d.unstable) ++unstable;
        out.push_back(d.cost);
      }
      return out;
    };
  const auto J = cost_on(study);
  // The search on study `s` (this one, or its worst speed alone; `send`: polls through `batch`): the
  // pattern search, or a multi-fidelity refinement's NLopt optimiser on J2 and the limits' excess.
  const bool model = study.coarse && study.refine_optimiser != numerics::Optimiser::Pattern;
  auto search_with = [&](const Study& s, const numerics::Cost& cost, const numerics::Options& o, bool send) {
    if (!model) return numerics::pattern_search(vars, cost, o, progress, send ? polls : numerics::BatchCost{});
    auto evaluation = [&](const DesignCost& c) {
      if (c.unstable) ++unstable;
      return numerics::Evaluation{c.J, c.excess};  // ranked() of it is c.cost (StudyCost::penalised)
    };
    const numerics::ConstrainedCost one = [&](const std::vector<double>& values) {
      return evaluation(design_cost(s, layout, params_of(values)));
    };
    numerics::ConstrainedBatch many;
    if (send && polls)
      many = [&](const std::vector<std::vector<double>>& values) {
        std::vector<network::Params> designs;
        for (const auto& v : values) designs.push_back(params_of(v));
        const std::vector<DesignCost> c = batch(designs);
        if (c.size() != values.size()) throw std::invalid_argument("optimise_layout: the batch gave a wrong number of costs");
        std::vector<numerics::Evaluation> out;
        for (const DesignCost& d : c) out.push_back(evaluation(d));
        return out;
      };
    return numerics::model_search(vars, one, o, study.refine_optimiser, progress, many);
  };
  numerics::Options search = study.search;
  if (study.coarse) {  // multi-fidelity: the coarse study's optimum is the one start of the refinement
    const LayoutResult c = coarse ? *coarse : optimise_layout(*study.coarse, layout, progress, warm);
    r.coarse_values = c.values, r.coarse_cost = c.cost, r.coarse_evaluations = c.evaluations;
    search = study.refine;
    search.starts = 0;
    auto start_of = [&](const network::Params& p) {
      std::vector<double> start;
      for (const auto& v : vars) {
        double x = p.count(v.name) ? p.at(v.name) : 0.0;
        if (std::isfinite(x) && x > 0) x = std::clamp(x, v.lo, v.hi);  // a reduced network's merged value may leave the box
        start.push_back(x);
      }
      return start;
    };
    const std::vector<double> start = start_of(c.values);
    search.initial_values = {start};
    // Further candidates: the next best distinct end points of the coarse starts (finite cost).
    for (const auto& [values, cost] : c.ends) {
      if (static_cast<int>(search.initial_values.size()) >= study.refine_candidates) break;
      const std::vector<double> s = start_of(values);
      if (std::isfinite(cost) &&
          std::find(search.initial_values.begin(), search.initial_values.end(), s) == search.initial_values.end())
        search.initial_values.push_back(s);
    }
    r.refined_from = static_cast<int>(search.initial_values.size());
    try {
      r.coarse_here = evaluate(study, network::resolve(layout, params_of(start)));
    } catch (const NumericalError&) {
      r.coarse_here.J = INFINITY;
    }
  } else {
    add_warm_starts(vars, warm, search);
  }
  std::vector<double> best;
  if (vars.empty()) {
    r.evaluations = 1;
  } else if (study.coarse && study.worst_speed_first && study.speeds.size() > 1 && std::isfinite(r.coarse_here.J) &&
             r.coarse_here.speed > 0) {
    // Fewer speeds first: the start's worst speed only, then every speed from that optimum.
    Study one = study;
    one.speeds = {r.coarse_here.speed};
    one.coarse.reset();
    const auto J1 = cost_on(one);
    numerics::Options first = search;
    first.max_evaluations = std::max(1, search.max_evaluations / 2);
    const numerics::Result s1 = search_with(one, J1, first, false);
    numerics::Options second = search;
    second.initial_values = {s1.values};
    second.initial_step = std::max(search.min_step, 0.5 * search.initial_step);
    second.max_evaluations = std::max(1, search.max_evaluations - s1.evaluations);
    const numerics::Result s2 = search_with(study, J, second, true);
    best = s2.values;
    r.evaluations = s1.evaluations + s2.evaluations;
    r.budget_exhausted = s2.exhausted;
  } else {
    numerics::Result s = search_with(study, J, search, true);
    best = s.values;
    r.evaluations = s.evaluations;
    r.budget_exhausted = s.exhausted;
    for (const auto& e : s.ends) {
      network::Params p = fixed;
      for (const auto& [k, v] : params_of(e.values)) p[k] = v;
      r.ends.push_back({p, e.cost});
    }
    std::stable_sort(r.ends.begin(), r.ends.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  }
  r.unstable = unstable;
  r.values = fixed;
  for (const auto& [k, v] : params_of(best)) r.values[k] = v;
  r.cost = evaluate(study, network::resolve(layout, params_of(best)));
  if (study.coarse && !vars.empty() && r.coarse_here.penalised() < r.cost.penalised()) {
    // The worst-speed stage led elsewhere: the refinement never ends worse than its start.
    best = search.initial_values.front();
    r.values = fixed;
    for (const auto& [k, v] : params_of(best)) r.values[k] = v;
    r.cost = r.coarse_here;
  }
  r.at_bounds.clear();
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (const double v = best[i]; v == 0 || std::isinf(v) || std::abs(v - vars[i].lo) <= 1e-9 * vars[i].lo ||
                                  std::abs(v - vars[i].hi) <= 1e-9 * vars[i].hi)
      r.at_bounds.push_back(vars[i].name);
  return r;
}
}  // namespace

LayoutResult optimise_layout(const Study& study, const std::string& layout, const numerics::Progress& progress,
                             const std::vector<network::Params>& warm, const DesignBatch& batch) {
  return search_layout(study, layout, progress, warm, batch, nullptr);
}

LayoutResult refine_layout(const Study& study, const std::string& layout, const LayoutResult& coarse,
                           const numerics::Progress& progress, const DesignBatch& batch) {
  if (!study.coarse) throw InvalidArgument(study.source + ": refine_layout needs a study with a coarse study");
  return search_layout(study, layout, progress, {}, batch, &coarse);
}

}  // namespace inerta::optim
