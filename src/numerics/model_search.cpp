#include "inerta/numerics/model_search.hpp"

#include <nlopt.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <stdexcept>

namespace inerta::numerics {

const char* optimiser_name(Optimiser o) {
  switch (o) {
    case Optimiser::Bobyqa: return "bobyqa";
    case Optimiser::Cobyla: return "cobyla";
    case Optimiser::Pattern: break;
  }
  return "pattern";
}

std::optional<Optimiser> parse_optimiser(std::string_view name) {
  for (Optimiser o : {Optimiser::Pattern, Optimiser::Bobyqa, Optimiser::Cobyla})
    if (name == optimiser_name(o)) return o;
  return std::nullopt;
}

double ranked(const Evaluation& e) { return e.g > 0 ? 1e100 * (1 + e.g) : e.f; }

namespace {

// One start's run: the cache, the budget and the best point so far.
struct Run {
  const std::vector<Variable>& vars;
  const ConstrainedCost& cost;
  const ConstrainedBatch& batch;
  const Progress& progress;
  int start = 0, done_before = 0;
  Run(const std::vector<Variable>& v, const ConstrainedCost& c, const ConstrainedBatch& b, const Progress& p, int s, int before)
      : vars(v), cost(c), batch(b), progress(p), start(s), done_before(before) {}
  std::map<std::vector<double>, Evaluation> cache;  // decoded values → evaluation
  int evals = 0;
  std::vector<double> best;
  double best_rank = INFINITY;
  bool have_best = false;

