#pragma once
// The data behind the figures of a design study (spec/07 "extra outputs", spec/06 §6.5), computed
// from a study and its optimised layouts. `inerta optimise --out DIR` writes them as CSV
// (io::write_study_report) and scripts/plot-study draws them:
//   (a) σ(v) of the default and the best design for each catenary (periodic fast path, as J2);
//   (b) the head FRF on the test rig (P_ay over the contact force, analysis::frf_linear), default vs best;
//   (c) the contact force in time at one speed (180 km/h) under each catenary (time domain), default vs best;
//   (d) the J2 map over (b, k) for the best layout with free b and k, its other values at their
//       optimum (thesis Fig. 7.15: b ∈ [0, 1500] kg × k ∈ [0, 100] kN/m);
//   (e) σ(v) of the best design with and without the inerter's centripetal correction (eq. 3.20 vs
//       the 1D form), in the time domain: the correction is quadratic in the velocities, so the
//       periodic path, linearised about rest, cannot see it.
// Speeds are in m/s, forces in N, FRFs in (m/s²)/N.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/frf.hpp"
#include "inerta/network/network.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::optim {

/// σ and the mean contact force over the study's speeds under one catenary.
struct SpeedCurve {
  std::string catenary;  ///< the catenary's label (its overrides)
  std::vector<double> speed, sigma, mean;
};

/// One curve per catenary for the suspension `net`, by the periodic fast path; the largest σ over
/// all curves is evaluate(study, net).J.
std::vector<SpeedCurve> sigma_curves(const Study& study, const network::Network& net);

/// The same by the time-domain reference (analysis::sweep), with the model option `centripetal`
/// (the inerter's centripetal correction, as `--no-centripetal` switches it off).
/// progress(done, total) counts speeds over all catenaries.
/// With acceptance limits, the runs use the criteria's filter (as evaluate_time); `runs`, if given,
/// receives each catenary's SpeedResults.
std::vector<SpeedCurve> sigma_curves_time(const Study& study, const network::Network& net, bool centripetal = true,
                                          const std::function<void(int, int)>& progress = {},
                                          std::vector<std::vector<analysis::SpeedResult>>* runs = nullptr);

/// One criterion of a study's acceptance set for one design, catenary variant, speed and contact
/// (analysis::assess of the run): its value, limit and margin, and the margin relative to the limit.
struct MarginRow {
  std::string design, catenary;
  double speed = 0;  ///< m/s
  int contact = 0;   ///< the pantograph (0: the first)
  analysis::CriterionResult result;
  double relative = NAN;  ///< analysis::relative_margin (< 0: fails)
};
/// Every criterion of the study's acceptance set on each run of `runs` (sigma_curves_time's), for `design`.
std::vector<MarginRow> acceptance_margins(const Study& study, const std::string& design,
                                          const std::vector<std::vector<analysis::SpeedResult>>& runs);

/// The largest σ over the curves: J2, its speed, the mean force there and the catenary's index.
StudyCost worst_of(const std::vector<SpeedCurve>& curves);

/// The pantograph on its test rig (head held by the rig joint) with the suspension `net`, relaxed
/// at the actuator's length of the rig's static equilibrium with the model's own suspension (so the
/// network carries no static load there). Input of analysis::frf_linear.
pantograph::Pantograph rig_model(const Study& study, const network::Network& net);

/// The contact force under one catenary at one speed (time domain, analysis::run_speed: static
/// equilibrium, then span by span until σ settles); t and F over the analysed window (the last
/// window_spans spans), t from the start of the run.
struct ForceHistory {
  std::string catenary;
  double speed = 0;
  std::vector<double> t, F;
  analysis::ContactStatistics stats;
};
std::vector<ForceHistory> contact_histories(const Study& study, const network::Network& net, double speed);

