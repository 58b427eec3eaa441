#include "inerta/optim/structure_search.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study_run.hpp"

namespace inerta::optim {

namespace {
using network::Network;
using K = Network::Kind;

// Networks of up to two elements are first scanned on a grid of one point per decade: they have no
// sub-network to start from, and random starts can miss a narrow optimum (an inerter of 1 kg in a
// box of twelve decades).
constexpr int grid_variables = 2;
// An element whose removal changes the objective by less than this (relative) is removed.
constexpr double prune_tolerance = 1e-4;

bool degenerate(const Network& n) { return n.kind == K::Open || n.kind == K::Rigid; }

void leaves(const Network& n, std::vector<const Network*>& out) {
  if (n.is_element()) out.push_back(&n);
  for (const auto& c : n.children) leaves(c, out);
}

struct Warm {
  network::Params values;
  double cost = INFINITY;
  std::string from;
};

// The best finished sub-network with one element fewer: element e opened or made rigid, the
// members that then merge with a neighbour of their type opened (in parallel) or made rigid (in
// series), the rest mapped leaf by leaf onto the sub-network's optimum (both in canonical order, so
// equal structures have their leaves in corresponding places).
std::optional<Warm> best_warm(const std::string& expression, const std::map<std::string, std::size_t>& by_structure,
                              const std::vector<StructureEntry>& entries, int elements) {
  const Network net = network::parse(expression);
  const std::vector<std::string> names = network::parameter_names(net);
  std::optional<Warm> best;
  for (const std::string& e : names)
    for (const double removed : {0.0, static_cast<double>(INFINITY)}) {
      network::Params p;
      for (const auto& n : names) p[n] = 1.0;
      p[e] = removed;
      const Network s = network::simplify(network::assign(net, p));
      if (degenerate(s)) continue;
      const std::string target = network::structure(s);
      const auto kept = network::parameter_names(network::canonical(s));
      for (const auto& n : network::parameter_names(s)) {
        if (std::find(kept.begin(), kept.end(), n) != kept.end()) continue;
        p[n] = 0.0;  // merged in a parallel group: open it
        const Network t = network::simplify(network::assign(net, p));
        if (degenerate(t) || network::structure(t) != target) p[n] = INFINITY;  // merged in series: rigid
      }
      const auto it = by_structure.find(target);
      if (it == by_structure.end()) continue;
      const StructureEntry& r = entries[it->second];
      if (r.counts.elements >= elements || !std::isfinite(r.cost)) continue;
      const Network sc = network::canonical(network::simplify(network::assign(net, p)));
      const Network rc = network::canonical(network::parse(r.expression));
      std::vector<const Network*> ls, lr;
      leaves(sc, ls), leaves(rc, lr);
      if (ls.size() != lr.size() || network::structure(sc) != network::structure(rc)) continue;
      bool ok = true;
      for (std::size_t i = 0; i < ls.size() && ok; ++i) {
        const auto v = r.values.find(lr[i]->name);
        ok = ls[i]->kind == lr[i]->kind && v != r.values.end();
        if (ok) p[ls[i]->name] = v->second;
      }
      if (ok && (!best || r.cost < best->cost)) best = Warm{p, r.cost, target};
    }
  return best;
}

}  // namespace

network::Params prune(const std::string& expression, network::Params values, const std::function<double(const network::Params&)>& cost,
                      double tolerance) {
  double base = cost(values);
  if (!std::isfinite(base)) return values;
  for (const auto& name : network::parameter_names(network::parse(expression))) {
    const double v = values.at(name);
    if (v == 0 || std::isinf(v)) continue;
    for (const double removed : {0.0, static_cast<double>(INFINITY)}) {
      network::Params p = values;
      p[name] = removed;
      const network::Network s = network::simplify(network::assign(network::parse(expression), p));
      if (s.kind == K::Rigid) continue;
      double c = INFINITY;
      try {
        c = cost(p);
      } catch (const NumericalError&) {
      } catch (const ModelError&) {
      }
      if (c <= base + tolerance * std::abs(base)) {
        values = p, base = std::min(base, c);
        break;
      }
    }
  }
  return values;
}

namespace {
void describe_reduced(StructureEntry& e) {
  if (e.values.size() < static_cast<std::size_t>(e.counts.elements)) {  // no design was found
    e.reduced = e.reduced_structure = std::string("-");
    e.reduced_counts = e.counts;
    return;
  }
  const Network b = network::simplify(network::assign(network::parse(e.expression), e.values));
  if (degenerate(b)) {
    e.reduced = e.reduced_structure = std::string(b.kind == K::Open ? "open" : "rigid");
    e.reduced_counts = {};
    return;
  }
  const Network c = network::renamed(network::canonical(b));
  e.reduced = network::to_string(c, true);
  e.reduced_structure = network::structure(c);
  e.reduced_counts = network::count_elements(c);
}
}  // namespace

std::optional<std::pair<std::string, network::Params>> reduced_design(const StructureEntry& e) {
  if (e.values.size() < static_cast<std::size_t>(e.counts.elements)) return std::nullopt;
  const Network b = network::simplify(network::assign(network::parse(e.expression), e.values));
  if (degenerate(b)) return std::nullopt;
  const Network c = network::renamed(network::canonical(b));
  std::vector<const Network*> ls;
  leaves(c, ls);
  network::Params values;
  for (const Network* l : ls) values[l->name] = l->value;
  return std::make_pair(network::to_string(c), values);
}

std::vector<StructureEntry> structure_search_batched(const std::vector<std::string>& expressions, const StructureBatch& optimise,
                                                     const StructureProgressFn& progress) {
  const std::size_t n = expressions.size();
  std::vector<StructureEntry> entries(n);
  std::map<std::string, std::size_t> by_structure;
  std::map<int, std::vector<std::size_t>> layers;
  long total_elements = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Network net = network::parse(expressions[i]);
    const auto names = network::parameter_names(net);
    entries[i].expression = expressions[i];
    entries[i].counts = network::count_elements(net);
    if (static_cast<int>(names.size()) != entries[i].counts.elements)
      throw InvalidArgument("structure search: '" + expressions[i] + "' uses an element name twice");
    by_structure.emplace(network::structure(net), i);
    layers[entries[i].counts.elements].push_back(i);
    total_elements += entries[i].counts.elements;
  }
  const auto t0 = std::chrono::steady_clock::now();
  StructureProgress state;
  state.total = static_cast<int>(n);
  long elements_done = 0;
  for (const auto& [size, members] : layers) {
    // Warm starts of one size come from smaller networks only: all known before the size starts.
    std::vector<StructureTask> tasks;
    std::vector<std::optional<Warm>> warms;
    for (const std::size_t k : members) {
      warms.push_back(best_warm(entries[k].expression, by_structure, entries, size));
      tasks.push_back({k, entries[k].expression,
                       warms.back() ? std::vector<network::Params>{warms.back()->values} : std::vector<network::Params>{}});
    }
    const auto layer0 = std::chrono::steady_clock::now();
    optimise(tasks, [&](std::size_t m, const StructureOutcome& o) {
      StructureEntry& e = entries[tasks[m].index];
      e.values = o.values, e.J = o.J, e.cost = o.cost, e.feasible = o.feasible, e.evaluations = o.evaluations;
      e.unstable = o.unstable;
      e.warm_from = warms[m] ? warms[m]->from : std::string();
      e.seconds = o.seconds >= 0 ? o.seconds : std::chrono::duration<double>(std::chrono::steady_clock::now() - layer0).count();
      describe_reduced(e);
      ++state.done;
      elements_done += e.counts.elements;
      state.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      state.remaining = state.elapsed / static_cast<double>(elements_done) * static_cast<double>(total_elements - elements_done);
      state.last = &e;
      if (e.feasible && e.J < state.best_J) state.best_J = e.J, state.best = e.reduced;
      if (progress) progress(state);
    });
  }
  return entries;
}

