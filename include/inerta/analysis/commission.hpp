#pragma once
// Commissioning a pantograph design (issue 49; docs/contact-quality.md "Commissioning"): as a real
// pantograph is set up once before service —
//   1. its suspension's static springs relaxed at standstill on a reference line (the actuator's
//      length at the static equilibrium with the model's own suspension), so that the static contact
//      force stays the model's nominal;
//   2. its aerodynamic uplift a v² tuned so that the mean contact force meets a target at one speed on
//      that line (aero-fit);
//   3. its static contact force at standstill over the working range of contact-wire heights (the
//      EN 50206-1 test: the head held at each height, the pantograph alone).
// After that every line it runs on takes these values; nothing is re-set. One function for the CLI
// (`inerta pantograph aero-fit`), the study engine and Python.
#include <cmath>
#include <vector>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/network/network.hpp"
#include "inerta/pantograph/pantograph.hpp"

namespace inerta::analysis {

/// The actuator's length at the static equilibrium of the pantograph (its own suspension) under the
/// catenary: where a candidate network is relaxed (it then carries no static load there). ModelError
/// if the pantograph has no actuator.
double operating_length(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                        const catenary::Contact& contact);

/// The aerodynamic trim: the uplift a v² that brings the mean contact force to `target` at `speed`.
struct Trim {
  double speed = 0;     ///< m/s; 0: no trim (the model's own aerodynamic uplift is kept)
  double target = NAN;  ///< N
  /// The mean of the 20 Hz statistics (a finite line) or of the raw force.
  Statistics statistics = Statistics::Filtered;
  RunOptions options;      ///< the trim runs (time domain): their filter
  bool periodic = false;   ///< by the periodic fast path (a lumped line), its raw mean
  int harmonics = 8;       ///< of the periodic path
  double tolerance = 0.05;  ///< N
};

/// Contact-wire heights around the reference line's, m (a study's `working_range:`).
struct WorkingRange {
  double below = 0.1, above = 0.1;
  int points = 5;  ///< heights from −below to +above, evenly (≥ 2)
};

/// What commissioning set and measured (reported per design).
struct Commissioning {
  /// m: the actuator's length on the reference line at standstill — every static spring of the
  /// suspension is relaxed there (NaN: the model's own suspension kept).
  double operating_length = NAN;
  /// N/m: the suspension's static stiffness G(0) = lim s→0 s·Y(s) (NaN: the model's own kept).
  double static_stiffness = NAN;
  /// N: the static contact force at standstill on the reference line (NaN: the model has no rig).
  double static_force = NAN;
  /// m: the head's height on the reference line at standstill above the model's rig position.
  double head_offset = NAN;
  double a = 0;          ///< N·s²/m²: the aerodynamic uplift a v² (b = c = 0) after the trim
  double mean = NAN;     ///< N: the mean contact force at the trim speed with it
  double mean_without = NAN;  ///< N: the same without aerodynamic uplift
  double target = NAN;   ///< N
  bool trimmed = false;  ///< a trim was asked for
  bool reached = false;  ///< the trim reached its target within its tolerance
  int runs = 0;          ///< trim runs made
  /// The static contact force over the working range (empty: not computed): heights relative to the
  /// reference line's contact point, m (up); the force there, N — the static force at the reference
  /// height plus what the suspension adds to the stock pantograph's at that height (its lifting device
  /// holds the stock static force over the range, EN 50206-1); and the model's own force there (its
  /// frame springs included: the HSX's joint-friction spring k_f alone moves it by ≈ ±35 % over ±0.1 m).
  std::vector<double> range_height, range_force, range_model;
  double range_min() const;  ///< N, NaN if empty
  double range_max() const;
};

struct Commissioned {
  pantograph::Pantograph pantograph;  ///< with its suspension relaxed and its aerodynamic uplift set
  Commissioning record;
};

/// Commissions `pantograph` with `suspension` (nullptr: its own suspension kept, no actuator needed) on
/// the `reference` line: relaxation, trim (trim.speed > 0) and, with `range`, the static contact force
/// over the working range (needs the model's rig joint; else left empty). Throws NumericalError if the
/// line gives no static equilibrium; a trim that cannot reach its target (the mean force without
/// uplift already above it) leaves a = 0 and reached = false.
Commissioned commission(const pantograph::Pantograph& pantograph, const network::Network* suspension,
                        const catenary::Catenary& reference, const catenary::Contact& contact, const Trim& trim,
                        const WorkingRange* range = nullptr);

/// The static contact force at standstill with the head held `offset` m above the model's rig position
/// (EN 50206-1's static force test): the rig joint's reaction. ModelError without a rig joint.
double static_force_at(const pantograph::Pantograph& pantograph, double offset);

}  // namespace inerta::analysis