  // The evaluations of several decoded points, the uncached ones by `batch` or in parallel threads.
  std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& pts) {
    std::vector<std::vector<double>> fresh;
    for (const auto& p : pts)
      if (!cache.count(p) && std::find(fresh.begin(), fresh.end(), p) == fresh.end()) fresh.push_back(p);
    std::vector<Evaluation> e(fresh.size());
    if (!fresh.empty()) {
      if (batch) {
        e = batch(fresh);
        if (e.size() != fresh.size()) throw std::invalid_argument("model search: the batch gave a wrong number of evaluations");
      } else if (fresh.size() == 1) {
        e[0] = cost(fresh[0]);
      } else {
        tbb::parallel_for(std::size_t{0}, fresh.size(), [&](std::size_t k) { e[k] = cost(fresh[k]); });
      }
    }
    for (std::size_t k = 0; k < fresh.size(); ++k) cache[fresh[k]] = e[k], ++evals;
    std::vector<Evaluation> out;
    for (const auto& p : pts) {
      out.push_back(cache.at(p));
      const double r = ranked(out.back());
      if (!have_best || r < best_rank) best = p, best_rank = r, have_best = true;  // first of equals
    }
    if (!fresh.empty() && progress) progress(start, done_before + evals, best_rank);
    return out;
  }
};

struct ModelData {
  Run* run = nullptr;
  nlopt_opt opt = nullptr;
  std::vector<double> x;          // the decoded point: held variables keep their values
  std::vector<std::size_t> free;  // the variables the model varies
  std::vector<double> u0;         // their start coordinates: the start's own values there (no round trip)
  double f0 = 1;                  // |f| at the model's start: the penalty's and the fill-in's scale
  bool cobyla = false;
  int limit = 0;  // the run's evaluation count at which the model stops (its budget)
  bool out_of_budget = false;
  std::exception_ptr error;  // a cost's exception: rethrown after NLopt returns
};

// The evaluation at model coordinates u, or nothing after a stop (budget spent, or an error).
std::optional<Evaluation> evaluation_at(ModelData& d, const double* u) {
  if (d.out_of_budget || d.error) return std::nullopt;
  std::vector<double> x = d.x;
  for (std::size_t j = 0; j < d.free.size(); ++j) {
    const Variable& v = d.run->vars[d.free[j]];
    // NLopt scales its coordinates: its start comes back rounded. The same design within 1e-12 decades.
    if (std::abs(u[j] - d.u0[j]) > 1e-12 * std::max(1.0, std::abs(d.u0[j])))
      x[d.free[j]] = std::pow(10.0, std::clamp(u[j], std::log10(v.lo), std::log10(v.hi)));
  }
  if (!d.run->cache.count(x) && d.run->evals >= d.limit) {
    d.out_of_budget = true;
    nlopt_force_stop(d.opt);
    return std::nullopt;
  }
  try {
    return d.run->evaluate({x})[0];
  } catch (...) {  // NLopt's callbacks must not throw
    d.error = std::current_exception();
    nlopt_force_stop(d.opt);
    return std::nullopt;
  }
}

// What the model sees: BOBYQA the exact penalty, COBYLA the objective; 100 |f₀| where f is not finite.
double model_objective(unsigned, const double* u, double*, void* data) {
  auto& d = *static_cast<ModelData*>(data);
  const std::optional<Evaluation> e = evaluation_at(d, u);
  if (!e) return 0;  // after a forced stop NLopt returns without using it
  const double f = std::isfinite(e->f) ? e->f : 100 * d.f0;
  const double g = std::isfinite(e->g) ? std::max(0.0, e->g) : 1.0;
  return d.cobyla ? f : f + 10 * d.f0 * g;
}

// COBYLA's constraint g ≤ 0 (called at the objective's point: a cache hit).
double model_constraint(unsigned, const double* u, double*, void* data) {
  auto& d = *static_cast<ModelData*>(data);
  const std::optional<Evaluation> e = evaluation_at(d, u);
  return e && std::isfinite(e->g) ? e->g : 1.0;
}

// One model run from the run's best point over its finite variables, at most up to `limit`
// evaluations. True if it stopped at that budget before its steps reached min_step.
bool model_run(Run& run, const Options& o, Optimiser which, int limit) {
  ModelData d;
  d.run = &run;
  d.x = run.best;
  for (std::size_t i = 0; i < d.x.size(); ++i)
    if (d.x[i] > 0 && std::isfinite(d.x[i])) d.free.push_back(i);
  if (d.free.empty() || run.evals >= limit) return false;
  const double f0 = run.cache.at(run.best).f;
  d.f0 = std::isfinite(f0) && f0 != 0 ? std::abs(f0) : 1.0;
  d.cobyla = which == Optimiser::Cobyla;
  d.limit = limit;
  const auto n = static_cast<unsigned>(d.free.size());
  d.opt = nlopt_create(d.cobyla ? NLOPT_LN_COBYLA : NLOPT_LN_BOBYQA, n);
  if (!d.opt) throw std::runtime_error("model search: NLopt could not create its optimiser");
  std::vector<double> lb, ub, u, step(n, o.initial_step), tol(n, o.min_step);
  for (std::size_t i : d.free) {
    const Variable& v = run.vars[i];
    lb.push_back(std::log10(v.lo)), ub.push_back(std::log10(v.hi));
    u.push_back(std::clamp(std::log10(d.x[i]), lb.back(), ub.back()));
  }
  d.u0 = u;
  nlopt_set_lower_bounds(d.opt, lb.data());
  nlopt_set_upper_bounds(d.opt, ub.data());
  nlopt_set_min_objective(d.opt, model_objective, &d);
  if (d.cobyla) nlopt_add_inequality_constraint(d.opt, model_constraint, &d, 0.0);
  nlopt_set_initial_step(d.opt, step.data());
  nlopt_set_xtol_abs(d.opt, tol.data());  // steps finer than min_step decades: converged
  nlopt_set_maxeval(d.opt, 100 * std::max(1, limit));  // calls, cached ones too: no endless loop
  double fu = 0;
  const nlopt_result r = nlopt_optimize(d.opt, u.data(), &fu);
  nlopt_destroy(d.opt);
  if (d.error) std::rethrow_exception(d.error);
  if (r < 0 && r != NLOPT_FORCED_STOP && r != NLOPT_ROUNDOFF_LIMITED)
    throw std::runtime_error("model search: NLopt failed (" + std::string(nlopt_result_to_string(r)) + ")");
  return d.out_of_budget || r == NLOPT_MAXEVAL_REACHED;
}

// The limit check's points: each variable at each limit it can reach (open 0, rigid ∞), or, already
// at one, at the finite end next to it.
std::vector<std::vector<double>> limit_moves(const std::vector<Variable>& vars, const std::vector<double>& x) {
  std::vector<std::vector<double>> moves;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    auto with = [&](double v) {
      moves.push_back(x);
      moves.back()[i] = v;
    };
    if (x[i] == 0) {
      with(vars[i].lo);
    } else if (std::isinf(x[i])) {
      with(vars[i].hi);
    } else {
      if (vars[i].can_open) with(0.0);
      if (vars[i].can_rigid) with(INFINITY);
    }
  }
  return moves;
}

}  // namespace

