#pragma once
// Road profiles of ISO 8608 (ISO 8608:2016, classes A–H) as base excitation (issue 13, part 4).
// Convention (documented in docs/assumptions.md#road-profiles):
//   one-sided displacement PSD in the spatial frequency n (cycles/m), m³ = m²/(cycles/m):
//     G_d(n) = G_d(n0) (n / n0)^−2,   n0 = 0.1 cycles/m,
//   G_d(n0) the class's geometric mean: A 16e-6, B 64e-6, C 256e-6, … ×4 per class, H 262144e-6 m³.
//   At a constant speed v (m/s) the profile seen in time, z(t) = h(v t), has the one-sided PSD
//     G_z(f) = G_d(f / v) / v  (m²/Hz),  and its velocity ż a white one-sided PSD
//     G_ż(f) = (2π f)² G_z(f) = 4π² n0² G_d(n0) v  (m²/s² per Hz).
// The seeded generator (RoadProfile, TimeFunction::road) is documented in time_function.hpp.
#include <cstdint>

namespace inerta::mbs {

constexpr double kIso8608N0 = 0.1;  ///< reference spatial frequency n0, cycles/m

/// G_d(n0) of class 'A'..'H' (lower case accepted), m³; InvalidArgument for any other letter.
double iso8608_gd0(char road_class);
/// G_d(n) = G_d(n0) (n/n0)^−2, m³ (n > 0, cycles/m).
double iso8608_psd(char road_class, double n);
/// The white one-sided PSD of the vertical velocity at speed v (m/s): 4π² n0² G_d(n0) v, m²/s²/Hz.
double iso8608_velocity_psd(char road_class, double speed);
/// ∫ G_d dn over [n_min, n_max] = G_d(n0) n0² (1/n_min − 1/n_max), m²: the profile's variance in that band.
double iso8608_variance(char road_class, double n_min, double n_max);

/// A seeded random road of ISO 8608 class `road_class` driven over at `speed` (see
/// TimeFunction::road): the profile is `length` metres long (it repeats after that) and contains
/// the spatial frequencies n_min ≤ n ≤ n_max (cycles/m).
struct RoadProfile {
  char road_class = 'A';
  double speed = 0;     ///< m/s, > 0
  double n_min = 0.011; ///< cycles/m, > 0 (ISO 8608's band 0.011–2.83 cycles/m by default)
  double n_max = 2.83;  ///< cycles/m, > n_min
  double length = 0;    ///< m, > 0: the generator's period (a whole number of the lowest wavelength)
  std::uint64_t seed = 1;
  double delay = 0;     ///< s, ≥ 0: f(t) = profile(t − delay) (a second axle on the same road)
};

}  // namespace inerta::mbs
