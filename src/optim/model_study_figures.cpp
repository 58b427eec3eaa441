// The data of a model study's report figures (optim/model_study_result.hpp).
#include "inerta/optim/model_study_result.hpp"

#include <cmath>

#include "inerta/optim/study.hpp"

namespace inerta::optim {

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
    fig.frf_best = study_frf(study, design_network(best.layout, best.values), f);
  }
  std::vector<std::string> finite;
  for (const auto& [k, v] : best.values)
    if (v > 0 && std::isfinite(v)) finite.push_back(k);
  if (finite.size() >= 2) fig.map = objective_map(study, best.layout, best.values, finite[0], finite[1]);
  return fig;
}

}  // namespace inerta::optim