std::vector<StructureEntry> structure_search(const std::vector<std::string>& expressions, const StructureOptimiser& optimise,
                                             const StructureProgressFn& progress) {
  return structure_search_batched(
      expressions,
      [&](const std::vector<StructureTask>& tasks, const std::function<void(std::size_t, const StructureOutcome&)>& done) {
        std::mutex mutex;
        tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t m) {
          const auto t = std::chrono::steady_clock::now();
          StructureOutcome o = optimise(tasks[m].index, tasks[m].expression, tasks[m].warm);
          o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
          std::lock_guard<std::mutex> lock(mutex);
          done(m, o);
        });
      },
      progress);
}

std::vector<std::size_t> ranking(const std::vector<StructureEntry>& entries) {
  std::vector<std::size_t> idx(entries.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    const StructureEntry &x = entries[a], &y = entries[b];
    if (x.feasible != y.feasible) return x.feasible;
    if (x.cost != y.cost) return x.cost < y.cost || std::isnan(y.cost);
    return x.reduced_counts.elements < y.reduced_counts.elements;
  });
  return idx;
}

std::vector<ParetoPoint> pareto_points(const std::vector<StructureEntry>& entries) {
  std::map<std::pair<int, int>, ParetoPoint> best;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const StructureEntry& e = entries[i];
    if (!e.feasible || !std::isfinite(e.J)) continue;
    const auto key = std::make_pair(e.reduced_counts.elements, e.reduced_counts.inerters);
    auto it = best.find(key);
    if (it == best.end() || e.J < it->second.J)
      best[key] = ParetoPoint{key.first, key.second, e.J, e.reduced, i, false};
  }
  std::vector<ParetoPoint> out;
  for (auto& [k, p] : best) out.push_back(p);
  // Dominated: another point no more complex and no worse (J within 1e-9), better in one respect.
  for (auto& p : out) {
    p.pareto = std::none_of(out.begin(), out.end(), [&](const ParetoPoint& q) {
      const bool no_worse = q.elements <= p.elements && q.inerters <= p.inerters && q.J <= p.J * (1 + 1e-9);
      return no_worse && (q.elements < p.elements || q.inerters < p.inerters || q.J < p.J * (1 - 1e-9));
    });
  }
  return out;
}

