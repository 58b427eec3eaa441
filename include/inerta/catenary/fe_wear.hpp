#pragma once
// Contact-wire wear (docs/catenary-fe.md "Wear"): the percent of the wire's cross-section remaining,
// uniform or along the line (wire-thickness measurements). Where worn, the wire's mass per length is
// that fraction of the new wire's and its bending stiffness that fraction squared (the second moment of
// area of a section worn at the same shape); its tension is unchanged.
#include <string>
#include <vector>

namespace inerta::catenary {

struct FeWear {
  double uniform = 100;           ///< %, over the whole contact wire
  std::vector<double> x, percent;  ///< a profile: m along the line, % (linear between, constant beyond)
  std::string file;               ///< where the profile was read from
  bool any() const { return uniform != 100 || !x.empty(); }
  /// The percent remaining at x (m along the line).
  double at(double x) const;
};

}  // namespace inerta::catenary
