#include "inerta/optim/report.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <numbers>
#include <utility>

#include "inerta/analysis/periodic.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::optim {

namespace {

SpeedCurve curve_of(const std::string& label, const std::vector<analysis::SpeedResult>& r) {
  SpeedCurve c;
  c.catenary = label;
  for (const auto& x : r) c.speed.push_back(x.speed), c.sigma.push_back(x.stats.std), c.mean.push_back(x.stats.mean);
  return c;
}

}  // namespace

std::vector<SpeedCurve> sigma_curves(const Study& study, const network::Network& net) {
  if (study.method == Study::Method::Time) return sigma_curves_time(study, net);
  std::vector<SpeedCurve> curves;
  const DesignPantographs d = design_pantographs(study, net);
  for (std::size_t i = 0; i < study.catenaries.size(); ++i)
    curves.push_back(
        curve_of(study.catenary_labels[i], analysis::sweep_periodic(d.pantographs[i], *study.catenaries[i],
                                                                    study.contact, study.speeds, study.harmonics)));
  return curves;
}

std::vector<SpeedCurve> sigma_curves_time(const Study& study, const network::Network& net, bool centripetal,
                                          const std::function<void(int, int)>& progress,
                                          std::vector<std::vector<analysis::SpeedResult>>* runs) {
  // The catenaries' sweeps run concurrently (nested oneTBB loops), so one sweep's slowest speeds
  // overlap the others' instead of idling a core.
  std::vector<SpeedCurve> curves(study.catenaries.size());
  std::vector<std::vector<analysis::SpeedResult>> results(study.catenaries.size());
  analysis::RunOptions options;
  if (study.limits.acceptance)  // the criteria's filter for the 20 Hz statistics, as evaluate_time
    options.filter_cutoff = study.limits.acceptance->filter_cutoff, options.filter_order = study.limits.acceptance->filter_order;
  const int total = static_cast<int>(study.catenaries.size() * study.speeds.size());
  std::mutex mutex;
  int done = 0;
  const DesignPantographs d = design_pantographs(study, net);
  tbb::parallel_for(std::size_t{0}, study.catenaries.size(), [&](std::size_t i) {
    pantograph::Pantograph m = d.pantographs[i];
    m.model.options.centripetal = centripetal;
    results[i] = analysis::sweep(m, *study.catenaries[i], study.contact, study.speeds, options, [&](int, int) {
      std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (progress) progress(done, total);
    });
    curves[i] = curve_of(study.catenary_labels[i], results[i]);
  });
  if (runs) *runs = std::move(results);
  return curves;
}

std::vector<MarginRow> acceptance_margins(const Study& study, const std::string& design,
                                          const std::vector<std::vector<analysis::SpeedResult>>& runs) {
  std::vector<MarginRow> rows;
  if (!study.limits.acceptance) return rows;
  for (std::size_t i = 0; i < runs.size() && i < study.catenary_labels.size(); ++i)
    for (const analysis::SpeedResult& x : runs[i]) {
      if (!x.stable()) continue;
      const std::vector<analysis::VerdictInput> inputs = analysis::verdict_inputs(x);
      for (std::size_t c = 0; c < inputs.size(); ++c)
        for (const analysis::CriterionResult& r : analysis::assess(*study.limits.acceptance, inputs[c]))
          rows.push_back({design, study.catenary_labels[i], x.speed, static_cast<int>(c), r,
                          r.assessed ? analysis::relative_margin(r) : NAN});
    }
  return rows;
}

StudyCost worst_of(const std::vector<SpeedCurve>& curves) {
  StudyCost c;
  c.J = -1;
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t k = 0; k < curves[i].sigma.size(); ++k)
      if (curves[i].sigma[k] > c.J)
        c.J = curves[i].sigma[k], c.speed = curves[i].speed[k], c.mean = curves[i].mean[k],
        c.catenary = static_cast<int>(i);
  return c;
}

pantograph::Pantograph rig_model(const Study& study, const network::Network& net) {
  pantograph::Pantograph rig = study.pantograph;
  const mbs::Model& p = study.pantograph.model;
  mbs::State x = mbs::assemble(p, 0.0);
  mbs::static_equilibrium(p, 0.0, x);
  const auto& f = p.forces[static_cast<std::size_t>(pantograph::suspension_index(p))];
  rig.model = pantograph::with_suspension(p, net, f->length(p, x));
  return rig;
}

std::vector<ForceHistory> contact_histories(const Study& study, const network::Network& net, double speed) {
  const std::size_t n = study.catenaries.size();
  std::vector<ForceHistory> h(n);
  std::exception_ptr error;
  std::mutex mutex;
  const analysis::RunOptions defaults;
  const DesignPantographs d = design_pantographs(study, net);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    try {
      const auto sys = study.catenaries[i]->couple(d.pantographs[i], study.contact, speed);
      const analysis::RunOptions o = defaults;
      analysis::SpeedResult r = analysis::run_speed(*sys, o);
      const std::size_t per = r.F.size() / static_cast<std::size_t>(r.spans),
                        keep = std::min(r.F.size(), per * static_cast<std::size_t>(o.window_spans));
      h[i].catenary = study.catenary_labels[i];
      h[i].speed = speed;
      h[i].t.assign(r.t.end() - static_cast<long>(keep), r.t.end());
      h[i].F.assign(r.F.end() - static_cast<long>(keep), r.F.end());
      h[i].stats = r.stats;
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  });
  if (error) std::rethrow_exception(error);
  return h;
}

