#pragma once
// The lumped catenary (eq. 7.1) fitted to a finite-element line.
#include <vector>

#include "inerta/catenary/fe_line.hpp"
#include "inerta/catenary/lumped.hpp"

namespace inerta::catenary {

/// The lumped catenary of eq. 7.1 fitted to the line (spec/05 §5.3): along one span, the point
/// stiffness k(x) = 1/e(x) (e: FeLine::elasticity), the equivalent moving mass
/// m(x) = gᵀ M g / e², the mass of the static deflection shape g = K₀⁻¹ N(x) under a unit force at
/// x seen at x (the low-frequency expansion 1/H(ω) ≈ k − m ω² of the point receptance), and the
/// damping c(x) = gᵀ C g / e² are sampled and expanded in cosines of 2π i x / L, i = 0..3 (x = 0 at
/// a mast): the coefficients k_ci, m_ci, c_ci of eq. 7.1.
struct LumpedFit {
  LumpedCatenary lumped;
  int span = 0;  ///< the span fitted (1-based)
  std::vector<double> x;  ///< m from the span's first mast
  std::vector<double> elasticity, mass, damping;  ///< FE values at x: m/N, kg, N·s/m
  std::vector<double> fitted_elasticity;          ///< 1 / (lumped k_c at x), m/N
  double max_elasticity_error = 0;                ///< max |fitted − FE| / FE over x
  /// The same with the FE elasticity averaged over one dropper spacing around x (the span-scale
  /// variation that three harmonics can follow; the dropper-scale wiggles they cannot).
  double max_smoothed_error = 0;
  double rms_error = 0, rms_smoothed_error = 0;  ///< root-mean-square of the same relative errors
};
/// span: 1-based, 0 = the middle span. points: samples along the span (>= 16).
LumpedFit fit_lumped(const FeLine& line, int span = 0, int points = 220);

}  // namespace inerta::catenary