/// J2 over a grid of two element values of a layout, the others fixed.
struct CostMap {
  std::string layout, x, y;  ///< layout, and the names of the two varied elements
  network::Params values;    ///< all element values except x and y
  std::vector<double> xs, ys;
  std::vector<double> J;  ///< J[i·ys.size() + j] = J2 at (xs[i], ys[j]); NaN where no valid steady state exists
  double at(std::size_t i, std::size_t j) const { return J[i * ys.size() + j]; }
};

/// J2 (evaluate(), periodic fast path) at every grid point, in parallel (oneTBB);
/// progress(done, total) from worker threads, serialised.
CostMap cost_map(const Study& study, const std::string& layout, const network::Params& values, const std::string& x,
                 const std::vector<double>& xs, const std::string& y, const std::vector<double>& ys,
                 const std::function<void(int, int)>& progress = {});

/// n equally spaced values from a to b (both included; n >= 2).
std::vector<double> linspace(double a, double b, int n);

/// Index of the result with the lowest J among those whose layout has free elements named x and y
/// (free_parameters), or -1. Ties go to the first.
int best_with(const std::vector<LayoutResult>& results, const std::string& x, const std::string& y);

/// A suspension design: a label and its bound network.
struct Design {
  std::string label, layout;
  network::Params values;
  network::Network net;
};

/// True if the simplified network has an inerter (a value strictly between 0 and ∞).
bool has_inerter(const network::Network& net);

struct ReportOptions {
  double history_speed = 180 / 3.6;            ///< (c), m/s
  std::vector<double> frf_f;                   ///< (b), Hz; empty: 0.1, 0.15, …, 20 Hz
  std::string frf_output = "P_ay";             ///< the head's vertical acceleration
  int map_size = 15;                           ///< (d): map_size × map_size points; 0: no map
  double map_b_max = 1500, map_k_max = 100e3;  ///< (d): ranges [0, max], widened to hold the optimum
  /// The index in `results` of the design the report is about; −1: the lowest cost within the limits.
  /// (`optimise` passes the best time-domain re-check of a `layouts: all` study, issue 24 item 4.)
  int best = -1;
};

struct Report {
  std::string study;
  std::vector<std::string> catenaries;
  Design baseline, best;
  StudyCost default_cost, best_cost;                        ///< periodic fast path
  std::vector<SpeedCurve> sigma_default, sigma_best;        ///< (a)
  std::string frf_output;                                   ///< (b)
  analysis::Frf frf_default, frf_best;                      ///< (b)
  double history_speed = 0;                                 ///< (c)
  std::vector<ForceHistory> history_default, history_best;  ///< (c)
  std::optional<CostMap> map;                               ///< (d), if a layout has free b and k
  std::string map_note;                                     ///< why there is no map, or ""
  double map_opt_x = 0, map_opt_y = 0, map_opt_J = 0;       ///< (d): the optimum of the map's layout
  /// (e): σ(v) in the time domain with the centripetal correction on and off, for the best design;
  /// if that has no inerter (the correction then cannot act), also for the map's best point with
  /// b > 0, the best design that has one. A design without an inerter is simulated once (the
  /// switch cannot change its runs): off = on, off_simulated = false.
  struct Centripetal {
    Design design;
    std::vector<SpeedCurve> on, off;
    bool off_simulated = true;
  };
  std::vector<Centripetal> centripetal;
  StudyCost time_check;  ///< the best design's J2 in the time domain (= worst_of(centripetal[0].on))
  /// With acceptance limits (a time-domain study): the set's name and every criterion's margin for the
  /// default and the best design, per catenary variant and speed (from the runs of (a)).
  std::string acceptance;
  std::vector<MarginRow> margins;
};

/// progress(step, steps, what, done, total): called with done = 0 when a step starts, then as it
/// advances (done = total at its end).
using ReportProgress = std::function<void(int, int, const std::string&, int, int)>;

/// Computes (a)–(e) for the study's default suspension and its best layout result.
Report make_report(const Study& study, const std::vector<LayoutResult>& results, const ReportOptions& options = {},
                   const ReportProgress& progress = {});

}  // namespace inerta::optim
