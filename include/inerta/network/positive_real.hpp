#pragma once
// Positive-real test of a rational admittance Y(s) = num/den (docs/synthesis.md).
//
// Y is positive real (PR) iff (Van Valkenburg, Introduction to Modern Network Synthesis, ch. 4;
// Guillemin, Synthesis of Passive Networks, ch. 1):
//  (i)   num and den have no roots in Re s > 0, and their jω-axis roots are simple;
//  (ii)  the poles on the jω axis, s = 0 and s = ∞ included (|deg num − deg den| ≤ 1), have real
//        positive residues (so have the zeros, as poles of 1/Y);
//  (iii) Re Y(jω) = E(ω²)/|den(jω)|² ≥ 0 for every ω ≥ 0, E(x) = Re[num(jω)·conj(den(jω))].
// (iii) is certified exactly, not on a frequency grid: the minimum of Re Y(jω) is taken over
// ω = 0, ω → ∞ and the stationary points, the positive roots of a polynomial.
#include <string>

#include "inerta/network/realisation.hpp"

namespace inerta::network {

struct PrTest {
  bool positive_real = false;
  std::string reason;     ///< why not (empty if PR)
  double re_min = 0;      ///< min over ω ≥ 0 (ω → ∞ included) of Re Y(jω)
  double omega_min = 0;   ///< where (rad/s; inf for ω → ∞)
};

/// Tolerances: s is normalised by wc, the median magnitude of the nonzero roots, and num, den by
/// their largest coefficients (Y(s) = g·Ỹ(s/wc)); coefficients below 1e-13 of the largest are
/// rounding (dropped at the top, zeroed at the bottom). Re Y(jω) ≥ −rel_tol·g·G counts as ≥ 0, G
/// the larger of 1 and the largest finite |Ỹ(jω)| at the frequencies examined (so a minimum
/// function, Re Y touching 0, is PR). Roots count as on the
/// jω axis when |Re s| ≤ max(rel_tol, 1e-7)·|s| (s normalised by a characteristic frequency);
/// roots of num and den closer than 1e-6 relative cancel first. Throws inerta::InvalidArgument
/// for an empty, all-zero or non-finite num or den, or a rel_tol outside [0, 1e-2].
PrTest positive_real(const Rational& y, double rel_tol = 1e-9);

/// The closed-form test of a biquadratic Y = (a2 s² + a1 s + a0)/(d2 s² + d1 s + d0) with all
/// coefficients ≥ 0 (not all of a, nor all of d, zero): PR iff
/// (√(a2·d0) − √(a0·d2))² ≤ a1·d1. Throws inerta::InvalidArgument otherwise.
bool biquadratic_positive_real(double a0, double a1, double a2, double d0, double d1, double d2);

}  // namespace inerta::network
