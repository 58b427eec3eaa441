#pragma once
// The catenary interface (docs/architecture.md#catenaries). Every catenary type implements
// `Catenary`; coupling pantographs to it gives a `Coupled` system, which is all that analyses,
// studies, the CLI and the Python module see. Two kinds coexist behind the same interface:
//   - embedded: the catenary is part of each pantograph's multibody model (its coordinates are
//     bodies, its forces force elements) and is integrated with it by the multibody integrator —
//     the lumped catenary of eq. 7.1, and the prescribed wire profile (no coordinates at all);
//   - co-simulated: the catenary has its own structural integrator (e.g. Newmark on a finite-
//     element wire) and exchanges, at every coupling step, the contact force and the motion of the
//     contact points with the pantographs' multibody models, which it integrates in between.
// Contacts are addressed by typed handles (ContactId), one per pantograph, in the order given.
#include <array>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "inerta/catenary/contact.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/pantograph/pantograph.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::catenary {

struct LumpedCatenary;  // lumped.hpp

/// One pantograph running on the line.
struct PantographOnLine {
  pantograph::Pantograph pantograph;
  double x0 = 0;    ///< position of its contact point along the line at t = 0, m (x = 0: a mast)
  Contact contact;  ///< its contact law
};

/// A stretch of the line, m along it (the analysis section of a finite line).
struct Section {
  double from = 0, to = 0;
};

/// Something along a finite line, for drawings (reports): a mast, a dropper, a stitch dropper (a
/// point: from = to), a stitch wire or an overlap (a stretch). m along the line.
struct LineFeature {
  enum class Kind { Mast, Dropper, StitchDropper, StitchWire, Overlap } kind = Kind::Mast;
  double from = 0, to = 0;
};

/// Typed handle of one contact of a coupled system (pantograph k of the list given to couple).
struct ContactId {
  int index = -1;
};

