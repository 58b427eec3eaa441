#pragma once
// Internal polynomial helpers of the positive-real test and the synthesis (not installed).
// Polynomials are real, ascending powers (network::Poly).
#include <complex>
#include <vector>

#include "inerta/network/realisation.hpp"

namespace inerta::network::detail {

using cd = std::complex<double>;

int degree(const Poly& p);                       ///< -1 for the zero polynomial
Poly trimmed(Poly p, double rel = 0);            ///< drops leading |c| <= rel·max|c| (exact zeros if rel = 0)
double max_abs(const Poly& p);
Poly mul(const Poly& a, const Poly& b);
Poly add(const Poly& a, const Poly& b, double beta = 1);  ///< a + beta·b
Poly scaled(Poly p, double f);
Poly derivative(const Poly& p);
double eval(const Poly& p, double x);
cd eval(const Poly& p, cd s);
/// Quotient of p / d (the remainder is dropped: used where d is known to divide p).
Poly quotient(const Poly& p, const Poly& d);
/// Roots of p: exact zero low coefficients give exact roots at 0, the rest are the eigenvalues of
/// the companion matrix polished by Newton steps.
std::vector<cd> roots(const Poly& p);
/// Newton steps on p from s.
cd polish(const Poly& p, cd s);

/// E(x) = Re[a(jω)·conj(b(jω))] as a polynomial in x = ω²:
/// E_m = Σ_{i+j=2m} (−1)^((i−j)/2) a_i b_j.
Poly even_part(const Poly& a, const Poly& b);

/// The minimum over x = ω² ≥ 0 (and x → ∞) of r(x) = E(x)/M(x), M > 0 on x ≥ 0: the candidates
/// are x = 0, x → ∞ and the stationary points (real parts of the roots of E'M − EM' in x > 0).
struct Minimum {
  double value = 0;
  double x = 0;  ///< inf for x → ∞
  double magnitude = 0;  ///< max |r| over the candidates (a scale for tolerances)
};
Minimum minimum_ratio(const Poly& E, const Poly& M);

/// The median magnitude of the nonzero roots of n and d (1 if none): the frequency that
/// normalises s.
double characteristic_frequency(const Poly& n, const Poly& d);
/// Rounding-level coefficients (|c| <= rel·max|c|) removed: leading ones dropped (a root near
/// ∞), the lowest ones zeroed (roots at 0).
void clean_rounding(Poly& p, double rel);

/// Cancels roots common to n and d (|r_n − r_d| <= tol·max(|r_n|, |r_d|), or both <= tol).
void cancel_common(Poly& n, Poly& d, double tol);

}  // namespace inerta::network::detail
