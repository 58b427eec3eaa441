#pragma once
// Design studies on any model (docs/studies.md): the network of one strut is replaced by candidate
// layouts whose element values are optimised (the pattern search of spec/07) against an objective
// of the linearised or simulated model:
//   rms   J = sqrt(Σ (w_i σ_i)²) of outputs under white noise or an ISO 8608 road (Lyapunov),
//         with limits on the rms of other outputs;
//   hinf  J = max_i max_f w_i |H_i(j 2π f)| from one input over a band of frequencies;
//   peak  J = max_i w_i max_t |y_i(t) − y_i(0)| of a time simulation (the model's own inputs).
// The pantograph's J2 under catenaries stays the study of optim/study.hpp.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "inerta/analysis/state_space.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/network.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::optim {

struct WeightedOutput {
  std::string name;
  double weight = 1;
};

struct RmsLimit {
  std::string output;
  double limit = 0;  ///< largest admissible rms, the output's unit
};

struct Objective {
  enum class Kind { Rms, Hinf, Peak };
  Kind kind = Kind::Rms;
  std::vector<WeightedOutput> outputs;
  // rms: white noise of intensity W_ii (E[u u] = W δ) on these inputs, or a road.
  std::vector<std::string> noise_inputs;
  std::vector<double> noise_intensity;
  std::optional<analysis::Road> road;
  std::vector<RmsLimit> limits;
  // hinf
  std::string input;
  std::vector<double> frequencies;  ///< Hz
  // peak
  double t_end = 5;      ///< s
  double sample = 1e-3;  ///< s
  static const char* name(Kind k);
};

struct ModelStudy {
  std::string name, source;
  mbs::Model model;
  int strut = -1;  ///< the force element whose network is replaced
  Objective objective;
  std::vector<std::string> layouts;
  /// `layouts: all`: the layouts are every network these options allow (network::enumerate), searched
  /// by optim::optimise_all.
  std::optional<network::EnumerationOptions> all;
  /// `admittance: [2, 3]`: also optimise a positive-real admittance of each degree (the bound of
  /// optim/admittance_search.hpp).
  std::vector<int> admittance_degrees;
  numerics::Options search;
  double lo = 0.1, hi = 1e9;  ///< bounds of every free value (SI), 0 and ∞ reachable
};

/// The model with strut `strut`'s network replaced by `bound` (simplified; an open network removes
/// the element). ModelError if the network is rigid or the element is not a network strut.
mbs::Model with_strut_network(const mbs::Model& model, int strut, const network::Network& bound);

/// The strut's own network (the study's baseline).
network::Network default_network(const ModelStudy& study);

struct ModelCost {
  double J = std::numeric_limits<double>::infinity();  ///< the objective
  /// What the search minimises: J if every limit holds, else 1e100 (1 + Σ max(0, σ_k/limit_k − 1)):
  /// limits are hard, a design that exceeds one ranks after every design that keeps them, and
  /// among those the smaller excess ranks first.
  double penalised = std::numeric_limits<double>::infinity();
  std::vector<double> values;  ///< per objective output: its rms, peak |H| or peak |y|
  std::vector<double> limit_values;  ///< per limit: the rms of its output
  double frequency = 0;              ///< hinf: the frequency of the peak, Hz
  bool feasible = true;
};

/// The objective of the model with the strut's network replaced by `net` (bound). Throws what the
/// analysis throws (an unstable design: InvalidArgument from the Lyapunov solver).
ModelCost evaluate(const ModelStudy& study, const network::Network& net);

struct ModelLayoutResult {
  std::string layout, expression;
  network::Params values;  ///< every element value (0 = open, inf = rigid)
  std::vector<std::string> at_bounds;  ///< free values that ended on the search's limits (0 or ∞ side)
  ModelCost cost;
  int evaluations = 0;
  bool budget_exhausted = false;  ///< the search stopped at max_evaluations (numerics::Result::exhausted)
};

/// Optimises one layout (no free values: evaluates it). progress(start, evaluations, best).
/// `warm`: element values of other designs (the default, smaller layouts' optima) used as further
/// starts: their values for the names they share, each other element open (0) or rigid (∞), every
/// combination of those up to four; so a layout that contains one of them does at least as well.
ModelLayoutResult optimise_layout(const ModelStudy& study, const std::string& layout,
                                  const numerics::Progress& progress = {}, const std::vector<network::Params>& warm = {});

}  // namespace inerta::optim

namespace inerta::optim {

/// The objective over a grid of two free elements of a layout (the others at `values`): x, y in
/// decades around their values (±`decades`), n × n points, in parallel (oneTBB). J[i][j] at (x_i, y_j);
/// +∞ where it cannot be evaluated.
struct ObjectiveMap {
  std::string layout, x_name, y_name;
  std::vector<double> x, y;
  std::vector<std::vector<double>> J;
};
ObjectiveMap objective_map(const ModelStudy& study, const std::string& layout, const network::Params& values,
                           const std::string& x_name, const std::string& y_name, int n = 15, double decades = 1.0);

/// The study's transfer functions for the report: from the excitation's first input (rms: the road
/// or noise input; hinf: its input) to the weighted outputs, |H| per frequency (Hz). Empty for a
/// peak objective.
struct StudyFrf {
  std::string input;
  std::vector<std::string> outputs;
  std::vector<double> f;
  std::vector<std::vector<double>> magnitude;  ///< [output][frequency]
};
StudyFrf study_frf(const ModelStudy& study, const network::Network& net, const std::vector<double>& f);

}  // namespace inerta::optim