/// One sample of a coupled run, for one contact: the multibody model integrated for that
/// pantograph (with an embedded catenary it holds the wire too), its state and workspace (frames;
/// accelerations and multipliers when asked for), and the contact force.
struct Sample {
  ContactId contact;
  double t = 0;          ///< s
  double x_contact = 0;  ///< position of the contact point along the line, m
  double force = 0;      ///< contact force, N, compression positive
  const mbs::Model& model;
  const mbs::State& state;
  const mbs::Workspace& ws;
  /// Height of the wire at the contact point above its static height without pantographs, m
  /// (NaN where the catenary has no such wire, e.g. a prescribed profile).
  double wire_uplift = std::numeric_limits<double>::quiet_NaN();
  /// On a line with two contact wires (Coupled::wires() == 2: tension sections and overlaps): the
  /// contact force of each wire (N; `force` is their sum) and each wire's uplift at the contact
  /// point (m; NaN where that wire is not at the contact point). `wire_uplift` is the running
  /// wire's (the lower one's).
  std::array<double, 2> force_wire{0.0, 0.0};
  std::array<double, 2> uplift_wire{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};
using SampleObserver = std::function<void(const Sample&)>;

/// Pantographs coupled to a catenary at one speed. Mutable: it holds the current state.
class Coupled {
 public:
  virtual ~Coupled() = default;
  virtual int n_contacts() const = 0;
  /// The handle of contact k; InvalidArgument outside 0 ≤ k < n_contacts().
  ContactId contact(int k) const;
  virtual double speed() const = 0;  ///< m/s
  virtual double span() const = 0;   ///< the catenary's span, m
  /// The multibody model integrated for the contact's pantograph, and its current state.
  virtual const mbs::Model& model(ContactId c) const = 0;
  virtual const mbs::State& state(ContactId c) const = 0;
  virtual double time() const = 0;  ///< current time, s
  /// A finite line (Catenary::line_length) and its analysis section: runs end before the leading
  /// pantograph reaches the end; statistics are taken over the section.
  virtual double line_length() const { return std::numeric_limits<double>::infinity(); }
  virtual Section section() const { return {0, line_length()}; }
  /// The time at which the leading pantograph is 1 m short of the end of a finite line (infinite otherwise).
  virtual double end_time() const { return std::numeric_limits<double>::infinity(); }
  /// Every part to its static equilibrium at t = 0 (the static uplift against the catenary).
  virtual void equilibrate() = 0;
  /// Integrates from time() to t_end, calling `observer` every dt (from time() on, for each
  /// contact in time order; a co-simulated catenary with a fixed step h samples every round(dt/h)
  /// steps). A bilateral contact whose force becomes negative stops the run with
  /// NumericalError (time, speed, force). `accelerations`: the samples' workspaces hold
  /// accelerations and multipliers. Returns the integrator statistics (summed over the parts).
  /// Positions along the line of the supports whose uplift the catenary reports (none by default),
  /// and their current uplift (m, up, from the static state without pantographs).
  virtual std::vector<double> support_x() const { return {}; }
  virtual std::vector<double> support_uplift() const { return {}; }
  /// A name per support (its column in OUT.supports.csv): `uplift@X`, with the suffix _w1 or _w2 where
  /// two registrations share a mast (an overlap).
  virtual std::vector<std::string> support_names() const;
  /// Contact wires a pantograph can touch: 1, or 2 on a line of tension sections (Sample::force_wire).
  virtual int wires() const { return 1; }
  /// The stretches of the line where two contact wires run side by side (statistics of their own).
  virtual std::vector<Section> overlaps() const { return {}; }
  virtual solve::RunStats advance(double t_end, double dt, const solve::IntegratorOptions& options,
                                  const SampleObserver& observer, bool accelerations = false) = 0;
};

/// One sample of lane `lane` of a CoupledLanes.
using LaneObserver = std::function<void(int lane, const Sample&)>;

/// Several designs on one line at one speed, stepped together (issue 50: a study's batch of designs):
/// lane i is the Coupled of the i-th train, the trains' pantographs at the same positions. Each lane's
/// samples and results are those of coupling its train alone, bit for bit. A lane that fails (no static
/// equilibrium, a numerical failure in its run) stops with its exception kept (error(i)); the others go
/// on. Catenary::couple_lanes makes one.
class CoupledLanes {
 public:
  explicit CoupledLanes(std::vector<std::unique_ptr<Coupled>> lanes);
  virtual ~CoupledLanes() = default;
  int lanes() const { return static_cast<int>(lanes_.size()); }
  Coupled& lane(int i);
  const Coupled& lane(int i) const;
  /// Lane i stops with this exception (e.g. its equilibrate() threw): not advanced any more.
  void fail(int i, std::exception_ptr e);
  std::exception_ptr error(int i) const;  ///< nullptr while it runs
  bool running(int i) const { return !error(i); }
  /// Every running lane from its time() to t_end: observer(i, s) receives what lane i's own
  /// Coupled::advance would give its observer, in the same order for that lane. A lane's exception
  /// (from its run or from the observer) fails that lane alone.
  virtual void advance(double t_end, double dt, const solve::IntegratorOptions& options, const LaneObserver& observer,
                       bool accelerations = false);

