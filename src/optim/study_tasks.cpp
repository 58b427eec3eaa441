// The study engine's units of work and where they run here (optim/study_run.hpp): checks, the
// LocalExecutor, the best-design rule. The searches are run_search (structure_search.cpp).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>
#include <type_traits>

#include "inerta/error.hpp"
#include "inerta/optim/lane_batcher.hpp"
#include "inerta/optim/study_run.hpp"

namespace inerta::optim {

CheckResult run_check(const Study& study, const CheckTask& task) {
  const network::Network net = task.layout.empty() ? default_suspension(study) : design_network(task.layout, task.values);
  CheckResult r;
  try {
    if ((task.time || study.method == Study::Method::Time) && std::isfinite(task.stop.above)) {
      const BatchEvaluation b = evaluate_time_batch(study, {net}, {task.stop}).at(0);
      r.cost = b.get(), r.stopped = b.stopped;
    } else {
      r.cost = task.time ? evaluate_time(study, net) : evaluate(study, net);
    }
  } catch (const NumericalError& e) {
    r.failure = e.what();
    r.cost.J = INFINITY;
  }
  return r;
}

std::vector<CheckResult> run_checks(const Study& study, const std::vector<CheckTask>& tasks) {
  // The designs by kind of evaluation: the time domain (lanes) and the study's own periodic path.
  std::vector<network::Network> time, own;
  std::vector<std::size_t> time_at, own_at;
  std::vector<EarlyStop> stops;
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    const CheckTask& t = tasks[k];
    network::Network net = t.layout.empty() ? default_suspension(study) : design_network(t.layout, t.values);
    if (t.time || study.method == Study::Method::Time)
      time.push_back(std::move(net)), time_at.push_back(k), stops.push_back(t.stop);
    else
      own.push_back(std::move(net)), own_at.push_back(k);
  }
  std::vector<BatchEvaluation> got(tasks.size());
  const std::vector<BatchEvaluation> a = evaluate_time_batch(study, time, stops), b = evaluate_batch(study, own);
  for (std::size_t j = 0; j < a.size(); ++j) got[time_at[j]] = a[j];
  for (std::size_t j = 0; j < b.size(); ++j) got[own_at[j]] = b[j];
  std::vector<CheckResult> out(tasks.size());
  for (std::size_t k = 0; k < tasks.size(); ++k) try {  // as run_check; another exception: the first task's
      out[k].cost = got[k].get(), out[k].stopped = got[k].stopped;
    } catch (const NumericalError& e) {
      out[k].failure = e.what();
      out[k].cost.J = INFINITY;
    }
  return out;
}

ModelCheckResult run_check(const ModelStudy& study, const CheckTask& task) {
  if (task.time) throw InvalidArgument(study.source + ": a model study has no time-domain check");
  const network::Network net = task.layout.empty() ? default_network(study) : design_network(task.layout, task.values);
  ModelCheckResult r;
  try {
    r.cost = evaluate(study, net);
  } catch (const NumericalError& e) {
    r.failure = e.what();
    r.cost.J = INFINITY;
  }
  return r;
}

std::size_t best_design(const std::vector<double>& penalised) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < penalised.size(); ++i)
    if (penalised[i] < penalised[best]) best = i;
  return best;
}

