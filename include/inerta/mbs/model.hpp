#pragma once
// The immutable planar multibody model (spec/02). Algorithms read `const Model&` and write
// into a State or Workspace (design.md, principle 1).
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "inerta/mbs/force_element.hpp"
#include "inerta/mbs/joint.hpp"
#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/output.hpp"
#include "inerta/mbs/spatial.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

/// Rigid body; coordinates q = [x y θ] (2D) or [x y z e0 e1 e2 e3] (3D, spatial.hpp) of the centre
/// of mass (centroidal frame).
struct Body {
  std::string name;
  double mass = 0;                                        ///< kg
  double inertia = 0;                                     ///< kg·m² about the centre of mass (2D)
  Vec3 q0 = Vec3::Zero();                                 ///< tabulated initial position [x y θ] (2D)
  Vec3 qd0 = Vec3::Zero();                                ///< initial velocity (2D)
  Mat3 inertia3 = Mat3::Zero();                           ///< 3D: centroidal inertia tensor in the body frame, kg·m²
  Vec7 q0s = (Vec7() << 0, 0, 0, 1, 0, 0, 0).finished();  ///< 3D: tabulated [R; p]
  Vec7 qd0s = Vec7::Zero();                               ///< 3D: [Ṙ; ṗ]
  bool weighs = true;  ///< gravity acts on it (not on an equivalent mass such as the lumped catenary's)

  /// InvalidArgument (naming the body, the parameter and the value) unless mass and inertia are
  /// finite and >= 0 (zero is allowed where the joints constrain the direction, docs/model-format.md),
  /// the 3D inertia tensor is symmetric, positive semi-definite and satisfies the triangle inequality
  /// of a rigid body, and the initial positions and velocities are finite. Model::finalize calls it.
  void validate() const;
};

/// Body-fixed point. body = kGround means a fixed point with u in global coordinates.
struct Marker {
  std::string name;  ///< "body.point"
  int body = kGround;
  Vec2 u = Vec2::Zero();
  Vec3 u3 = Vec3::Zero();  ///< 3D: local coordinates (u = its x, y)
};

struct Options {
  bool gravity = true;
  Vec2 g = Vec2(0.0, -9.81);        ///< m/s², spec README
  Vec3 g3 = Vec3(0.0, -9.81, 0.0);  ///< 3D
  double alpha = 5.0;               ///< Baumgarte, eq. 4.11
  double beta = 5.0;
  bool centripetal = true;  ///< model-wide switch of the inerter correction (eq. 3.9)
  double t_end = 10.0;      ///< default simulation end time, s
  double sample = 0.01;     ///< default output sampling interval, s
  /// A run fails when max |C(q, t)| exceeds this (m or rad; docs/assumptions.md#constraint-drift).
  double max_violation = 1e-4;
};

struct Model {
  std::string name;
  std::string source;  ///< file the model was read from (for messages)
  Options options;
  std::vector<Body> bodies;
  std::vector<Marker> markers;
  std::vector<Joint> joints;
  std::vector<std::shared_ptr<const ForceElement>> forces;
  /// Indices in `forces` of the actuators (a pantograph's suspension, spec/04 §4.2), in file order:
  /// written by the loader, kept by the transformations that move force elements.
  std::vector<int> actuators;
  std::vector<Output> outputs;
  std::vector<int> held;           ///< coordinates held fixed during assembly
  std::vector<std::string> notes;  ///< things the loader decided that a user should read (printed by the CLI)

  int dimension = 2;  ///< 2 (planar) or 3 (spatial)
  bool spatial() const { return dimension == 3; }
  int body_coords() const { return spatial() ? 7 : 3; }
  int n_coords() const { return body_coords() * static_cast<int>(bodies.size()); }
  int n_constraints() const { return n_constraints_; }
  int dof() const { return n_coords() - n_constraints_; }
  int n_states() const { return n_states_; }  ///< internal states of force elements

  int find_body(const std::string& name) const;    ///< index, kGround for "ground", -2 if unknown
  int find_marker(const std::string& name) const;  ///< -1 if unknown
  int find_joint(const std::string& name) const;
  int find_force(const std::string& name) const;
  std::string coord_name(int k) const;  ///< "bar1.theta" (2D), "bar1.e2" (3D)
  /// Constraint row r for messages: "joint 'pin' (equation 2)", or a 3D body's normalisation.
  std::string constraint_name(int row) const;
  /// 3D: the row of body b's normalisation constraint pᵀp − 1 = 0 (after the joints' rows).
  int norm_row(int b) const { return n_joint_rows_ + b; }
  /// Rows of eq. 4.12 as solved by `accelerations`: all in 2D, the joints' in 3D (the normalisation
  /// rows are eliminated there, dynamics.cpp).
  int n_solved_rows() const { return n_joint_rows_; }

  /// The compile step: assigns every body's coordinate address, every joint's constraint rows and
  /// every force element's internal-state offset (an element whose states must move is replaced by
  /// a relocated copy, ForceElement::with_state_offset). Call after any change of bodies, joints or
  /// forces; the transformations in this library (remove_joint, coupling, suspension replacement)
  /// do, so no offset can go stale. Checks every body (Body::validate).
  void finalize();

  // Address table (valid after finalize) and the per-body views that use it.
  int q_adr(int body) const { return q_adr_[static_cast<std::size_t>(body)]; }  ///< first coordinate of body
  int state_adr(int force) const { return state_adr_[static_cast<std::size_t>(force)]; }  ///< first z of element
  Vec3 q_of(const State& x, int body) const;   ///< 2D body coordinates [x y θ] (zeros for ground)
  Vec3 qd_of(const State& x, int body) const;  ///< 2D velocities
  BodyFrame frame(const State& x, int body) const;      ///< 2D frame (identity for ground)
  SpatialFrame sframe(const State& x, int body) const;  ///< 3D frame (identity for ground)

  /// Removes joint `name` if present (outputs of that joint go, the others are re-indexed) and
  /// refinalizes; returns whether it was there.
  bool remove_joint(const std::string& name);

  /// Initial state from the bodies' tabulated q0, qd0 (not yet assembled).
  Eigen::VectorXd q0() const;
  Eigen::VectorXd qd0() const;

 private:
  int n_constraints_ = 0;
  int n_joint_rows_ = 0;
  int n_states_ = 0;
  std::vector<int> q_adr_, state_adr_;
};

}  // namespace inerta::mbs