namespace {
// prune() of an optimum with the study's cost of a bound network (a rigid network is no design).
template <class CostOfNetwork>
network::Params prune_optimum(const std::string& expression, const network::Params& values, CostOfNetwork&& cost) {
  return prune(
      expression, values,
      [&](const network::Params& p) {
        const Network net = network::resolve(expression, p);
        return network::simplify(net).kind == K::Rigid ? static_cast<double>(INFINITY) : cost(net);
      },
      prune_tolerance);
}
}  // namespace

LayoutResult run_search(const Study& study_in, const SearchTask& task, const numerics::Progress& progress,
                        const DesignBatch& batch) {
  if (task.coarse) {  // multi-fidelity layouts: all: the exhaustive search on the coarse study
    if (!study_in.coarse) throw InvalidArgument(study_in.source + ": a coarse search task needs a study with a coarse study");
    SearchTask t = task;
    t.coarse = false;
    return run_search(*study_in.coarse, t, progress, {});  // the batch evaluates designs on this study, not the coarse one
  }
  if (task.refine) {  // multi-fidelity layouts: all: a reduced network refined here from its coarse optimum
    if (task.warm.empty()) throw InvalidArgument("run_search: a refine task needs its start (warm.front())");
    LayoutResult c;
    c.layout = c.expression = task.layout;
    c.values = task.warm.front();
    c.cost.J = NAN;
    try {
      return refine_layout(study_in, task.layout, c, progress, batch);
    } catch (const NumericalError&) {  // the final evaluation failed: no design
      LayoutResult r;
      r.layout = r.expression = task.layout;
      r.cost.J = INFINITY;
      return r;
    }
  }
  if (!task.network) return optimise_layout(study_in, task.layout, progress, task.warm, batch);
  Study study = study_in;
  study.search.grid_variables = std::max(study.search.grid_variables, grid_variables);
  const std::string& expression = task.layout;
  LayoutResult r;
  try {
    r = optimise_layout(study, expression, progress, task.warm, batch);
    const auto pruned = prune_optimum(expression, r.values, [&](const Network& n) { return evaluate(study, n).penalised(); });
    if (pruned != r.values) r.values = pruned, r.cost = evaluate(study, network::resolve(expression, pruned));
  } catch (const NumericalError&) {  // the best point's final evaluation failed: no design
    r = LayoutResult{};
    r.layout = r.expression = expression;
    r.cost.J = INFINITY;
  } catch (const ModelError&) {  // every point failed and the best is a rigid suspension
    r = LayoutResult{};
    r.layout = r.expression = expression;
    r.cost.J = INFINITY;
  }
  return r;
}

