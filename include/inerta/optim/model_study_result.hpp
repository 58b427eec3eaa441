#pragma once
// A whole model study's result (docs/studies.md), what the study engine (optim::run_study,
// optim/study_run.hpp) returns for a model study as StudyOutcome::model, and the data of its report
// figures. The files are written by io::write_model_study_results.
#include <cstddef>
#include <optional>
#include <vector>

#include "inerta/optim/admittance_search.hpp"
#include "inerta/optim/model_study.hpp"
#include "inerta/optim/structure_search.hpp"

namespace inerta::optim {

struct ModelStudyResult {
  ModelStudy study;
  network::Network baseline;  ///< the strut's own network
  ModelCost baseline_cost;
  /// Named layouts: in the study's order. `layouts: all`: every network, ranked, best first.
  std::vector<ModelLayoutResult> results;
  std::vector<StructureEntry> entries;  ///< `layouts: all` only: the structure search's entries
  std::size_t best = 0;                 ///< index in results: the best design (optim::best_design)
  /// `admittance: [d, …]`: the positive-real bounds, started from the default and the results.
  std::vector<AdmittanceBound> admittance;
  double seconds = 0;                   ///< wall time of the default's evaluation and the searches (not the bounds)
};

/// The report's figures: |H| of the default and the best design over the objective's band (0.1–50 Hz,
/// 400 points, if it has none; none for a peak objective), and the objective over the best layout's
/// first two finite, non-zero elements (none if it has fewer).
struct ModelStudyFigures {
  std::optional<StudyFrf> frf_default, frf_best;
  std::optional<ObjectiveMap> map;
};
ModelStudyFigures model_study_figures(const ModelStudyResult& result);

}  // namespace inerta::optim
