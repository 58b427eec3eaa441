#include "inerta/optim/study_run.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <mutex>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"

namespace inerta::optim {

CheckResult run_check(const Study& study, const CheckTask& task) {
  const network::Network net = task.layout.empty() ? default_suspension(study) : design_network(task.layout, task.values);
  CheckResult r;
  try {
    r.cost = task.time ? evaluate_time(study, net) : evaluate(study, net);
  } catch (const NumericalError& e) {
    r.failure = e.what();
    r.cost.J = INFINITY;
  }
  return r;
}

std::vector<LayoutResult> LocalExecutor::search(const Study& study, const std::vector<SearchTask>& tasks,
                                                const std::function<void(std::size_t, const LayoutResult&)>& done,
                                                const std::function<void(std::size_t, int, int, double)>& searching) {
  std::vector<LayoutResult> out(tasks.size());
  const bool networks = std::any_of(tasks.begin(), tasks.end(), [](const SearchTask& t) { return t.network; });
  if (networks) {  // the networks of one size in parallel, as optimise_all
    std::mutex mutex;
    tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t i) {
      out[i] = run_search(study, tasks[i]);
      std::lock_guard<std::mutex> lock(mutex);
      if (done) done(i, out[i]);
    });
    return out;
  }
  for (std::size_t i = 0; i < tasks.size(); ++i) {  // one after another, each search's polls in parallel
    numerics::Progress p;
    if (searching) p = [&](int start, int evals, double best) { searching(i, start, evals, best); };
    out[i] = run_search(study, tasks[i], p);
    if (done) done(i, out[i]);
  }
  return out;
}

std::vector<CheckResult> LocalExecutor::check(const Study& study, const std::vector<CheckTask>& tasks) {
  std::vector<CheckResult> out;
  for (const auto& t : tasks) out.push_back(run_check(study, t));
  return out;
}

std::string StudyOutcome::recheck_csv() const {
  std::string csv = "network,reduced,J2_periodic,J2_time,v_kmh_time,periodic_rank,settling_spans\n";
  for (const Recheck& c : rechecks) {
    if (!c.failure.empty()) continue;
    const auto& e = entries[c.entry];
    csv += fmt::format("\"{}\",\"{}\",{:.10g},{:.10g},{:.6g},{},{:.6g}\n", e.expression, e.reduced, e.J, c.time.J,
                       c.time.speed * 3.6, c.periodic_rank, c.settling_spans);
  }
  return csv;
}

std::string StudyOutcome::screened_csv() const {
  std::string csv = "screen_rank,network,reduced,coarse_rank,J_coarse,J,feasible,violation,refined,failure\n";
  for (std::size_t k = 0; k < screened.size(); ++k) {
    const Screened& c = screened[k];
    const StructureEntry& e = entries[c.entry];
    csv += fmt::format("{},\"{}\",\"{}\",{},{:.10g},{:.10g},{},\"{}\",{},\"{}\"\n", k + 1, e.expression, e.reduced, c.coarse_rank,
                       e.J, c.cost.J, c.cost.feasible ? 1 : 0, c.cost.violation, c.refined ? 1 : 0, c.failure);
  }
  return csv;
}

