// The study engine's units of work and where they run here (optim/study_run.hpp): checks, the
// LocalExecutor, the best-design rule. The searches are run_search (structure_search.cpp).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "inerta/error.hpp"
#include "inerta/optim/study_run.hpp"

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
// LocalExecutor's searches, either kind: the networks of one size in parallel (as optimise_all), named
// layouts one after another (each search's polls in parallel).
template <class S, class Result>
std::vector<Result> search_here(const S& study, const std::vector<SearchTask>& tasks,
                                const StudyExecutor::Done<Result>& done, const StudyExecutor::Searching& searching) {
  std::vector<Result> out(tasks.size());
  if (std::any_of(tasks.begin(), tasks.end(), [](const SearchTask& t) { return t.network; })) {
    std::mutex mutex;
    tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t i) {
      out[i] = run_search(study, tasks[i]);
      std::lock_guard<std::mutex> lock(mutex);
      if (done) done(i, out[i]);
    });
    return out;
  }
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    numerics::Progress p;
    if (searching) p = [&](int start, int evals, double best) { searching(i, start, evals, best); };
    out[i] = run_search(study, tasks[i], p);
    if (done) done(i, out[i]);
  }
  return out;
}

template <class S>
auto check_here(const S& study, const std::vector<CheckTask>& tasks) {
  std::vector<decltype(run_check(study, CheckTask{}))> out;
  for (const auto& t : tasks) out.push_back(run_check(study, t));
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
  return check_here(study, tasks);
}
std::vector<ModelCheckResult> LocalExecutor::check(const ModelStudy& study, const std::vector<CheckTask>& tasks) {
  return check_here(study, tasks);
}

}  // namespace inerta::optim