StructureOutcome structure_outcome(const LayoutResult& r) {
  return StructureOutcome{r.values, r.cost.J, r.cost.penalised(), r.cost.feasible && std::isfinite(r.cost.J), r.evaluations,
                          r.unstable};
}

std::vector<StructureEntry> optimise_all(const Study& study, std::vector<LayoutResult>& results,
                                         const StructureProgressFn& progress) {
  results.assign(study.layouts.size(), LayoutResult{});
  return structure_search(
      study.layouts,
      [&](std::size_t i, const std::string& expression, const std::vector<network::Params>& warm) {
        results[i] = run_search(study, SearchTask{expression, warm, true});
        return structure_outcome(results[i]);
      },
      progress);
}

ModelLayoutResult run_search(const ModelStudy& study_in, const SearchTask& task, const numerics::Progress& progress) {
  if (task.coarse || task.refine) throw InvalidArgument(study_in.source + ": a model study has no coarse or refine tasks");
  if (!task.network) return optimise_layout(study_in, task.layout, progress, task.warm);
  ModelStudy study = study_in;
  study.search.grid_variables = std::max(study.search.grid_variables, grid_variables);
  const std::string& expression = task.layout;
  ModelLayoutResult r;
  try {
    r = optimise_layout(study, expression, progress, task.warm);
    const auto pruned = prune_optimum(expression, r.values, [&](const Network& n) { return evaluate(study, n).penalised; });
    if (pruned != r.values) {
      r.values = pruned, r.cost = evaluate(study, network::resolve(expression, pruned));
      r.at_bounds.clear();
      for (const auto& [name, v] : pruned)
        if (v == 0 || std::isinf(v)) r.at_bounds.push_back(name);
    }
  } catch (const NumericalError&) {  // no design
    r = ModelLayoutResult{};
    r.layout = r.expression = expression;
    r.cost.feasible = false;
  } catch (const ModelError&) {
    r = ModelLayoutResult{};
    r.layout = r.expression = expression;
    r.cost.feasible = false;
  }
  return r;
}

StructureOutcome structure_outcome(const ModelLayoutResult& r) {
  return StructureOutcome{r.values, r.cost.J, r.cost.penalised, r.cost.feasible && std::isfinite(r.cost.J), r.evaluations};
}

std::vector<StructureEntry> optimise_all(const ModelStudy& study, std::vector<ModelLayoutResult>& results,
                                         const StructureProgressFn& progress) {
  results.assign(study.layouts.size(), ModelLayoutResult{});
  return structure_search(
      study.layouts,
      [&](std::size_t i, const std::string& expression, const std::vector<network::Params>& warm) {
        results[i] = run_search(study, SearchTask{expression, warm, true});
        return structure_outcome(results[i]);
      },
      progress);
}

}  // namespace inerta::optim