std::string StudyOutcome::refined_csv() const {
  // A commissioned study (issue 49): the stock suspension ranked with the refined designs, the objective's
  // σ and F_m, and what commissioning set (a, G(0), the static force and its range).
  const bool commissioned = study && study->commissioned();
  std::string csv =
      "rank,network,coarse_network,coarse_rank,J2_coarse,J2_start,J2,vs_default_pct,feasible,violation,binding,"
      "binding_margin,evaluations,budget_exhausted,values";
  if (!screened.empty()) csv += ",screen_rank";
  csv += commissioned ? ",design,objective,sigma_N,mean_N,a,static_stiffness,static_force,static_force_min,static_force_max\n" : "\n";
  for (std::size_t k = 0; k < results.size() && k < refinements.size(); ++k) {
    const LayoutResult& r = results[k];
    const bool stock = refinements[k].entry == Refinement::kStock;
    const StructureEntry* e = stock ? nullptr : &entries[refinements[k].entry];
    std::string values;
    for (const auto& [name, v] : r.values) values += fmt::format("{}{}={:.10g}", values.empty() ? "" : ";", name, v);
    csv += fmt::format("{},\"{}\",\"{}\",{},{:.10g},{:.10g},{:.10g},{:.6g},{},\"{}\",\"{}\",{:.6g},{},{},\"{}\"", k + 1,
                       r.expression, e ? e->expression : "-", refinements[k].coarse_rank, e ? e->J : coarse_default_cost.J,
                       stock ? r.cost.J : r.coarse_here.J, r.cost.J, 100 * (r.cost.J - default_cost.J) / default_cost.J,
                       r.cost.feasible ? 1 : 0, r.cost.violation, r.cost.binding, r.cost.binding_margin, r.evaluations,
                       r.budget_exhausted ? 1 : 0, values);
    if (!screened.empty()) csv += fmt::format(",{}", refinements[k].screen_rank);
    if (commissioned) {
      const analysis::Commissioning c = r.cost.commissioning.value_or(analysis::Commissioning{});
      csv += fmt::format(",{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", stock ? "default" : "refined",
                         objective_name(*study), r.cost.sigma, r.cost.mean, c.a, c.static_stiffness, c.static_force,
                         c.range_min(), c.range_max());
    } else {
      csv += "\n";
    }
  }
  return csv;
}

namespace {

class NoEvents : public StudyEvents {};

// The best few distinct feasible designs of the fast path, re-checked in the time domain (the reference),
// ranked by their time-domain J2 (issue 24: the fast path can be off by a few per cent).
std::vector<Recheck> recheck(const Study& study, const std::vector<StructureEntry>& entries, int count, StudyExecutor& ex) {
  std::vector<std::string> seen;
  std::vector<Recheck> out;
  std::vector<CheckTask> tasks;
  for (std::size_t i : ranking(entries)) {
    const auto& e = entries[i];
    if (static_cast<int>(seen.size()) == count) break;
    if (!e.feasible || std::find(seen.begin(), seen.end(), e.reduced_structure) != seen.end()) continue;
    seen.push_back(e.reduced_structure);
    Recheck c;
    c.entry = i, c.periodic_rank = static_cast<int>(seen.size());
    out.push_back(c);
    tasks.push_back({e.expression, e.values, true});
  }
  const std::vector<CheckResult> checked = ex.check(study, tasks);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].time = checked[k].cost, out[k].failure = checked[k].failure;
    if (!out[k].failure.empty()) continue;
    // The slowest free vibration (Floquet multiplier of the periodic path): a time-domain run shorter
    // than its decay measures the transient's beating, not the steady state (issue 24 item 4).
    const auto& e = entries[out[k].entry];
    try {
      out[k].settling_spans = evaluate(study, network::resolve(e.expression, e.values)).settling_spans();
    } catch (const NumericalError&) {
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Recheck& x, const Recheck& y) { return x.time.J < y.time.J; });
  return out;
}

// Ranks 1…n of x (ties: their mean rank).
std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> i(x.size());
  for (std::size_t k = 0; k < i.size(); ++k) i[k] = k;
  std::stable_sort(i.begin(), i.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t k = 0; k < i.size();) {
    std::size_t e = k;
    while (e + 1 < i.size() && x[i[e + 1]] == x[i[k]]) ++e;
    for (std::size_t j = k; j <= e; ++j) r[i[j]] = 0.5 * static_cast<double>(k + e) + 1;
    k = e + 1;
  }
  return r;
}

// Spearman's ρ of two orders of the refined networks: `chosen[k]` (a rank: the order they were chosen in,
// or the coarse search's) and this study's (by the refined costs, penalised).
double spearman(const std::vector<LayoutResult>& refined, const std::vector<double>& chosen) {
  const std::size_t n = refined.size();
  if (n < 2) return NAN;
  std::vector<double> fine(n);
  for (std::size_t k = 0; k < n; ++k) fine[k] = refined[k].cost.penalised();
  const std::vector<double> a = ranks(chosen), b = ranks(fine);
  const double mean = 0.5 * static_cast<double>(n + 1);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t k = 0; k < n; ++k) sab += (a[k] - mean) * (b[k] - mean), saa += (a[k] - mean) * (a[k] - mean), sbb += (b[k] - mean) * (b[k] - mean);
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : NAN;
}