 protected:
  std::vector<std::unique_ptr<Coupled>> lanes_;
  std::vector<std::exception_ptr> errors_;
};

/// A catenary type (lumped.hpp, wire_profile.hpp, ...).
class Catenary {
 public:
  virtual ~Catenary() = default;
  virtual std::string describe() const = 0;  ///< one line for reports, with its key numbers
  virtual double span() const = 0;           ///< m: the period of the line (statistics windows)
  virtual int max_pantographs() const = 0;   ///< how many pantographs it carries at once
  /// Length of the line, m: a run ends when the leading pantograph reaches it (infinite for a
  /// periodic catenary, which runs until its statistics settle).
  virtual double line_length() const { return std::numeric_limits<double>::infinity(); }
  /// The speed of transverse waves in the contact wire, sqrt(T/ρA), m/s: a pantograph must stay
  /// well below it (infinite for a catenary without wires, the lumped and profile models).
  virtual double wave_speed() const { return std::numeric_limits<double>::infinity(); }
  /// The analysis section of a finite line (EN 50317 statistics are taken there).
  virtual Section section() const { return {0, line_length()}; }
  /// m: the line's design limit of the contact wire's uplift at its registrations (acceptance
  /// criterion support_uplift, analysis/acceptance.hpp); NaN: none given.
  virtual double uplift_limit() const { return std::numeric_limits<double>::quiet_NaN(); }
  /// Whether a stop limits the registrations' uplift physically (registration.uplift_limited): the
  /// criterion support_uplift then takes its limited clearance factor (EN 50119 practice: 1.5 S₀).
  virtual bool uplift_limited() const { return false; }
  /// The line's masts, droppers, stitch wires and overlaps in order along it (empty: a point model).
  virtual std::vector<LineFeature> features() const { return {}; }
  /// The catenary without its variation along the line (for modes about a static equilibrium).
  virtual std::shared_ptr<const Catenary> mean() const = 0;
  /// The point model with time-periodic coefficients (eq. 7.1), if the catenary is one: the
  /// harmonic-balance fast path needs it. nullptr otherwise.
  virtual const LumpedCatenary* point_model() const { return nullptr; }
  /// Couples the pantographs at `speed` (m/s > 0). ModelError if it cannot carry them (too many,
  /// a contact law it does not support, a pantograph without a contact point).
  std::unique_ptr<Coupled> couple(const std::vector<PantographOnLine>& pantographs, double speed) const;
  /// One pantograph at x0 = 0.
  std::unique_ptr<Coupled> couple(const pantograph::Pantograph& p, const Contact& contact, double speed) const;
  /// Several trains (designs) on the line at `speed`, stepped together (CoupledLanes): each train
  /// checked as couple does; InvalidArgument unless every train has its pantographs at the same x0.
  /// A catenary that cannot share work between them (the point models) advances them one after another.
  std::unique_ptr<CoupledLanes> couple_lanes(const std::vector<std::vector<PantographOnLine>>& trains, double speed) const;
  /// The work runs with these pantographs need once (a finite-element line's modes, in parallel);
  /// sweeps call it before their parallel loop. Nothing for most catenaries; couple does it too.
  virtual void prepare(const std::vector<PantographOnLine>& /*pantographs*/) const {}
  /// A rough wall time (s) of one run with these pantographs at `speed` (m/s) for `t_end` s (≤ 0:
  /// until the leading pantograph reaches the line's end), on the 2-core reference machine
  /// (docs/benchmarks.md "Run-time estimate"): a guide for the cost guard (analysis/cost_guard.hpp),
  /// not a bound. Includes the one-off work not yet done (estimated_setup_seconds).
  /// The point models (lumped lines, wire profiles: issue 52): the pantographs' ODE run, about 1 ms a
  /// simulated second and pantograph (the HSX on models/catenary.yaml: 0.70 ms at 0.1 and 1 m/s, where the
  /// run's length is set by the speed: 7 200 s of a 720 m line at 0.1 m/s); t_end ≤ 0: a sweep's
  /// longest run, kSweepSpans spans.
  virtual double estimated_seconds(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const;
  static constexpr int kSweepSpans = 40;  ///< analysis::RunOptions::max_spans
  /// The part of estimated_seconds done once for every run of this catenary and not yet done (a
  /// finite-element line's setup and first modes): a sweep counts it once.
  virtual double estimated_setup_seconds(const std::vector<PantographOnLine>& /*pantographs*/) const { return 0; }
  /// The memory (bytes) a run with these pantographs at `speed` for `t_end` (≤ 0: to the line's end)
  /// keeps (a finite-element line's matrices, its windows' modes and the supports' history of a
  /// simulation; speed ≤ 0: a sweep's runs, which keep no history); 0 where that is small.
  virtual double estimated_bytes(const std::vector<PantographOnLine>& /*pantographs*/, double /*speed*/,
                                 double /*t_end*/) const {
    return 0;
  }

 protected:
  /// After couple's checks (count, speed, contact laws valid, contact markers present).
  virtual std::unique_ptr<Coupled> make_coupled(const std::vector<PantographOnLine>& pantographs,
                                                double speed) const = 0;
  /// After couple_lanes' checks: by default each train coupled on its own (CoupledLanes' own advance).
  virtual std::unique_ptr<CoupledLanes> make_lanes(const std::vector<std::vector<PantographOnLine>>& trains,
                                                   double speed) const;

 private:
  /// couple's checks; the pantographs with their aerodynamic uplift at this speed.
  std::vector<PantographOnLine> running(const std::vector<PantographOnLine>& pantographs, double speed) const;
};

}  // namespace inerta::catenary
