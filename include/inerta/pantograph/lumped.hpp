#pragma once
// Lumped n-mass pantograph (spec/05 §5.3; issue 12): a vertical chain of point masses, the head
// first, each on a vertical slider (x and θ locked), joined by springs and dampers; the last
// spring and damper hold the lowest mass to the ground (the car roof):
//
//     head m_1 ──k_1,c_1── m_2 ──k_2,c_2── … ── m_n ──k_n,c_n── ground
//
//   m_i ÿ_i = k_{i−1}(y_{i−1} − y_i) + k_i(y_{i+1} − y_i) + (the same with c and ẏ) + f_i,
//   y_0 = y_1 on the head's upper side (nothing above the head), y_{n+1} = 0 (ground),
//   f_n = F_0 (the static uplift, up), f_1 = −F_contact + F_aero(v), F_aero = a v² + b v + c.
//
// Gravity is off in this model: the static uplift is the net upward force of the real pantograph's
// raising mechanism on the lowest mass after its own weight, so the static contact force is
// F_0 + F_aero(v) minus what the ground spring takes (k_n times the lowest mass's static uplift).
// Coordinates y are displacements from the unloaded state: every mass sits at the origin at t = 0,
// and every spring and damper runs vertically over 10 m from mass i's centre to a point 10 m above
// mass i+1 (or the ground); only the relative vertical motion enters, so the geometry does not
// matter while the displacements stay below 10 m.
#include <vector>

#include "inerta/pantograph/pantograph.hpp"

namespace inerta::pantograph {

struct LumpedPantographData {
  std::vector<double> mass;       ///< kg, head first, each > 0
  std::vector<double> stiffness;  ///< N/m, >= 0: k_i between mass i and i+1, the last to the ground
  std::vector<double> damping;    ///< N·s/m, >= 0, at the same places
  double static_uplift = 0;       ///< N, >= 0: constant upward force on the lowest mass
  double aero_a = 0, aero_b = 0, aero_c = 0;  ///< aerodynamic uplift a v² + b v + c on the head (N, v in m/s)
  /// InvalidArgument unless every mass is > 0, every stiffness and damping >= 0, the three lists
  /// have the same length (>= 1), static_uplift >= 0 and a, b, c finite. The parameter is named as
  /// in the file: masses (empty), masses[i], stiffness[i], damping[i] (i from 0, the head),
  /// stiffness / damping (a list of the wrong length), static_uplift, aerodynamic.a, .b, .c.
  void validate() const;
};

/// The model (name "lumped pantograph", gravity off): bodies head, m2, …, mn (prismatic joints
/// slide_head, slide_m2, … to the ground, axis Y), springs k1..kn and dampers c1..cn, the constant
/// force static_uplift on mn, and a driving joint `rig` holding the head at y = 0 (the rig; removed
/// when a catenary is attached). Markers: head.cm, the contact point. Outputs: y_head, y_m2, … (m,
/// displacements) and F_contact (the rig's force on the head, N, compression positive). `aero` is
/// set on the head unless a = b = c = 0. Validates the data first (InvalidArgument).
Pantograph make_lumped_pantograph(const LumpedPantographData& d);

}  // namespace inerta::pantograph
