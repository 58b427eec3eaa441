#pragma once
// A whole model study as `inerta optimise` runs it (docs/studies.md): the default network, then each
// layout warm-started from the default and the earlier optima (or, for `layouts: all`, the structure
// search), the admittance bounds it asks for, and the data of its report figures. The files are written by io::write_model_study_results.
#include <cstddef>
#include <functional>
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
  std::size_t best = 0;                 ///< index in results: feasible first, then the smallest J
  /// `admittance: [d, …]`: the positive-real bounds, started from the default and the results.
  std::vector<AdmittanceBound> admittance;
  double seconds = 0;                   ///< wall time of the default's evaluation and the searches (not the bounds)
};

struct ModelStudyProgress {
  /// During layout `index`'s search (named layouts): start, evaluations so far, best J so far.
  std::function<void(std::size_t index, int start, int evaluations, double best)> searching;
  /// After layout `index` (named layouts).
  std::function<void(std::size_t index, const ModelLayoutResult&)> finished;
  StructureProgressFn structure;  ///< `layouts: all`: after each network
  /// After the searches (the result without its admittance bounds), before the bounds.
  std::function<void(const ModelStudyResult&)> searched;
  std::function<void(const AdmittanceBound&)> bound;  ///< after each admittance bound
};

ModelStudyResult run_model_study(const ModelStudy& study, const ModelStudyProgress& progress = {});

/// The report's figures: |H| of the default and the best design over the objective's band (0.1–50 Hz,
/// 400 points, if it has none; none for a peak objective), and the objective over the best layout's
/// first two finite, non-zero elements (none if it has fewer).
struct ModelStudyFigures {
  std::optional<StudyFrf> frf_default, frf_best;
  std::optional<ObjectiveMap> map;
};
ModelStudyFigures model_study_figures(const ModelStudyResult& result);

}  // namespace inerta::optim
