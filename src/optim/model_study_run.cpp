#include "inerta/optim/model_study_run.hpp"

#include <chrono>
#include <cmath>

namespace inerta::optim {

namespace {
network::Params element_values(const network::Network& n) {
  network::Params p;
  std::function<void(const network::Network&)> collect = [&](const network::Network& x) {
    if (x.is_element()) p[x.name] = x.value;
    for (const auto& c : x.children) collect(c);
  };
  collect(n);
  return p;
}
}  // namespace

ModelStudyResult run_model_study(const ModelStudy& study, const ModelStudyProgress& progress) {
  ModelStudyResult r;
  r.study = study;
  r.baseline = default_network(study);
  const auto t0 = std::chrono::steady_clock::now();
  r.baseline_cost = evaluate(study, r.baseline);
  if (study.all) {
    std::vector<ModelLayoutResult> all;
    r.entries = optimise_all(study, all, progress.structure);
    for (std::size_t i : ranking(r.entries)) r.results.push_back(all[i]);
  } else {
    // Warm starts: the default's values and every earlier layout's optimum (optimise_layout).
    std::vector<network::Params> warm{element_values(r.baseline)};
    for (std::size_t l = 0; l < study.layouts.size(); ++l) {
      numerics::Progress p;
      if (progress.searching) p = [&](int start, int evals, double best) { progress.searching(l, start, evals, best); };
      r.results.push_back(optimise_layout(study, study.layouts[l], p, warm));
      warm.push_back(r.results.back().values);
      if (progress.finished) progress.finished(l, r.results.back());
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < r.results.size(); ++i) {
    const auto& c = r.results[i].cost;
    const auto& b = r.results[r.best].cost;
    if ((c.feasible && !b.feasible) || (c.feasible == b.feasible && c.J < b.J)) r.best = i;
  }
  if (progress.searched) progress.searched(r);
  if (!study.admittance_degrees.empty()) {
    std::vector<BoundCandidate> cands{
        {"default " + network::to_string(r.baseline, true), r.baseline, r.baseline_cost.penalised, r.baseline_cost.J}};
    for (const auto& x : r.results) try {  // a layout without a design is skipped
        const network::Network net = network::resolve(x.layout, x.values);
        cands.push_back({x.layout + " " + network::to_string(net, true), net, x.cost.penalised, x.cost.J});
      } catch (const network::NetworkError&) {
      }
    r.admittance = admittance_bounds(
        study.admittance_degrees, cands, [&](int d, const network::Network& w) { return admittance_bound(study, d, w); },
        progress.bound);
  }
  return r;
}

ModelStudyFigures model_study_figures(const ModelStudyResult& r) {
  ModelStudyFigures fig;
  if (r.results.empty()) return fig;
  const ModelStudy& study = r.study;
  const ModelLayoutResult& best = r.results[r.best];
  if (study.objective.kind != Objective::Kind::Peak) {
    std::vector<double> f = study.objective.frequencies;
    if (f.empty())
      for (int k = 0; k < 400; ++k) f.push_back(0.1 * std::pow(500.0, k / 399.0));  // 0.1 … 50 Hz
    fig.frf_default = study_frf(study, r.baseline, f);
    fig.frf_best = study_frf(study, network::resolve(best.layout, best.values), f);
  }
  std::vector<std::string> finite;
  for (const auto& [k, v] : best.values)
    if (v > 0 && std::isfinite(v)) finite.push_back(k);
  if (finite.size() >= 2) fig.map = objective_map(study, best.layout, best.values, finite[0], finite[1]);
  return fig;
}

}  // namespace inerta::optim
