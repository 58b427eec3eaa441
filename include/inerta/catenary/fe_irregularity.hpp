#pragma once
// Irregularities of a finite-element line (docs/catenary-fe.md "Irregularities").
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace inerta::catenary {

/// Irregularities of the line (docs/catenary-fe.md "Irregularities"), applied to the form-found line.
struct FeIrregularity {
  /// m: random dropper-length errors, normal N(0, std²) truncated at ±4 std (a draw beyond is drawn
  /// again), from splitmix64-seeded xoshiro256** and Box–Muller (the same numbers on every platform);
  /// 0: none. One value per dropper in line order (stitch droppers included).
  double dropper_length_std = 0;
  std::uint64_t seed = 1;
  /// m, explicit per-dropper length errors in line order (added to the random ones); empty: none.
  std::vector<double> dropper_length_errors;
  /// A contact-wire height-error profile (x m, Δz m, up): interpolated linearly at the droppers and
  /// added to the form-finding's target heights (an installation error). Empty: none.
  std::vector<double> height_error_x, height_error_dz;
  std::string height_errors_file;  ///< where the profile was read from (for messages)
  struct PointMass {
    double x;     ///< m along the line
    double mass;  ///< kg
  };
  std::vector<PointMass> point_masses;  ///< hard spots on the contact wire (clamps, section insulators)
  /// The dynamics (K, M) with each dropper's own stiffness EA/L' and mass; false (default): with the
  /// designed droppers' (the form-finding without errors), so that the modal solve keeps the perfect
  /// line's modes (docs/catenary-fe.md "Irregularities"). The static state is exact either way.
  bool exact_dropper_dynamics = false;
  bool any() const {
    return dropper_length_std > 0 || !dropper_length_errors.empty() || !height_error_x.empty() || !point_masses.empty();
  }
};

/// The random dropper-length errors of `irr` for `count` droppers (m; FeIrregularity header).
std::vector<double> dropper_length_errors(const FeIrregularity& irr, std::size_t count);

}  // namespace inerta::catenary