// The stock suspension as a study result: its expression and element values, its cost.
LayoutResult stock_result(const network::Network& baseline, const StudyCost& cost) {
  LayoutResult r;
  r.layout = r.expression = network::to_string(baseline, false);
  std::function<void(const network::Network&)> leaves = [&](const network::Network& n) {
    if (n.is_element()) r.values[n.name] = n.value;
    for (const auto& c : n.children) leaves(c);
  };
  leaves(baseline);
  r.cost = cost;
  r.evaluations = 1;
  r.stock = true;
  return r;
}

// Multi-fidelity `layouts: all`: the study's refine_networks best distinct reduced networks of the coarse
// search (feasible first, by the coarse ranking), each refined here from its coarse optimum; ranked by the
// cost here (penalised: within the limits first), ties by the coarse rank. Sets o.refinements.
std::vector<LayoutResult> refine_networks(const Study& study, StudyOutcome& o, StudyExecutor& ex, StudyEvents& events) {
  // The candidates: the best distinct reduced networks of the coarse search (screen of them, or
  // refine_networks without a screen), each at its coarse optimum.
  struct Candidate {
    std::size_t entry;
    std::string layout;
    network::Params values;
  };
  const bool screen = study.refine_screen > study.refine_networks;
  const std::size_t wanted = static_cast<std::size_t>(screen ? study.refine_screen : study.refine_networks);
  std::vector<std::string> seen;
  std::vector<Candidate> cands;
  for (std::size_t i : o.order) {
    if (cands.size() == wanted) break;
    const StructureEntry& e = o.entries[i];
    if (!std::isfinite(e.J)) continue;
    const auto design = reduced_design(e);
    if (!design || std::find(seen.begin(), seen.end(), e.reduced_structure) != seen.end()) continue;
    seen.push_back(e.reduced_structure);
    cands.push_back({i, design->first, design->second});
  }
  // The screen: each candidate evaluated here at its coarse optimum; the best refine_networks by that
  // cost (penalised: within the limits first; ties by the coarse rank) are refined, in that order.
  std::vector<std::size_t> pick(cands.size());
  for (std::size_t k = 0; k < pick.size(); ++k) pick[k] = k;
  std::vector<int> screen_rank(cands.size(), 0);
  if (screen && cands.size() > static_cast<std::size_t>(study.refine_networks)) {
    std::vector<std::size_t> entries;
    std::vector<CheckTask> checks;
    for (const Candidate& c : cands) entries.push_back(c.entry), checks.push_back({c.layout, c.values, false});
    events.screening(entries);
    const std::vector<CheckResult> got = ex.check(study, checks);
    std::stable_sort(pick.begin(), pick.end(), [&](std::size_t a, std::size_t b) {
      return got[a].cost.penalised() < got[b].cost.penalised();
    });
    for (std::size_t r = 0; r < pick.size(); ++r) {
      const std::size_t k = pick[r];
      screen_rank[k] = static_cast<int>(r) + 1;
      Screened sc;
      sc.entry = cands[k].entry, sc.coarse_rank = static_cast<int>(k) + 1, sc.cost = got[k].cost, sc.failure = got[k].failure;
      sc.refined = r < static_cast<std::size_t>(study.refine_networks);
      o.screened.push_back(std::move(sc));
    }
    pick.resize(static_cast<std::size_t>(study.refine_networks));
  }
  std::vector<SearchTask> tasks;
  std::vector<Refinement> from;
  for (std::size_t k : pick) {
    SearchTask t;
    t.layout = cands[k].layout, t.warm = {cands[k].values}, t.refine = true;
    tasks.push_back(std::move(t));
    Refinement f;
    f.entry = cands[k].entry, f.coarse_rank = static_cast<int>(k) + 1, f.screen_rank = screen_rank[k];
    from.push_back(f);
  }
  std::vector<std::size_t> entries;
  for (const auto& f : from) entries.push_back(f.entry);
  events.refining(entries);
  std::vector<LayoutResult> refined = ex.search(
      study, tasks, [&](std::size_t k, const LayoutResult& r) { events.refined(k, r); }, {});
  for (std::size_t k = 0; k < refined.size(); ++k) {  // the coarse search's side of each (not the task's)
    const StructureEntry& e = o.entries[from[k].entry];
    LayoutResult& r = refined[k];
    r.coarse_cost.J = e.J, r.coarse_cost.feasible = e.feasible, r.coarse_evaluations = e.evaluations;
  }
  {  // the order they were chosen in (the screen's, else the coarse search's) and the coarse search's own
    std::vector<double> chosen(refined.size()), coarse(refined.size());
    for (std::size_t k = 0; k < refined.size(); ++k) chosen[k] = static_cast<double>(k), coarse[k] = from[k].coarse_rank;
    o.rank_agreement = spearman(refined, chosen);
    o.coarse_rank_agreement = spearman(refined, coarse);
  }
  // A commissioned study: the stock suspension competes in the final ranking (issue 49), commissioned and
  // judged as every refined design; ahead of a design it ties with.
  if (study.commissioned()) refined.push_back(stock_result(o.baseline, o.default_cost)), from.push_back({Refinement::kStock, 0});
  std::vector<std::size_t> idx(refined.size());
  for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    const double x = refined[a].cost.penalised(), y = refined[b].cost.penalised();
    return x < y || (x == y && refined[a].stock && !refined[b].stock);
  });
  std::vector<LayoutResult> out;
  for (std::size_t k : idx) out.push_back(refined[k]), o.refinements.push_back(from[k]);
  return out;
}

