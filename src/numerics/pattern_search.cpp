#include "inerta/numerics/pattern_search.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>

namespace inerta::numerics {

namespace {
double box_lo(const Variable& v) { return std::log10(v.lo) - (v.can_open ? 1.0 : 0.0); }
double box_hi(const Variable& v) { return std::log10(v.hi) + (v.can_rigid ? 1.0 : 0.0); }
}  // namespace

double decode(const Variable& v, double u) {
  const double a = std::log10(v.lo), b = std::log10(v.hi);
  if (v.can_open && u < a - 0.5) return 0.0;
  if (v.can_rigid && u > b + 0.5) return INFINITY;
  return std::pow(10.0, std::clamp(u, a, b));
}

std::string describe(double value) {
  if (value == 0) return "open";
  if (std::isinf(value)) return "rigid";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

Result pattern_search(const std::vector<Variable>& vars, const Cost& cost, const Options& o, const Progress& progress,
                      const BatchCost& batch) {
  // The costs of several decoded points: by `batch` if given, else in parallel threads.
  auto costs = [&](const std::vector<std::vector<double>>& values) {
    if (values.empty()) return std::vector<double>{};
    if (batch) {
      std::vector<double> c = batch(values);
      if (c.size() != values.size()) throw std::invalid_argument("pattern search: the batch cost gave a wrong number of costs");
      return c;
    }
    std::vector<double> c(values.size());
    tbb::parallel_for(std::size_t{0}, values.size(), [&](std::size_t k) { c[k] = cost(values[k]); });
    return c;
  };
  const std::size_t n = vars.size();
  for (const auto& v : vars)
    if (!(v.lo > 0) || !(v.hi > v.lo) || !std::isfinite(v.hi))
      throw std::invalid_argument("variable '" + v.name + "': need finite 0 < lo < hi");
  // Bounded work (issue 15): a positive finite mesh and budget.
  if (!(o.min_step > 0) || !(o.initial_step >= o.min_step) || !std::isfinite(o.initial_step))
    throw std::invalid_argument("pattern search: need 0 < min_step <= initial_step (decades), finite");
  if (o.max_evaluations < 1) throw std::invalid_argument("pattern search: max_evaluations must be >= 1");
  std::mt19937 rng(o.seed);
  Result best;
  best.cost = INFINITY;
  int total = 0;
  // At least one random start (the box centre), unless warm starts are given and starts is 0.
  const int random_starts = o.initial_values.empty() ? std::max(1, o.starts) : std::max(0, o.starts);
  for (const auto& w : o.initial_values)
    if (w.size() != n) throw std::invalid_argument("pattern search: an initial point needs one value per variable");
  // The grid's best point (a start after the warm ones), evaluated up front.
  std::vector<double> grid_best;
  int grid_evals = 0;
  if (n > 0 && static_cast<int>(n) <= o.grid_variables) {
    std::vector<std::vector<double>> axes(n);
    for (std::size_t i = 0; i < n; ++i)
      for (double u = box_lo(vars[i]); u <= box_hi(vars[i]) + 1e-9; u += 1.0) axes[i].push_back(u);
    std::vector<std::vector<double>> pts(1);
    for (const auto& ax : axes) {
      std::vector<std::vector<double>> next;
      for (const auto& p : pts)
        for (double u : ax) {
          next.push_back(p);
          next.back().push_back(u);
        }
      pts = std::move(next);
    }
    std::vector<std::vector<double>> vals(pts.size(), std::vector<double>(n));
    for (std::size_t k = 0; k < pts.size(); ++k)
      for (std::size_t i = 0; i < n; ++i) vals[k][i] = decode(vars[i], pts[k][i]);
    const std::vector<double> c = costs(vals);
    std::size_t k = 0;
    for (std::size_t j = 1; j < c.size(); ++j)
      if (c[j] < c[k]) k = j;
    grid_best = pts[k];
    grid_evals = static_cast<int>(pts.size());
  }
  const int warm_starts = static_cast<int>(o.initial_values.size());
  total += grid_evals;
  for (int start = 0; start < random_starts + warm_starts + (grid_best.empty() ? 0 : 1); ++start) {
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = box_lo(vars[i]), b = box_hi(vars[i]);
      if (start == random_starts + warm_starts) {
        u[i] = grid_best[i];
      } else if (start >= random_starts) {  // a warm start: its value's cell (0 and ∞ in their half decades)
        const double v = o.initial_values[static_cast<std::size_t>(start - random_starts)][i];
        const double la = std::log10(vars[i].lo), lb = std::log10(vars[i].hi);
        u[i] = v <= 0 ? (vars[i].can_open ? a + 0.25 : la) : std::isinf(v) ? (vars[i].can_rigid ? b - 0.25 : lb)
                                                              : std::clamp(std::log10(v), la, lb);
      } else {
        u[i] = start == 0 ? 0.5 * (a + b) : std::uniform_real_distribution<double>(a, b)(rng);
      }
    }
    // Cache of evaluated points: decoded values identify a design (0/∞ cells and clamped ends repeat).
    std::map<std::vector<double>, double> cache;
    int evals = 0;
    auto values_of = [&](const std::vector<double>& x) {
      std::vector<double> v(n);
      for (std::size_t i = 0; i < n; ++i) v[i] = decode(vars[i], x[i]);
      return v;
    };
    auto evaluate_all = [&](const std::vector<std::vector<double>>& pts) {
      std::vector<std::vector<double>> vals(pts.size());
      std::vector<double> c(pts.size(), NAN);
      std::vector<char> todo(pts.size(), 0);
      for (std::size_t k = 0; k < pts.size(); ++k) {
        vals[k] = values_of(pts[k]);
        auto it = cache.find(vals[k]);
        if (it != cache.end())
          c[k] = it->second;
        else
          todo[k] = 1;
      }
      std::vector<std::vector<double>> fresh;
      for (std::size_t k = 0; k < pts.size(); ++k)
        if (todo[k]) fresh.push_back(vals[k]);
      const std::vector<double> cf = costs(fresh);
      for (std::size_t k = 0, f = 0; k < pts.size(); ++k)
        if (todo[k]) c[k] = cf[f++];
      for (std::size_t k = 0; k < pts.size(); ++k)
        if (todo[k]) cache[vals[k]] = c[k], ++evals;
      return c;
    };
    double fu = evaluate_all({u})[0];
    double step = o.initial_step;
    // Polls are counted too: a run of cached (repeated) points cannot loop without end.
    long polls = 0;
    const long max_polls = 100L * o.max_evaluations;
    while (step >= o.min_step && evals < o.max_evaluations && polls++ < max_polls) {
      std::vector<std::vector<double>> poll;
      for (std::size_t i = 0; i < n; ++i)
        for (double s : {+1.0, -1.0}) {
          std::vector<double> p = u;
          p[i] = std::clamp(p[i] + s * step, box_lo(vars[i]), box_hi(vars[i]));
          poll.push_back(p);
        }
      std::vector<double> c = evaluate_all(poll);
      std::size_t k = 0;
      for (std::size_t j = 1; j < c.size(); ++j)
        if (c[j] < c[k]) k = j;  // first of equals: deterministic
      if (c[k] < fu) {
        u = poll[k], fu = c[k];
        step = std::min(2 * step, o.initial_step);  // expand after a success
      } else {
        step *= 0.5;
      }
      if (progress) progress(start, total + evals, std::min(best.cost, fu));
    }
    total += evals;
    if (step >= o.min_step) best.exhausted = true;  // stopped by the budget, not by the mesh
    best.ends.push_back({values_of(u), fu});
    if (fu < best.cost || best.values.empty()) {  // the first start stands even if nothing was finite
      best.cost = fu, best.u = u, best.values = values_of(u), best.best_start = start;
    }
  }
  best.evaluations = total;
  return best;
}

}  // namespace inerta::numerics
