#pragma once
// One small uniform interface for every force element (design.md, principle 3): an element adds
// its generalised force into Workspace::Q and, for inerters, its mass term into Workspace::M
// (eq. 3.33); it never overwrites them. Each element reports its stored energy and the power it
// delivers, so that d/dt(T + Σ energy) = Σ power holds for any model without driven constraints.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "inerta/network/network.hpp"

namespace inerta::mbs {

struct Model;
struct State;
struct Workspace;
struct TimeFunction;

class ForceElement {
 public:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}
  virtual ~ForceElement() = default;
  const std::string& name() const { return name_; }

  /// Adds the generalised force (and inerter mass term) at (t, state).
  virtual void add(const Model& model, double t, const State& x, Workspace& ws) const = 0;
  /// Stored energy: spring potential, ½ b l̇² of an inerter, potential of gravity / constant force.
  virtual double energy(const Model&, double, const State&) const { return 0.0; }
  /// Power delivered to the bodies beyond −d(energy)/dt: −c l̇² for a damper, F·v for a point force.
  virtual double power(const Model&, double, const State&) const { return 0.0; }
  /// Scalar force for outputs (axial tension, joint moment or applied force), using ws.qdd.
  virtual double force(const Model& model, double t, const State& x, const Workspace& ws) const = 0;
  /// Strut length or joint relative angle; NaN where it has no meaning.
  virtual double length(const Model& model, const State& x) const;

  /// Internal states (e.g. the internal nodes of a network strut): their number and their first
  /// index in State::z, assigned by the compile step (Model::finalize). add() writes their
  /// derivatives into Workspace::zd.
  virtual int n_states() const { return 0; }
  int state_offset() const { return state_offset_; }
  /// A copy of this element whose states start at `offset` (called by Model::finalize). Every
  /// element with n_states() > 0 implements it; the default throws std::logic_error.
  virtual std::shared_ptr<const ForceElement> with_state_offset(int offset) const;
  /// Sets the internal states to their steady values at rest in the configuration x.q.
  virtual void relax(const Model&, State&) const {}
  /// A load whose value is a time function (point force, point torque): the same load with value f
  /// instead (the inputs of a linear analysis, mbs::linearise). Null for every other element.
  virtual std::shared_ptr<const ForceElement> with_value(const TimeFunction&) const { return nullptr; }
  /// The value of such a load at t (NaN for other elements).
  virtual double load_value(double) const;
  /// A network strut (network, actuator): its network, and the same strut with another network
  /// (simplified, neither open nor rigid; same markers) relaxed at `reference_length` (m; NaN: the
  /// strut's own), for design studies. Null for every other element.
  virtual const network::Network* strut_network() const { return nullptr; }
  virtual std::shared_ptr<const ForceElement> with_network(const network::Network&, double /*reference_length*/) const {
    return nullptr;
  }
  /// A strut: its terminal vector r = r_Pj − r_Pi (z = 0 in 2D) at x, so that the integrator can
  /// stop a strut that passes through zero length between two steps (r reverses). False otherwise.
  virtual bool strut_vector(const Model&, const State&, Eigen::Vector3d&) const { return false; }

 protected:
  int state_offset_ = 0;

 private:
  std::string name_;
};

}  // namespace inerta::mbs
