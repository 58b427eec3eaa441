#pragma once
// A tensioned wire and the element matrices of a tensioned Euler–Bernoulli beam (spec/05 §5.3;
// fe_line.hpp's header comment).
#include <Eigen/Dense>

namespace inerta::catenary {

/// A tensioned wire.
struct FeWire {
  double tension = 0;          ///< T, N
  double mass_per_length = 0;  ///< ρA, kg/m
  double EI = 0;               ///< bending stiffness, N·m²
  double wave_speed() const;   ///< sqrt(T/ρA), m/s
};

/// Element matrices of a tensioned Euler–Bernoulli beam on [w_i, θ_i, w_j, θ_j] (header comment).
Eigen::Matrix4d beam_stiffness(double EI, double tension, double length);
Eigen::Matrix4d beam_mass(double mass_per_length, double length);

}  // namespace inerta::catenary
