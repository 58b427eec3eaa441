#pragma once
// Solving a finite-element line in time: the loads, the state and the direct HHT-α integrator
// (fe_line.hpp's header comment).
#include <Eigen/Dense>
#include <exception>
#include <memory>
#include <vector>

#include "inerta/catenary/fe_line.hpp"

namespace inerta::catenary {

/// The structural solver of one run on the line (a workspace, one per run): the direct HHT-α solve
/// of the whole line (FeIntegrator) or the modal solve of a moving window (FeModalSolver). Heights
/// are absolute; x along the line.
struct FeLoad;
class FeLineSolver {
 public:
  virtual ~FeLineSolver() = default;
  virtual double dt() const = 0;
  virtual double time() const = 0;
  /// At rest in the static equilibrium under upward forces F_k at x_k, at time t.
  virtual void start(const std::vector<double>& x, const std::vector<double>& F, double t) = 0;
  /// One step to time() + dt() with the loads at its end; `forces`: the upward force of each load.
  virtual void step(const std::vector<FeLoad>& loads, std::vector<double>& forces) = 0;
  virtual double height(double x) const = 0;                     ///< contact wire at x, m
  virtual double height_rate(double x, double speed) const = 0;  ///< at the point moving with speed, m/s
  virtual double uplift(double x) const = 0;                     ///< contact wire at x from its static state, m
  virtual std::vector<double> support_uplift() const = 0;        ///< contact wire at each interior mast, m
  /// Kinetic + elastic energy relative to the static state (slack droppers' springs removed), J.
  virtual double energy() const = 0;
};

/// A load on the contact wire at x for one step: either a prescribed upward force, or a penalty
/// contact with a head whose height and vertical velocity at the end of the step are given
/// (absolute heights: the wire at x is at static_height(x) + N(x)ᵀu).
struct FeLoad {
  double x = 0;
  bool penalty = false;
  double force = 0;                ///< N, prescribed (penalty = false)
  double head_y = 0, head_v = 0;   ///< m, m/s (penalty)
  double stiffness = 0, damping = 0;
  double speed = 0;                ///< m/s, for the convective part of the wire's velocity
};

/// The line's dynamic state: displacements from the static state, velocities, accelerations.
struct FeState {
  Eigen::VectorXd u, v, a;
  std::vector<char> slack;   ///< per dropper
  std::vector<char> active;  ///< per penalty load of the last step: in contact
  Eigen::VectorXd q;         ///< net internal force at this time (HHT-α only)
  double t = 0;
};

/// HHT-α stepping of one FeLine with a fixed step; holds the factorisation and the cache of
/// columns of its inverse (a workspace: one per run, not shared between threads).
class FeIntegrator {
 public:
  FeIntegrator(const FeLine& line, double dt, double alpha);
  double dt() const { return h_; }
  const FeLine& line() const { return L_; }
  /// The line at rest in its static equilibrium under upward forces F_k at x_k (droppers free to
  /// slacken), at time t.
  FeState initial(const std::vector<double>& x, const std::vector<double>& F, double t = 0) const;
  /// One step from s.t to s.t + dt() with the loads at the end of the step; `forces` receives the
  /// upward force on the wire of each load (N; 0 for an open contact). NumericalError (with t) if
  /// the active set of droppers and contacts does not settle.
  void step(FeState& s, const std::vector<FeLoad>& loads, std::vector<double>& forces);
  /// Kinetic + elastic energy relative to the static state (droppers as in s.slack), J.
  double energy(const FeState& s) const;
  /// Wire height (m, absolute) and its vertical velocity (m/s) at the moving point x with speed.
  double height(const FeState& s, double x) const;
  double height_rate(const FeState& s, double x, double speed) const;
  long solves() const { return solves_; }
  long active_set_passes() const { return passes_; }

 private:
  const Eigen::VectorXd& column(int dof);  ///< A⁻¹ e_dof, cached (least recently used evicted)
  void solve(Eigen::VectorXd& b) const;    ///< b ← A⁻¹ b (banded Cholesky, LAPACK)
  const FeLine& L_;
  double h_, alpha_, beta_, gamma_;
  double c0_, c1_, c2_, c3_, c4_, c5_;
  int kd_ = 0;                ///< half bandwidth of A
  std::vector<double> band_;  ///< Cholesky factor of A, LAPACK lower band storage
  std::vector<double> rdiag_;  ///< 1 / its diagonal
  std::vector<double> mk_band_;  ///< M and (1+α) b K₀, lower band storage interleaved per column
  void band_products(const Eigen::VectorXd& w, const Eigen::VectorXd& v, Eigen::VectorXd& r) const;  ///< r = M w + Kb v
  std::vector<Eigen::VectorXd> contact_z_, dropper_z_;
  std::vector<int> slot_of_;  ///< per DOF: cache slot or −1
  std::vector<Eigen::VectorXd> cache_;
  std::vector<int> cache_dof_;
  std::vector<long> cache_used_;
  long clock_ = 0;
  mutable long solves_ = 0;
  long passes_ = 0;
  Eigen::VectorXd r_, x0_, w1_, w2_, vt_;
};

/// The direct solve of the whole line (FeIntegrator) as a run's solver.
std::unique_ptr<FeLineSolver> make_direct_solver(const FeLine& line);

/// The solvers of several runs on one line stepped together (issue 50: lanes, one a design), their
/// loads at the same places every step: what depends on the line and the load positions only (the
/// window and its modes, the loads' modal rows and couplings) made once for all of them, each lane its
/// own state. Each lane's numbers are those of its solver stepped alone, bit for bit.
class FeLineLanes {
 public:
  virtual ~FeLineLanes() = default;
  virtual int lanes() const = 0;
  /// Lane i's solver: start() and the queries; its step() steps it alone (the others left as they are
  /// only where the lanes share nothing: a lane alone in its group).
  virtual FeLineSolver& lane(int i) = 0;
  /// One step of the lanes `which` (ascending, each started): loads[j], forces[j] those of lane which[j]
  /// (the same positions x in every lane). A lane's exception is caught into errors[j] (its state then
  /// undefined: the caller stops it); the other lanes step on.
  virtual void step(const std::vector<int>& which, const std::vector<std::vector<FeLoad>>& loads,
                    std::vector<std::vector<double>>& forces, std::vector<std::exception_ptr>& errors) = 0;
};

/// Independent solvers stepped one after the other (the direct solve shares nothing between runs).
std::unique_ptr<FeLineLanes> make_separate_lanes(std::vector<std::unique_ptr<FeLineSolver>> solvers);

}  // namespace inerta::catenary
