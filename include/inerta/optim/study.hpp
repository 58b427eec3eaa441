#pragma once
// Structure-based suspension design (spec/07): for each candidate layout, optimise its free element
// values by pattern search to minimise J2 = max over catenary variants of σ_max over the speeds.
#include <string>
#include <vector>

#include <memory>
#include <optional>

#include "inerta/catenary/catenary.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/network.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::optim {

struct Study {
  std::string name, source;
  pantograph::Pantograph pantograph;
  std::vector<std::shared_ptr<const catenary::Catenary>> catenaries;  ///< the variants (J1: one)
  std::vector<std::string> catenary_labels;
  catenary::Contact contact;
  std::vector<double> speeds;        ///< m/s
  std::vector<std::string> layouts;  ///< named layouts or expressions
  /// `layouts: all`: the layouts are every network these options allow (network::enumerate), searched
  /// by optim::optimise_all.
  std::optional<network::EnumerationOptions> all;
  /// `admittance: [2, 3]`: also optimise a positive-real admittance of each degree (the bound of
  /// optim/admittance_search.hpp).
  std::vector<int> admittance_degrees;
  numerics::Options search;
  double lo = 0.1, hi = 1e9;  ///< bounds of every free value (SI), 0 and ∞ reachable
  int harmonics = 8;
  /// Per catenary: the actuator's length at the static equilibrium of the pantograph with its own
  /// suspension under that catenary. Candidate networks are relaxed there, so they carry no static
  /// load and the static (≈ mean) contact force stays the design's, as the thesis requires.
  std::vector<double> operating_length;
};

/// Per catenary: the actuator's length at the static equilibrium of the pantograph with its own
/// suspension under that catenary (Study::operating_length).
std::vector<double> operating_lengths(const Study& study);

struct StudyCost {
  double J = 0;      ///< max over catenaries of σ_max, N
  double speed = 0;  ///< speed of the worst σ, m/s
  double mean = 0;   ///< mean contact force there, N
  int catenary = 0;  ///< index of the worst catenary
  /// > 0: the periodic solution is unstable at this speed, m/s (Floquet check, analysis/periodic.hpp):
  /// the design is infeasible and J = +∞.
  double unstable_speed = 0;
};

/// The pantograph's own suspension network (its actuator's), the baseline of the study.
network::Network default_suspension(const Study& study);

/// J2 of the pantograph with its suspension replaced by `net` (bound), by the periodic fast path.
/// A design whose periodic solution is unstable at some speed costs J = +∞ (unstable_speed set).
StudyCost evaluate(const Study& study, const network::Network& net);

struct LayoutResult {
  std::string layout, expression;
  network::Params values;  ///< all element values (fixed and optimised; 0 = open, inf = rigid)
  StudyCost cost;
  int evaluations = 0;
  int unstable = 0;                     ///< designs the search refused as unstable (Floquet multiplier ≥ 1)
  bool budget_exhausted = false;        ///< the search stopped at max_evaluations (numerics::Result::exhausted)
  std::vector<std::string> at_bounds;   ///< free values that ended on the search's limits (lo, hi, 0 or ∞)
};

/// J2 of a design by the time-domain reference (analysis::sweep), to re-check the fast path's winner.
StudyCost evaluate_time(const Study& study, const network::Network& net);

/// The element names of a layout (name or expression) that the optimiser varies: all but those the
/// named layout fixes, in order of appearance.
std::vector<std::string> free_parameters(const std::string& layout);

/// Optimises one layout (no free values: just evaluates it). progress(start, evaluations, best J).
/// `warm`: other designs' element values as further starts (as for model studies:
/// optim::optimise_layout(const ModelStudy&, …)), so the result is never worse than any of them.
LayoutResult optimise_layout(const Study& study, const std::string& layout, const numerics::Progress& progress = {},
                             const std::vector<network::Params>& warm = {});

}  // namespace inerta::optim
