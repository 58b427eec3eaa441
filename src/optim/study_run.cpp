#include "inerta/optim/study_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <type_traits>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"

namespace inerta::optim {

std::string StudyOutcome::recheck_csv() const {
  // stopped: the time-domain run stopped behind the best (early stops): J2_time is a lower bound.
  std::string csv = "network,reduced,J2_periodic,J2_time,v_kmh_time,periodic_rank,settling_spans,stopped\n";
  for (const Recheck& c : rechecks) {
    if (!c.failure.empty()) continue;
    const auto& e = entries[c.entry];
    csv += fmt::format("\"{}\",\"{}\",{:.10g},{:.10g},{:.6g},{},{:.6g},{}\n", e.expression, e.reduced, e.J, c.time.J,
                       c.time.speed * 3.6, c.periodic_rank, c.settling_spans, c.stopped ? 1 : 0);
  }
  return csv;
}

std::string StudyOutcome::screened_csv() const {
  // stopped: the evaluation stopped once it could not be among the refined (early stops): J is a lower bound.
  std::string csv = "screen_rank,network,reduced,coarse_rank,J_coarse,J,feasible,violation,refined,failure,stopped\n";
  for (std::size_t k = 0; k < screened.size(); ++k) {
    const Screened& c = screened[k];
    const StructureEntry& e = entries[c.entry];
    csv += fmt::format("{},\"{}\",\"{}\",{},{:.10g},{:.10g},{},\"{}\",{},\"{}\",{}\n", k + 1, e.expression, e.reduced,
                       c.coarse_rank, e.J, c.cost.J, c.cost.feasible ? 1 : 0, c.cost.violation, c.refined ? 1 : 0, c.failure,
                       c.stopped ? 1 : 0);
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

// Checks with exact early stops (issue 50): the first `lead` tasks in full; if each is feasible, the worst of
// them is the incumbent the others must beat (CheckTask::stop: its J, its worst run first), else the others
// run in full too.
// Whichever `lead` designs rank first among all, the stopped ones rank behind every one of the lead.
std::vector<CheckResult> checks_behind(const Study& study, const std::vector<CheckTask>& tasks, std::size_t lead,
                                       StudyExecutor& ex) {
  if (lead == 0 || lead >= tasks.size()) return ex.check(study, tasks);
  std::vector<CheckResult> out = ex.check(study, std::vector<CheckTask>(tasks.begin(), tasks.begin() + static_cast<std::ptrdiff_t>(lead)));
  EarlyStop stop = EarlyStop::behind(out.front().cost);  // the lead's worst: its J and worst run
  for (const CheckResult& c : out) {
    const EarlyStop e = EarlyStop::behind(c.cost);
    if (!c.failure.empty() || !std::isfinite(e.above)) {
      stop = EarlyStop{};  // an incumbent outside the limits or failed: no stops
      break;
    }
    if (e.above > stop.above) stop = e;
  }
  std::vector<CheckTask> rest(tasks.begin() + static_cast<std::ptrdiff_t>(lead), tasks.end());
  for (CheckTask& t : rest) t.stop = stop;
  for (CheckResult& c : ex.check(study, rest)) out.push_back(std::move(c));
  return out;
}

// The best few distinct feasible designs of the fast path, re-checked in the time domain (the reference),
// ranked by their time-domain cost, within the limits first (issue 24: the fast path can be off by a few per cent).
// Early stops: the fast path's best first, in full (the incumbent); the others stop once they rank behind it.
std::vector<Recheck> recheck(const Study& study, const std::vector<StructureEntry>& entries, int count, bool early_stops,
                             StudyExecutor& ex) {
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
  const std::vector<CheckResult> checked = checks_behind(study, tasks, early_stops ? 1 : tasks.size(), ex);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].time = checked[k].cost, out[k].failure = checked[k].failure, out[k].stopped = checked[k].stopped;
    if (!out[k].failure.empty()) continue;
    // The slowest free vibration (Floquet multiplier of the periodic path): a time-domain run shorter
    // than its decay measures the transient's beating, not the steady state (issue 24 item 4).
    const auto& e = entries[out[k].entry];
    try {
      out[k].settling_spans = evaluate(study, network::resolve(e.expression, e.values)).settling_spans();
    } catch (const NumericalError&) {
    }
  }
  // By the time domain's penalised cost (within the limits first), the stopped behind the others.
  std::stable_sort(out.begin(), out.end(), [](const Recheck& x, const Recheck& y) {
    return x.stopped != y.stopped ? y.stopped : x.time.penalised() < y.time.penalised();
  });
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

// A network's element values by name.
network::Params element_values(const network::Network& net) {
  network::Params p;
  std::function<void(const network::Network&)> leaves = [&](const network::Network& n) {
    if (n.is_element()) p[n.name] = n.value;
    for (const auto& c : n.children) leaves(c);
  };
  leaves(net);
  return p;
}

// The stock suspension as a study result: its expression and element values, its cost.
LayoutResult stock_result(const network::Network& baseline, const StudyCost& cost) {
  LayoutResult r;
  r.layout = r.expression = network::to_string(baseline, false);
  r.values = element_values(baseline);
  r.cost = cost;
  r.evaluations = 1;
  r.stock = true;
  return r;
}

// Multi-fidelity `layouts: all`: the study's refine_networks best distinct reduced networks of the coarse
// search (feasible first, by the coarse ranking), each refined here from its coarse optimum; ranked by the
// cost here (penalised: within the limits first), ties by the coarse rank. Sets o.refinements.
std::vector<LayoutResult> refine_networks(const Study& study, StudyOutcome& o, bool early_stops, StudyExecutor& ex,
                                          StudyEvents& events) {
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
    // Early stops: the first best_networks in full; a later candidate stops once it cannot be among the refined.
    const auto m = static_cast<std::size_t>(study.refine_networks);
    const std::vector<CheckResult> got = checks_behind(study, checks, early_stops ? m : checks.size(), ex);
    std::stable_sort(pick.begin(), pick.end(), [&](std::size_t a, std::size_t b) {
      return got[a].stopped != got[b].stopped ? got[b].stopped : got[a].cost.penalised() < got[b].cost.penalised();
    });
    for (std::size_t r = 0; r < pick.size(); ++r) {
      const std::size_t k = pick[r];
      screen_rank[k] = static_cast<int>(r) + 1;
      Screened sc;
      sc.entry = cands[k].entry, sc.coarse_rank = static_cast<int>(k) + 1, sc.cost = got[k].cost, sc.failure = got[k].failure;
      sc.stopped = got[k].stopped;
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

template <class Result>
BestDesign best_of(const Result& r, std::size_t index) {
  BestDesign b;
  b.index = index;
  b.layout = r.layout, b.expression = r.expression, b.values = r.values;
  b.net = design_network(r.layout, r.values);  // a named layout's fixed values stay the layout's (S2-default's c)
  b.J = r.cost.J, b.feasible = r.cost.feasible;
  return b;
}

// The parts of the outcome that differ by kind of study: a J2 study's are StudyOutcome's own, a model
// study's are in its ModelStudyResult.
std::vector<LayoutResult>& results_of(StudyOutcome& o, const Study&) { return o.results; }
std::vector<ModelLayoutResult>& results_of(StudyOutcome& o, const ModelStudy&) { return o.model->results; }
StudyCost& default_cost_of(StudyOutcome& o, const Study&) { return o.default_cost; }
ModelCost& default_cost_of(StudyOutcome& o, const ModelStudy&) { return o.model->baseline_cost; }
std::vector<StructureEntry>& entries_of(StudyOutcome& o, const Study&) { return o.entries; }
std::vector<StructureEntry>& entries_of(StudyOutcome& o, const ModelStudy&) { return o.model->entries; }
std::vector<AdmittanceBound>& bounds_of(StudyOutcome& o, const Study&) { return o.admittance; }
std::vector<AdmittanceBound>& bounds_of(StudyOutcome& o, const ModelStudy&) { return o.model->admittance; }
double penalised(const StudyCost& c) { return c.penalised(); }
double penalised(const ModelCost& c) { return c.penalised; }
// What an admittance bound's candidate costs: a J2 study's J, a model study's penalised cost.
double bound_cost(const StudyCost& c) { return c.J; }
double bound_cost(const ModelCost& c) { return c.penalised; }

// The engine, for either kind of study; what only a J2 study has (a coarse study, re-checks, the report's
// time check) under `if constexpr`.
template <class S>
StudyOutcome run_engine(const S& study, const StudyOptions& options, StudyEvents& events, StudyExecutor& ex) {
  constexpr bool j2 = std::is_same_v<S, Study>;
  using Result = std::conditional_t<j2, LayoutResult, ModelLayoutResult>;
  StudyOutcome o;
  if constexpr (j2) {
    o.study = study;
    o.baseline = default_suspension(study);
  } else {
    o.model.emplace();
    o.model->study = study;
    o.baseline = o.model->baseline = default_network(study);
  }
  std::vector<Result>& results = results_of(o, study);
  auto& default_cost = default_cost_of(o, study);
  std::vector<StructureEntry>& entries = entries_of(o, study);
  const auto t0 = std::chrono::steady_clock::now();
  {
    const auto def = ex.check(study, {CheckTask{}}).at(0);
    if (!def.failure.empty()) throw NumericalError(def.failure);
    default_cost = def.cost;
  }
  bool coarse = false;  // multi-fidelity `layouts: all` (J2)
  if constexpr (j2) {
    if (o.default_cost.unstable_speed > 0)
      throw NumericalError(fmt::format("{}: the default suspension's periodic solution is unstable at {:.4g} km/h "
                                       "(Floquet multiplier ≥ 1): the study has no baseline",
                                       study.source, o.default_cost.unstable_speed * 3.6));
    coarse = study.all && study.coarse;
    if (coarse) try {  // the entries' baseline: the default on the coarse study
        o.coarse_default_cost = evaluate(*study.coarse, o.baseline);
      } catch (const NumericalError&) {
        o.coarse_default_cost.J = NAN;
      }
  }
  if (study.all) {
    std::vector<Result> all(study.layouts.size());
    entries = structure_search_batched(
        study.layouts,
        [&](const std::vector<StructureTask>& tasks, const std::function<void(std::size_t, const StructureOutcome&)>& done) {
          std::vector<SearchTask> st;
          for (const auto& t : tasks) st.push_back({t.expression, t.warm, true, coarse});
          ex.search(study, st, [&](std::size_t k, const Result& r) {
            all[tasks[k].index] = r;
            done(k, structure_outcome(r));
          }, {});
        },
        [&](const StructureProgress& p) { events.network(p); });
    o.order = ranking(entries);
    if constexpr (j2)
      if (coarse) results = refine_networks(study, o, options.early_stops, ex, events);  // the best distinct reduced networks refined here
    if (!coarse)
      for (std::size_t i : o.order) results.push_back(all[i]);  // ranked: results.csv best first
  } else if constexpr (j2) {  // independent searches
    std::vector<SearchTask> tasks;
    for (const auto& l : study.layouts) tasks.push_back({l, {}, false});
    results = ex.search(
        study, tasks, [&](std::size_t i, const Result& r) { events.searched(i, r); },
        [&](std::size_t i, int start, int evals, double best) { events.searching(i, start, evals, best); });
  } else {  // in turn: each warm-started from the default's values and every earlier optimum
    std::vector<network::Params> warm{element_values(o.baseline)};
    for (std::size_t l = 0; l < study.layouts.size(); ++l) {
      results.push_back(ex.search(
                             study, {SearchTask{study.layouts[l], warm}},
                             [&](std::size_t, const Result& r) { events.searched(l, r); },
                             [&](std::size_t, int start, int evals, double best) { events.searching(l, start, evals, best); })
                            .at(0));
      warm.push_back(results.back().values);
    }
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (results.empty()) throw InvalidArgument(study.source + ": the study has no layouts");
  std::vector<double> costs;
  for (const Result& r : results) costs.push_back(penalised(r.cost));
  std::size_t best = best_design(costs);
  int verified = -1;
  if constexpr (j2) {
    if (study.all && !study.coarse) {
      o.rechecks = recheck(study, o.entries, options.rechecks, options.early_stops, ex);
      if (!o.rechecks.empty() && o.rechecks.front().failure.empty())  // the time domain has the last word
        verified = static_cast<int>(std::find(o.order.begin(), o.order.end(), o.rechecks.front().entry) - o.order.begin());
    }
  }
  if (verified >= 0) best = static_cast<std::size_t>(verified);
  o.best = best_of(results[best], best);
  o.best.verified = verified >= 0;
  if constexpr (j2)
    o.stock_best = results[best].stock;
  else
    o.model->best = best, o.model->seconds = o.seconds;
  events.searches_done(o);
  if (!study.admittance_degrees.empty()) {
    std::vector<BoundCandidate> cands{
        {"default " + network::to_string(o.baseline, true), o.baseline, bound_cost(default_cost), default_cost.J}};
    for (const Result& r : results) try {  // a layout without a design (values missing) is skipped
        const network::Network net = design_network(r.layout, r.values);
        cands.push_back({r.layout + " " + network::to_string(net, true), net, bound_cost(r.cost), r.cost.J});
      } catch (const network::NetworkError&) {
      }
    bounds_of(o, study) = admittance_bounds(
        study.admittance_degrees, cands, [&](int d, const network::Network& w) { return admittance_bound(study, d, w); },
        [&](const AdmittanceBound& b) { events.bound(b); });
  }
  if constexpr (j2) {
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
  } else if (options.report) {
    o.model_figures = model_study_figures(*o.model);
  }
  return o;
}

}  // namespace

StudyOutcome run_study(const Study& study, const StudyOptions& options, StudyEvents* events, StudyExecutor* executor) {
  NoEvents none;
  LocalExecutor local;
  return run_engine(study, options, events ? *events : none, executor ? *executor : local);
}

StudyOutcome run_study(const ModelStudy& study, const StudyOptions& options, StudyEvents* events, StudyExecutor* executor) {
  NoEvents none;
  LocalExecutor local;
  return run_engine(study, options, events ? *events : none, executor ? *executor : local);
}

}  // namespace inerta::optim
