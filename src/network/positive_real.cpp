#include "inerta/network/positive_real.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "inerta/error.hpp"
#include "polynomial.hpp"

namespace inerta::network {

namespace {
using detail::cd;

void check_coefficients(const Poly& p, const char* which) {
  if (p.empty()) throw InvalidArgument("positive_real", which, "no coefficients");
  bool nonzero = false;
  for (double c : p) {
    if (!std::isfinite(c)) throw InvalidArgument("positive_real", which, fmt::format("coefficient {} is not finite", c));
    nonzero = nonzero || c != 0.0;
  }
  if (!nonzero) throw InvalidArgument("positive_real", which, "all coefficients are zero");
}

std::string complex_text(cd z) {
  if (z.imag() == 0) return fmt::format("{:.4g}", z.real());
  return fmt::format("{:.4g}{:+.4g}j", z.real(), z.imag());
}

constexpr double kCluster = 1e-6;  // roots this close (relative) are one multiple root
constexpr double kZero = 1e-12;    // |s| below this (normalised) is s = 0
constexpr double kRounding = 1e-13;  // coefficients below this (relative, normalised) are rounding
}  // namespace

PrTest positive_real(const Rational& y, double rel_tol) {
  check_coefficients(y.num, "num");
  check_coefficients(y.den, "den");
  if (!(rel_tol >= 0 && rel_tol <= 1e-2))
    throw InvalidArgument("positive_real", "rel_tol", fmt::format("must be in [0, 1e-2], got {}", rel_tol));
  PrTest out;
  out.re_min = out.omega_min = std::numeric_limits<double>::quiet_NaN();

  Poly N = detail::trimmed(y.num), D = detail::trimmed(y.den);
  while (N.size() > 1 && D.size() > 1 && N[0] == 0.0 && D[0] == 0.0) N.erase(N.begin()), D.erase(D.begin());
  // Normalise s by a characteristic frequency wc and both polynomials to max |coefficient| 1:
  // Y(s) = g·Ỹ(s/wc).
  const double wc = detail::characteristic_frequency(N, D);
  for (std::size_t i = 0; i < N.size(); ++i) N[i] *= std::pow(wc, static_cast<double>(i));
  for (std::size_t i = 0; i < D.size(); ++i) D[i] *= std::pow(wc, static_cast<double>(i));
  const double gn = detail::max_abs(N), gd = detail::max_abs(D), g = gn / gd;
  N = detail::scaled(N, 1 / gn);
  D = detail::scaled(D, 1 / gd);
  detail::clean_rounding(N, kRounding);
  detail::clean_rounding(D, kRounding);
  detail::cancel_common(N, D, kCluster);
  N = detail::trimmed(N);
  D = detail::trimmed(D);
  const double axis_tol = std::max(rel_tol, 1e-7);

  const int dn = detail::degree(N), dd = detail::degree(D);
  if (std::abs(dn - dd) > 1) {
    out.reason = fmt::format("degree difference {} (numerator degree {}, denominator degree {}): Y has a multiple {} at "
                             "s = ∞; a positive-real function has |deg num − deg den| ≤ 1",
                             dn - dd, dn, dd, dn > dd ? "pole" : "zero");
    return out;
  }

  auto on_axis = [&](cd r) { return std::abs(r) <= kZero || std::abs(r.real()) <= axis_tol * std::abs(r); };
  // (i) Hurwitz in the wide sense, jω-axis roots simple.
  const std::vector<cd> rn = detail::roots(N), rd = detail::roots(D);
  for (const auto& [rs, name] : {std::pair{&rd, "denominator"}, std::pair{&rn, "numerator"}}) {
    for (cd r : *rs) {
      cd centre = 0;
      int m = 0;
      for (cd q : *rs)
        if (std::abs(q - r) <= kCluster * std::max(std::abs(q), std::abs(r)) || (std::abs(q) <= kZero && std::abs(r) <= kZero))
          centre += q, ++m;
      centre /= static_cast<double>(m);
      if (m > 1 && on_axis(centre)) {
        out.reason = fmt::format("{} has a root of multiplicity {} on the imaginary axis at s = {}; jω-axis poles and "
                                 "zeros of a positive-real function are simple",
                                 name, m, complex_text(on_axis(centre) && std::abs(centre) <= kZero ? cd(0) : centre * wc));
        return out;
      }
      if (!on_axis(r) && r.real() > 0) {
        out.reason = fmt::format("{} has a root at s = {} in the right half-plane", name, complex_text(r * wc));
        return out;
      }
    }
  }

  // (ii) Residues at the jω-axis poles of Y (from den) and of 1/Y (from num) real and positive.
  std::vector<double> pole_x;  // ω̃² of the jω-axis poles of Y (0 for s = 0)
  for (int pass = 0; pass < 2; ++pass) {
    const Poly& a = pass == 0 ? N : D;  // function a/b
    const Poly& b = pass == 0 ? D : N;
    const std::vector<cd>& rb = pass == 0 ? rd : rn;
    const char* what = pass == 0 ? "pole of Y" : "zero of Y (pole of 1/Y)";
    const double unit = pass == 0 ? g * wc : wc / g;  // residue of the unnormalised function
    const Poly db = detail::derivative(b);
    for (cd r : rb) {
      if (!on_axis(r)) continue;
      if (std::abs(r) > kZero && r.imag() < 0) continue;  // the pair's other member
      const cd s = std::abs(r) <= kZero ? cd(0) : cd(0, std::abs(r.imag()));
      const cd rho = detail::eval(a, s) / detail::eval(db, s);
      if (!(rho.real() > 0) || std::abs(rho.imag()) > kCluster * std::abs(rho)) {
        out.reason = fmt::format("{} at s = {} has the residue {}; jω-axis poles of a positive-real function have real "
                                 "positive residues",
                                 what, complex_text(s * wc), complex_text(rho * unit));
        return out;
      }
      if (pass == 0) pole_x.push_back(std::norm(s));
    }
    const int da = detail::degree(a), dbg = detail::degree(b);
    if (da == dbg + 1 && !(a.back() / b.back() > 0)) {
      out.reason = fmt::format("{} at s = ∞ has the residue {:.4g}; it must be positive", what,
                               a.back() / b.back() * (pass == 0 ? g / wc : 1 / (g * wc)));
      return out;
    }
  }

  // (iii) Re Y(jω) = E(x)/M(x), x = ω², M = |den(jω)|². A jω-axis pole at jω0 is a factor
  // (x − ω0²) of M twice and of E twice (its residue is real), at s = 0 a factor x of both: dividing
  // them out leaves the real part of the rest of Y, which is continuous.
  Poly E = detail::even_part(N, D), M = detail::even_part(D, D);
  for (double x0 : pole_x) {
    const Poly f = x0 == 0 ? Poly{0.0, 1.0} : Poly{x0 * x0, -2 * x0, 1.0};
    E = detail::quotient(E, f);
    M = detail::quotient(M, f);
  }
  const detail::Minimum mn = detail::minimum_ratio(E, M);
  // Scale for the tolerance: the largest finite |Ỹ(jω̃)| at the frequencies examined, and at least
  // 1, the ratio of the largest normalised coefficients (Y = g·Ỹ).
  double G = std::max(1.0, mn.magnitude);
  for (double w : {0.0, 1.0, std::sqrt(mn.x)}) {
    if (!std::isfinite(w)) continue;
    const double v = std::abs(detail::eval(N, cd(0, w)) / detail::eval(D, cd(0, w)));
    if (std::isfinite(v)) G = std::max(G, v);
  }
  if (dn <= dd) G = std::max(G, dn == dd ? std::abs(N.back() / D.back()) : 0.0);
  out.re_min = g * mn.value;
  out.omega_min = std::isinf(mn.x) ? mn.x : wc * std::sqrt(mn.x);
  if (mn.value < -rel_tol * G) {
    out.reason = fmt::format("Re Y(jω) = {:.4g} < 0 at ω = {:.6g} rad/s", out.re_min, out.omega_min);
    return out;
  }
  out.positive_real = true;
  return out;
}

bool biquadratic_positive_real(double a0, double a1, double a2, double d0, double d1, double d2) {
  const double c[] = {a0, a1, a2, d0, d1, d2};
  const char* names[] = {"a0", "a1", "a2", "d0", "d1", "d2"};
  for (int i = 0; i < 6; ++i)
    if (!(c[i] >= 0 && std::isfinite(c[i])))
      throw InvalidArgument("biquadratic_positive_real", names[i], fmt::format("must be finite and >= 0, got {}", c[i]));
  if (a0 == 0 && a1 == 0 && a2 == 0) throw InvalidArgument("biquadratic_positive_real", "a", "all numerator coefficients are zero");
  if (d0 == 0 && d1 == 0 && d2 == 0) throw InvalidArgument("biquadratic_positive_real", "d", "all denominator coefficients are zero");
  // Nonnegative quadratics have no roots in Re s > 0; Re Y(jω) ≥ 0 is E(x) = a2 d2 x² −
  // (a2 d0 + a0 d2 − a1 d1) x + a0 d0 ≥ 0 on x ≥ 0, i.e. a1 d1 − a2 d0 − a0 d2 ≥ −2√(a2 d2 a0 d0)
  // (Van Valkenburg, Introduction to Modern Network Synthesis, the biquadratic PR condition);
  // it also covers the jω-axis and degree conditions for nonnegative coefficients.
  const double t = std::sqrt(a2 * d0) - std::sqrt(a0 * d2);
  return t * t <= a1 * d1;
}

}  // namespace inerta::network