CostMap cost_map(const Study& study, const std::string& layout, const network::Params& values, const std::string& x,
                 const std::vector<double>& xs, const std::string& y, const std::vector<double>& ys,
                 const std::function<void(int, int)>& progress) {
  CostMap map{layout, x, y, values, xs, ys, std::vector<double>(xs.size() * ys.size(), NAN)};
  map.values.erase(x), map.values.erase(y);
  const auto free = free_parameters(layout);
  for (const auto& name : {x, y})
    if (std::find(free.begin(), free.end(), name) == free.end())
      throw ModelError(fmt::format("layout '{}' has no free element '{}' to map", layout, name));
  std::mutex mutex;
  int done = 0;
  const int total = static_cast<int>(map.J.size());
  tbb::parallel_for(std::size_t{0}, map.J.size(), [&](std::size_t n) {
    network::Params p = map.values;
    p[x] = xs[n / ys.size()], p[y] = ys[n % ys.size()];
    try {
      map.J[n] = evaluate(study, network::resolve(layout, p)).J;
    } catch (const network::NetworkError&) {
      throw;  // a wrong layout or value set is a programming error, not a point of the map
    } catch (const std::exception&) {
      // a rigid suspension or no valid steady state: no value (NaN)
    }
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress) progress(done, total);
  });
  return map;
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(n > 1 ? a + (b - a) * k / (n - 1) : a);
  return v;
}

int best_with(const std::vector<LayoutResult>& results, const std::string& x, const std::string& y) {
  int best = -1;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto free = free_parameters(results[i].layout);
    const bool both =
        std::find(free.begin(), free.end(), x) != free.end() && std::find(free.begin(), free.end(), y) != free.end();
    if (both && (best < 0 || results[i].cost.penalised() < results[static_cast<std::size_t>(best)].cost.penalised()))
      best = static_cast<int>(i);
  }
  return best;
}

bool has_inerter(const network::Network& net) {
  const network::Network s = network::simplify(net);
  std::function<bool(const network::Network&)> any = [&](const network::Network& n) {
    if (n.kind == network::Network::Kind::Inerter) return n.value > 0 && std::isfinite(n.value);
    return std::any_of(n.children.begin(), n.children.end(), any);
  };
  return any(s);
}