namespace {
// A search here: a time-domain study's polls through design_costs (the designs in lanes); a model study's
// and a periodic study's as optimise_layout evaluates them (in threads).
LayoutResult search_task(const Study& study, const SearchTask& task, const numerics::Progress& progress) {
  DesignBatch lanes;
  if (study.method == Study::Method::Time)
    lanes = [&](const std::vector<network::Params>& params) { return design_costs(study, task.layout, params); };
  return run_search(study, task, progress, lanes);
}
ModelLayoutResult search_task(const ModelStudy& study, const SearchTask& task, const numerics::Progress& progress) {
  return run_search(study, task, progress);
}

// A time-domain study's refinements (multi-fidelity `layouts: all`) run side by side: each on a thread of
// its own, their searches' evaluations gathered by a LaneBatcher into one batch whenever every
// refinement still running waits (issue 50: the designs stepped together as lanes, each design's cost
// its lone evaluation's, so each refinement's path is the one it takes alone).
bool side_by_side(const Study& study, const std::vector<SearchTask>& tasks) {
  return study.method == Study::Method::Time && tasks.size() > 1 &&
         std::all_of(tasks.begin(), tasks.end(), [](const SearchTask& t) { return t.refine && !t.network && !t.coarse; });
}
std::vector<LayoutResult> refine_side_by_side(const Study& study, const std::vector<SearchTask>& tasks,
                                              const StudyExecutor::Done<LayoutResult>& done,
                                              const StudyExecutor::Searching& searching) {
  std::vector<LayoutResult> out(tasks.size());
  LaneBatcher batcher(static_cast<int>(tasks.size()),
                      [&](const std::vector<network::Network>& nets) { return evaluate_batch(study, nets); });
  std::mutex mutex;  // the callers' callbacks, one at a time
  std::vector<std::exception_ptr> errors(tasks.size());
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < tasks.size(); ++i)
    threads.emplace_back([&, i] {
      try {
        numerics::Progress p;
        if (searching)
          p = [&](int start, int evals, double best) {
            std::lock_guard<std::mutex> lock(mutex);
            searching(i, start, evals, best);
          };
        const DesignBatch lanes = [&](const std::vector<network::Params>& params) {
          return design_costs(study, tasks[i].layout, params,
                              [&](const std::vector<network::Network>& nets) { return batcher.ask(nets); });
        };
        out[i] = run_search(study, tasks[i], p, lanes);
        std::lock_guard<std::mutex> lock(mutex);
        if (done) done(i, out[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
      batcher.done();
    });
  for (std::thread& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

// LocalExecutor's searches, either kind: the networks of one size in parallel (as optimise_all), named
// layouts one after another (each search's polls in parallel, or in lanes).
template <class S, class Result>
std::vector<Result> search_here(const S& study, const std::vector<SearchTask>& tasks,
                                const StudyExecutor::Done<Result>& done, const StudyExecutor::Searching& searching) {
  std::vector<Result> out(tasks.size());
  if (std::any_of(tasks.begin(), tasks.end(), [](const SearchTask& t) { return t.network; })) {
    std::mutex mutex;
    tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t i) {
      out[i] = search_task(study, tasks[i], {});
      std::lock_guard<std::mutex> lock(mutex);
      if (done) done(i, out[i]);
    });
    return out;
  }
  if constexpr (std::is_same_v<S, Study>)
    if (side_by_side(study, tasks)) return refine_side_by_side(study, tasks, done, searching);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    numerics::Progress p;
    if (searching) p = [&](int start, int evals, double best) { searching(i, start, evals, best); };
    out[i] = search_task(study, tasks[i], p);
    if (done) done(i, out[i]);
  }
  return out;
}
}  // namespace

std::vector<LayoutResult> LocalExecutor::search(const Study& study, const std::vector<SearchTask>& tasks,
                                                const Done<LayoutResult>& done, const Searching& searching) {
  return search_here(study, tasks, done, searching);
}
std::vector<ModelLayoutResult> LocalExecutor::search(const ModelStudy& study, const std::vector<SearchTask>& tasks,
                                                     const Done<ModelLayoutResult>& done, const Searching& searching) {
  return search_here(study, tasks, done, searching);
}
std::vector<CheckResult> LocalExecutor::check(const Study& study, const std::vector<CheckTask>& tasks) {
  return run_checks(study, tasks);
}
std::vector<ModelCheckResult> LocalExecutor::check(const ModelStudy& study, const std::vector<CheckTask>& tasks) {
  std::vector<ModelCheckResult> out;
  for (const auto& t : tasks) out.push_back(run_check(study, t));
  return out;
}

}  // namespace inerta::optim
