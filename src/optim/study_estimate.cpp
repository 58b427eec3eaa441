// The estimated wall time of a whole study, every stage (optim/study.hpp, issue 52).
#include <algorithm>
#include <chrono>

#include "inerta/optim/study.hpp"

namespace inerta::optim {

namespace {

// Evaluations of one search of a network with `free` values from one start. The periodic path: about
// 60 per free value (the bundled real-line study's coarse search: 31, 154, 141 and 223 on average for
// 1–4 elements; 60 · n gives 60, 120, 180, 240), at most the search's limit. The time domain: its limit
// (a bound, as the refinements' budget).
long search_evaluations(std::size_t free, const Study& study) {
  const long limit = study.search.max_evaluations;
  if (study.method == Study::Method::Time) return limit;
  return std::min<long>(60L * static_cast<long>(std::max<std::size_t>(free, 1)), limit);
}

// One evaluation of `study`, s: the time domain's estimate, or the periodic path timed on the stock
// suspension (the second of two runs; its cost hardly depends on the network's size: 17–21 ms for 1
// and 4 elements on the real-line study's coarse line).
double evaluation_seconds(const Study& study) {
  if (study.method == Study::Method::Time) return estimated_evaluation_seconds(study);
  double best = 0.02;  // s, if the stock suspension cannot be evaluated here (the measured order)
  try {
    const network::Network net = default_suspension(study);
    for (int i = 0; i < 2; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      (void)evaluate(study, net);
      best = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
  } catch (const std::exception&) {
  }
  return best;
}

}  // namespace

StudyEstimate estimated_study_seconds(const Study& study) {
  StudyEstimate e;
  const Study& searched = study.coarse ? *study.coarse : study;
  for (const std::string& layout : study.layouts)
    e.search_evaluations += search_evaluations(free_parameters(layout).size(), searched) * std::max(1, searched.search.starts);
  e.search_seconds = evaluation_seconds(searched) * static_cast<double>(e.search_evaluations);
  if (study.coarse) {
    const long refined = static_cast<long>(study.all ? std::min<std::size_t>(static_cast<std::size_t>(study.refine_networks), study.layouts.size())
                                                     : study.layouts.size());
    e.refine_evaluations = static_cast<long>(study.refine.max_evaluations) * study.refine_candidates * refined;
    if (study.all && study.refine_screen > study.refine_networks)  // the screen: one evaluation a network
      e.refine_evaluations += std::min<long>(study.refine_screen, static_cast<long>(study.layouts.size()));
    e.refine_seconds = evaluation_seconds(study) * static_cast<double>(e.refine_evaluations);
  }
  return e;
}

}  // namespace inerta::optim
