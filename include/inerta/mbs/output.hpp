#pragma once
// Named outputs of a model (CSV columns of `inerta simulate`).
#include <string>

namespace inerta::mbs {

struct Model;
struct State;
struct Workspace;

struct Output {
  enum class Kind {
    Coordinate,     ///< body coordinate x, y or θ (component 0, 1, 2)
    Position,       ///< global point position, component 0 = x, 1 = y
    Velocity,       ///< global point velocity
    Acceleration,   ///< global point acceleration
    ElementForce,   ///< force element's scalar force (tension positive for struts)
    ElementLength,  ///< strut length or joint relative angle
    Reaction,       ///< joint reaction on body j: component 0 = Fx, 1 = Fy, 2 = moment about its centre of mass
    Multiplier,     ///< raw Lagrange multiplier number `component` of the joint
  };
  std::string name;
  Kind kind = Kind::Coordinate;
  int index = 0;  ///< body, marker, force element or joint index
  int component = 0;
  double scale = 1.0;  ///< multiplies the value (e.g. −1 to report a compression as positive)
};

/// True if the output needs accelerations or multipliers (Workspace after `accelerations`).
bool needs_accelerations(const Output& out);

/// Evaluates an output; ws must hold the frames (set_state) at (t, x) and, where
/// needs_accelerations(out), the accelerations and multipliers.
double evaluate_output(const Output& out, const Model& model, double t, const State& x, const Workspace& ws);

}  // namespace inerta::mbs