Result model_search(const std::vector<Variable>& vars, const ConstrainedCost& cost, const Options& o, Optimiser which,
                    const Progress& progress, const ConstrainedBatch& batch) {
  if (which == Optimiser::Pattern) {  // the pattern search on the ranks
    const Cost c = [&](const std::vector<double>& v) { return ranked(cost(v)); };
    BatchCost b;
    if (batch)
      b = [&](const std::vector<std::vector<double>>& v) {
        std::vector<double> r;
        for (const Evaluation& e : batch(v)) r.push_back(ranked(e));
        return r;
      };
    return pattern_search(vars, c, o, progress, b);
  }
  for (const auto& v : vars)
    if (!(v.lo > 0) || !(v.hi > v.lo) || !std::isfinite(v.hi))
      throw std::invalid_argument("variable '" + v.name + "': need finite 0 < lo < hi");
  if (!(o.min_step > 0) || !(o.initial_step >= o.min_step) || !std::isfinite(o.initial_step))
    throw std::invalid_argument("model search: need 0 < min_step <= initial_step (decades), finite");
  if (o.max_evaluations < 1) throw std::invalid_argument("model search: max_evaluations must be >= 1");
  if (o.initial_values.empty()) throw std::invalid_argument("model search: needs a start (initial_values)");
  // Kept back for the limit check: one move per variable and reachable limit.
  int reserve = 0;
  for (const auto& v : vars) reserve += std::max(1, int{v.can_open} + int{v.can_rigid});
  Result out;
  out.cost = INFINITY;
  int total = 0;
  for (std::size_t s = 0; s < o.initial_values.size(); ++s) {
    const std::vector<double>& w = o.initial_values[s];
    if (w.size() != vars.size()) throw std::invalid_argument("model search: an initial point needs one value per variable");
    std::vector<double> x0(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) {  // as the pattern search's warm starts
      const Variable& v = vars[i];
      x0[i] = w[i] <= 0 ? (v.can_open ? 0.0 : v.lo) : std::isinf(w[i]) ? (v.can_rigid ? INFINITY : v.hi)
                                                                       : std::clamp(w[i], v.lo, v.hi);
    }
    Run run(vars, cost, batch, progress, static_cast<int>(s), total);
    run.evaluate({x0});
    const int model_limit = std::max(1, o.max_evaluations - reserve);
    bool exhausted = model_run(run, o, which, model_limit);
    // The limit check, and the model again from a better point while its budget lasts.
    for (;;) {
      const std::vector<std::vector<double>> moves = limit_moves(vars, run.best);
      std::size_t fresh = 0;
      for (const auto& m : moves) fresh += run.cache.count(m) ? 0 : 1;
      if (moves.empty() || run.evals + static_cast<int>(fresh) > o.max_evaluations) {
        exhausted = exhausted || fresh > 0;
        break;
      }
      const double before = run.best_rank;
      run.evaluate(moves);
      if (!(run.best_rank < before)) break;
      if (run.evals >= model_limit) {
        exhausted = true;  // a better point at a limit, and no budget to refine from it
        break;
      }
      exhausted = model_run(run, o, which, model_limit) || exhausted;
    }
    total += run.evals;
    out.exhausted = out.exhausted || exhausted;
    out.ends.push_back({run.best, run.best_rank});
    if (run.best_rank < out.cost || out.values.empty()) {
      out.cost = run.best_rank, out.values = run.best, out.best_start = static_cast<int>(s);
      out.u.clear();
      for (std::size_t i = 0; i < vars.size(); ++i)  // the search coordinate: 0 and ∞ in their half decades
        out.u.push_back(run.best[i] == 0 ? std::log10(vars[i].lo) - 0.75
                        : std::isinf(run.best[i]) ? std::log10(vars[i].hi) + 0.75 : std::log10(run.best[i]));
    }
  }
  out.evaluations = total;
  return out;
}

}  // namespace inerta::numerics