BestDesign best_of(const LayoutResult& r, std::size_t index) {
  BestDesign b;
  b.index = index;
  b.layout = r.layout, b.expression = r.expression, b.values = r.values;
  b.net = design_network(r.layout, r.values);  // a named layout's fixed values stay the layout's (S2-default's c)
  b.J = r.cost.J, b.feasible = r.cost.feasible;
  return b;
}

}  // namespace

StudyOutcome run_study(const Study& study, const StudyOptions& options, StudyEvents* events_in, StudyExecutor* executor_in) {
  NoEvents none;
  StudyEvents& events = events_in ? *events_in : none;
  LocalExecutor local;
  StudyExecutor& ex = executor_in ? *executor_in : local;
  StudyOutcome o;
  o.study = study;
  o.baseline = default_suspension(study);
  const auto t0 = std::chrono::steady_clock::now();
  {
    const CheckResult def = ex.check(study, {CheckTask{}}).at(0);
    if (!def.failure.empty()) throw NumericalError(def.failure);
    o.default_cost = def.cost;
  }
  if (o.default_cost.unstable_speed > 0)
    throw NumericalError(fmt::format("{}: the default suspension's periodic solution is unstable at {:.4g} km/h "
                                     "(Floquet multiplier ≥ 1): the study has no baseline",
                                     study.source, o.default_cost.unstable_speed * 3.6));
  if (study.all && study.coarse) try {  // the entries' baseline: the default on the coarse study
      o.coarse_default_cost = evaluate(*study.coarse, o.baseline);
    } catch (const NumericalError&) {
      o.coarse_default_cost.J = NAN;
    }
  if (study.all) {
    std::vector<LayoutResult> all(study.layouts.size());
    o.entries = structure_search_batched(
        study.layouts,
        [&](const std::vector<StructureTask>& tasks, const std::function<void(std::size_t, const StructureOutcome&)>& done) {
          std::vector<SearchTask> st;
          for (const auto& t : tasks) st.push_back({t.expression, t.warm, true, study.coarse != nullptr});
          ex.search(study, st, [&](std::size_t k, const LayoutResult& r) {
            all[tasks[k].index] = r;
            done(k, structure_outcome(r));
          }, {});
        },
        [&](const StructureProgress& p) { events.network(p); });
    o.order = ranking(o.entries);
    if (study.coarse)  // multi-fidelity: the best distinct reduced networks refined here, ranked here
      o.results = refine_networks(study, o, ex, events);
    else
      for (std::size_t i : o.order) o.results.push_back(all[i]);  // ranked: results.csv best first
  } else {
    std::vector<SearchTask> tasks;
    for (const auto& l : study.layouts) tasks.push_back({l, {}, false});
    o.results = ex.search(
        study, tasks, [&](std::size_t i, const LayoutResult& r) { events.searched(i, r); },
        [&](std::size_t i, int start, int evals, double best) { events.searching(i, start, evals, best); });
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.results.empty()) throw InvalidArgument(study.source + ": the study has no layouts");
  std::size_t best = 0;
  for (std::size_t i = 0; i < o.results.size(); ++i)
    if (o.results[i].cost.penalised() < o.results[best].cost.penalised()) best = i;  // within the limits first
  int verified = -1;
  if (study.all && !study.coarse) {
    o.rechecks = recheck(study, o.entries, options.rechecks, ex);
    if (!o.rechecks.empty() && o.rechecks.front().failure.empty())  // the time domain has the last word
      verified = static_cast<int>(std::find(o.order.begin(), o.order.end(), o.rechecks.front().entry) - o.order.begin());
  }
  if (verified >= 0) best = static_cast<std::size_t>(verified);
  o.best = best_of(o.results[best], best);
  o.best.verified = verified >= 0;
  o.stock_best = o.results[best].stock;
  events.searches_done(o);
  if (!study.admittance_degrees.empty()) {
    std::vector<BoundCandidate> cands{
        {"default " + network::to_string(o.baseline, true), o.baseline, o.default_cost.J, o.default_cost.J}};
    for (const auto& r : o.results) try {  // a layout without a design (values missing) is skipped
        const network::Network net = design_network(r.layout, r.values);
        cands.push_back({r.layout + " " + network::to_string(net, true), net, r.cost.J, r.cost.J});
      } catch (const network::NetworkError&) {
      }
    o.admittance = admittance_bounds(
        study.admittance_degrees, cands, [&](int d, const network::Network& w) { return admittance_bound(study, d, w); },
        [&](const AdmittanceBound& b) { events.bound(b); });
  }
  // The best design verified by the time domain (the reference): a periodic study's in the report's
  // post-processing (its σ(v) with the centripetal correction on) or by itself.
  if (options.report) {
    ReportOptions ro = options.report_options;
    ro.best = static_cast<int>(best);
    o.report = make_report(study, o.results, ro, [&](int step, int steps, const std::string& what, int done, int total) {
      events.report(step, steps, what, done, total);
    });
    o.time_check = o.report->time_check;
  } else if (study.method == Study::Method::Time) {
    o.time_check = o.results[best].cost;
  } else if (verified >= 0) {
    o.time_check = o.rechecks.front().time;
  } else {
    const CheckResult c = ex.check(study, {CheckTask{o.best.layout, o.best.values, true}}).at(0);
    if (!c.failure.empty()) throw NumericalError(c.failure);
    o.time_check = c.cost;
  }
  if (study.method == Study::Method::Periodic) o.best.J = o.time_check.J;
  return o;
}