Report make_report(const Study& study, const std::vector<LayoutResult>& results, const ReportOptions& options,
                   const ReportProgress& progress) {
  if (results.empty()) throw std::invalid_argument("make_report needs at least one layout result");
  const int steps = 5;
  auto step = [&](int k, const std::string& what, int done = 0, int total = 1) {
    if (progress) progress(k, steps, what, done, total);
  };
  Report r;
  r.study = study.name;
  r.catenaries = study.catenary_labels;
  r.baseline = {"default", "", {}, default_suspension(study)};
  std::size_t b = 0;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].cost.penalised() < results[b].cost.penalised()) b = i;  // within the limits first
  if (options.best >= 0) {
    if (static_cast<std::size_t>(options.best) >= results.size())
      throw std::invalid_argument(fmt::format("make_report: best = {} but there are {} layout results", options.best, results.size()));
    b = static_cast<std::size_t>(options.best);
  }
  r.best = {"best (" + results[b].layout + ")", results[b].layout, results[b].values,
            design_network(results[b].layout, results[b].values)};

  step(1, study.method == Study::Method::Time ? "σ(v) of the default and the best design (time domain)"
                                               : "σ(v) of the default and the best design (periodic)");
  if (study.method == Study::Method::Time && study.limits.acceptance) {  // and every criterion's margin
    std::vector<std::vector<analysis::SpeedResult>> runs_default, runs_best;
    r.sigma_default = sigma_curves_time(study, r.baseline.net, true, {}, &runs_default);
    r.sigma_best = sigma_curves_time(study, r.best.net, true, {}, &runs_best);
    r.acceptance = study.limits.acceptance->name;
    r.margins = acceptance_margins(study, r.baseline.label, runs_default);
    const auto best = acceptance_margins(study, r.best.label, runs_best);
    r.margins.insert(r.margins.end(), best.begin(), best.end());
    // A commissioned study: the static contact force over the working range, a row of each design at
    // standstill on the reference line (speed 0), like every criterion (issue 49).
    if (study.commissioned())
      for (const auto* d : {&r.baseline, &r.best})
        if (const auto c = design_pantographs(study, d->net).commissioning)
          for (const analysis::CriterionResult& x : analysis::assess_static(*study.limits.acceptance, *c))
            r.margins.push_back({d->label, "reference line at standstill", 0.0, 0, x, x.assessed ? analysis::relative_margin(x) : NAN});
  } else {
    r.sigma_default = sigma_curves(study, r.baseline.net);
    r.sigma_best = sigma_curves(study, r.best.net);
  }
  r.default_cost = worst_of(r.sigma_default);
  r.best_cost = worst_of(r.sigma_best);
  step(1, "", 1, 1);

  step(2, "head FRF on the test rig, default and best");
  std::vector<double> f = options.frf_f;
  if (f.empty())
    for (int k = 0; k <= 398; ++k) f.push_back(0.1 + 0.05 * k);
  r.frf_output = options.frf_output;
  r.frf_default = analysis::frf_linear(rig_model(study, r.baseline.net), {options.frf_output}, f);
  r.frf_best = analysis::frf_linear(rig_model(study, r.best.net), {options.frf_output}, f);
  step(2, "", 1, 1);

  r.history_speed = options.history_speed;
  step(3, fmt::format("contact force at {:g} km/h, default and best (time domain)", options.history_speed * 3.6));
  r.history_default = contact_histories(study, r.baseline.net, options.history_speed);
  r.history_best = contact_histories(study, r.best.net, options.history_speed);
  step(3, "", 1, 1);

  const int m = best_with(results, "b", "k");
  if (options.map_size < 2) {
    r.map_note = "no J2 map requested";
  } else if (study.method == Study::Method::Time) {
    r.map_note = fmt::format("no J2 map for a time-domain study ({} × {} runs of every catenary and speed)",
                             options.map_size, options.map_size);
  } else if (m < 0) {
    r.map_note = "no layout of the study has free b and k";
  } else {
    const LayoutResult& lr = results[static_cast<std::size_t>(m)];
    const double bo = lr.values.at("b"), ko = lr.values.at("k");
    const double b_max = std::isfinite(bo) ? std::max(options.map_b_max, 1.25 * bo) : options.map_b_max;
    const double k_max = std::isfinite(ko) ? std::max(options.map_k_max, 1.25 * ko) : options.map_k_max;
    step(4, fmt::format("J2 map over (b, k) of {}, {}×{} points", lr.layout, options.map_size, options.map_size));
    r.map = cost_map(study, lr.layout, lr.values, "b", linspace(0, b_max, options.map_size), "k",
                     linspace(0, k_max, options.map_size), [&](int done, int total) { step(4, "", done, total); });
    r.map_opt_x = bo, r.map_opt_y = ko, r.map_opt_J = lr.cost.J;
  }
  if (!r.map) step(4, "J2 map: " + r.map_note, 1, 1);

  std::vector<Design> designs{r.best};
  if (!has_inerter(r.best.net) && r.map) {
    // The correction acts on inerters only: add the map's best point that has one.
    const CostMap& map = *r.map;
    std::size_t bi = 0, bj = 0;
    double bJ = INFINITY;
    for (std::size_t i = 0; i < map.xs.size(); ++i)
      for (std::size_t j = 0; j < map.ys.size(); ++j)
        if (map.xs[i] > 0 && map.at(i, j) < bJ) bJ = map.at(i, j), bi = i, bj = j;
    if (std::isfinite(bJ)) {
      network::Params p = map.values;
      p["b"] = map.xs[bi], p["k"] = map.ys[bj];
      designs.push_back({fmt::format("{} with b = {:.0f} kg, k = {:.0f} N/m", map.layout, map.xs[bi], map.ys[bj]),
                         map.layout, p, network::resolve(map.layout, p)});
    }
  }
  // Without an inerter the switch has nothing to act on (tests/optim/report_test.cpp shows the runs
  // are bit-identical), so such a design is simulated once: its curves off are those on.
  const int per = static_cast<int>(study.catenaries.size() * study.speeds.size());
  int total = 0;
  for (const auto& d : designs) total += (has_inerter(d.net) ? 2 : 1) * per;
  step(5, fmt::format("σ(v) with and without the centripetal correction, {} design(s) (time domain)", designs.size()),
       0, total);
  // All runs (design × on/off) concurrently, for the same reason as in sigma_curves_time.
  std::vector<Report::Centripetal> cs(designs.size());
  std::vector<std::pair<std::size_t, bool>> jobs;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    cs[i].design = designs[i];
    cs[i].off_simulated = has_inerter(designs[i].net);
    jobs.push_back({i, true});
    if (cs[i].off_simulated) jobs.push_back({i, false});
  }
  std::mutex mutex;
  int done = 0;
  tbb::parallel_for(std::size_t{0}, jobs.size(), [&](std::size_t j) {
    const std::size_t i = jobs[j].first;
    const bool on = jobs[j].second;
    int last = 0;
    auto curves = sigma_curves_time(study, designs[i].net, on, [&](int d, int) {
      std::lock_guard<std::mutex> lock(mutex);
      done += d - last, last = d;
      step(5, "", done, total);
    });
    (on ? cs[i].on : cs[i].off) = std::move(curves);
  });
  for (auto& c : cs) {
    if (!c.off_simulated) c.off = c.on;
    r.centripetal.push_back(std::move(c));
  }
  r.time_check = worst_of(r.centripetal.front().on);
  return r;
}

}  // namespace inerta::optim