StudyOutcome run_study(const ModelStudy& study, const StudyOptions& options, StudyEvents* events_in) {
  NoEvents none;
  StudyEvents& events = events_in ? *events_in : none;
  ModelStudyProgress p;
  p.searching = [&](std::size_t l, int start, int evals, double best) { events.searching(l, start, evals, best); };
  p.finished = [&](std::size_t l, const ModelLayoutResult& r) { events.searched(l, r); };
  p.structure = [&](const StructureProgress& s) { events.network(s); };
  StudyOutcome o;
  p.searched = [&](const ModelStudyResult& r) {
    o.model = r;
    events.searches_done(o);
  };
  p.bound = [&](const AdmittanceBound& b) { events.bound(b); };
  o.model = run_model_study(study, p);
  const ModelStudyResult& r = *o.model;
  o.baseline = r.baseline;
  o.seconds = r.seconds;
  if (!r.results.empty()) {
    const ModelLayoutResult& b = r.results[r.best];
    o.best.index = r.best;
    o.best.layout = b.layout, o.best.expression = b.expression, o.best.values = b.values;
    o.best.net = network::resolve(b.layout, b.values);
    o.best.J = b.cost.J, o.best.feasible = b.cost.feasible;
  }
  if (options.report) o.model_figures = model_study_figures(r);
  return o;
}

}  // namespace inerta::optim
