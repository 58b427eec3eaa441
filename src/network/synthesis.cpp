#include "inerta/network/synthesis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

#include "inerta/network/enumeration.hpp"
#include "inerta/network/positive_real.hpp"
#include "polynomial.hpp"

namespace inerta::network {

namespace {
using detail::cd;
using K = Network::Kind;

// Immittance F = n/d of a sub-network: its admittance (Y mode: terms add in parallel) or its
// impedance (Z mode: terms add in series). Force–current analogy: spring ↔ inductor 1/k,
// damper ↔ conductance c, inerter ↔ capacitor b (Smith, "Synthesis of mechanical networks: the
// inerter", IEEE TAC 2002).
enum class Mode { Y, Z };
Mode dual(Mode m) { return m == Mode::Y ? Mode::Z : Mode::Y; }
K join(Mode m) { return m == Mode::Y ? K::Parallel : K::Series; }

struct Fn {
  Poly n, d;
};

constexpr double kTrim = 1e-13;    // leading coefficients below this (relative) are rounding
constexpr double kZeroRoot = 1e-10;  // |p0/p1| below this is a root at s = 0
constexpr double kAxis = 1e-8;     // |Re s| ≤ kAxis·|s|: a root on the jω axis
constexpr double kCancel = 1e-6;   // common roots of n and d closer than this cancel

Network leaf(K kind, double v) {
  Network n;
  n.kind = kind;
  n.value = v;
  n.name = std::string(kind == K::Spring ? "k" : kind == K::Damper ? "c" : "b");  // (GCC 12 -Wrestrict false positive on const char*)
  return n;
}

Network group(K kind, std::vector<Network> members) {
  if (members.size() == 1) return std::move(members.front());
  Network n;
  n.kind = kind;
  n.children = std::move(members);
  return n;
}

// The element whose immittance in mode m is α·s^p (p = −1, 0, 1).
Network element(Mode m, int p, double alpha) {
  if (!(alpha > 0) || !std::isfinite(alpha) || !std::isfinite(1 / alpha))
    throw NetworkError(fmt::format("synthesise: an element of immittance {:g}·s^{} came out non-positive or "
                                   "non-finite (numerical failure)",
                                   alpha, p),
                       0);
  if (m == Mode::Y) return leaf(p < 0 ? K::Spring : p == 0 ? K::Damper : K::Inerter, alpha);
  return leaf(p < 0 ? K::Inerter : p == 0 ? K::Damper : K::Spring, 1 / alpha);
}

// The Foster term A·s/(s² + ω0²) in mode m: its reciprocal s/A + ω0²/(A s) is a sum in the dual
// mode (Y mode: spring A in series with inerter A/ω0²; Z mode: inerter 1/A ∥ spring ω0²/A).
Network resonator(Mode m, double A, double w0) {
  const Mode o = dual(m);
  return group(join(o), {element(o, 1, 1 / A), element(o, -1, w0 * w0 / A)});
}

void clean_zero_root(Poly& p) {
  if (p.size() >= 2 && p[1] != 0.0 && std::abs(p[0]) <= kZeroRoot * std::abs(p[1])) p[0] = 0.0;
}

void normalise(Fn& f) {
  f.n = detail::trimmed(f.n, kTrim);
  f.d = detail::trimmed(f.d, kTrim);
  clean_zero_root(f.n);
  clean_zero_root(f.d);
  detail::cancel_common(f.n, f.d, kCancel);
  const double s = detail::max_abs(f.d);
  f.n = detail::scaled(f.n, 1 / s);
  f.d = detail::scaled(f.d, 1 / s);
}

bool has_axis_root(const Poly& p) {
  for (cd r : detail::roots(p))
    if (std::abs(r.real()) <= kAxis * std::abs(r)) return true;
  return false;
}

class Synthesiser {
 public:
  bool bott_duffin_used = false;

  // A network realising F in mode m (Guillemin, Synthesis of Passive Networks, chs. 5 and 9).
  Network build(Fn f, Mode m, int depth) {
    if (depth > 64) throw NetworkError("synthesise: recursion too deep (numerical failure)", 0);
    normalise(f);
    Poly& n = f.n;
    Poly& d = f.d;
    std::vector<Network> terms;
    const double ref = detail::max_abs(n);
    auto done = [&] {
      if (terms.empty()) throw NetworkError("synthesise: a sub-network came out empty (numerical failure)", 0);
      return group(join(m), std::move(terms));
    };
    // Foster: remove the jω-axis poles (s = ∞, s = 0, ±jω0), each a reactive element or pair.
    for (;;) {
      n = detail::trimmed(n, kTrim);
      if (detail::max_abs(n) <= 1e-11 * ref) return done();
      const int dn = detail::degree(n), dd = detail::degree(d);
      if (dn == dd + 1) {  // α s
        const double alpha = n[static_cast<std::size_t>(dn)] / d[static_cast<std::size_t>(dd)];
        terms.push_back(element(m, 1, alpha));
        n = detail::add(n, detail::mul({0.0, 1.0}, d), -alpha);
        n.resize(static_cast<std::size_t>(dn));
        continue;
      }
      if (dd >= 1 && d[0] == 0.0) {  // ρ/s: F − ρ/s = (n − ρ q)/(s q), d = s q
        const Poly q(d.begin() + 1, d.end());
        const double rho = n[0] / q[0];
        terms.push_back(element(m, -1, rho));
        Poly t = detail::add(n, q, -rho);
        n.assign(t.begin() + 1, t.end());
        d = q;
        continue;
      }
      bool removed = false;
      for (cd r : detail::roots(d)) {
        if (r.imag() <= 0 || std::abs(r.real()) > kAxis * std::abs(r)) continue;
        const double w0 = std::abs(detail::polish(d, cd(0, r.imag())).imag());
        const Poly f2{w0 * w0, 0.0, 1.0};
        const Poly q = detail::quotient(d, f2);
        const cd jw(0, w0);
        const double A = (detail::eval(n, jw) / (jw * detail::eval(q, jw))).real();  // 2 × residue
        terms.push_back(resonator(m, A, w0));
        n = detail::quotient(detail::add(n, detail::mul({0.0, A}, q), -1.0), f2);
        d = q;
        removed = true;
        break;
      }
      if (!removed) break;
    }
    clean_zero_root(n);
    // jω-axis zeros of F are poles of 1/F: continue in the dual mode.
    if (detail::degree(d) == detail::degree(n) + 1 || n[0] == 0.0 || has_axis_root(n)) {
      terms.push_back(build({d, n}, dual(m), depth + 1));
      return done();
    }
    // No jω-axis poles or zeros: remove min Re F(jω) as a damper (Brune's first step).
    const detail::Minimum mn = detail::minimum_ratio(detail::even_part(n, d), detail::even_part(d, d));
    const bool at_inf = std::isinf(mn.x);
    const double w1 = at_inf ? mn.x : std::sqrt(mn.x);
    const cd F1 = at_inf ? cd(n.back() / d.back()) : detail::eval(n, cd(0, w1)) / detail::eval(d, cd(0, w1));
    double scale = std::max({mn.magnitude, std::abs(F1), std::abs(n[0] / d[0]), std::abs(n.back() / d.back())});
    if (mn.value < -1e-8 * scale)
      throw NetworkError(fmt::format("synthesise: Re F(jω) = {:g} < 0 at an intermediate step (numerical failure)",
                                     mn.value),
                         0);
    const double before = detail::max_abs(n);
    if (mn.value > 1e-12 * scale) {
      terms.push_back(element(m, 0, mn.value));
      n = detail::add(n, d, -mn.value);
    }
    if (detail::max_abs(n) <= 1e-10 * before) return done();  // F was a constant
    if (mn.x == 0) {
      n[0] = 0.0;  // zero at s = 0
    } else if (at_inf) {
      n.resize(static_cast<std::size_t>(detail::degree(d)));  // zero at s = ∞
    } else if (std::abs(F1.imag()) > 1e-8 * scale) {
      terms.push_back(bott_duffin({n, d}, m, w1, F1.imag(), depth + 1));
      return done();
    }  // else F(jω1) = 0: a pair of jω-axis zeros
    terms.push_back(build({d, n}, dual(m), depth + 1));
    return done();
  }

 private:
  // F a minimum function, F(jω1) = jX, X > 0. Richards' theorem: for k > 0 with F(k)/k = X/ω1,
  // R = (k F − s F(k))/(k F(k) − s F) is PR with R(jω1) = 0, and F = F(k)(kR + s)/(k + sR) =
  // [F(k)R ⊕' k F(k)/s] ⊕ [F(k)/R ⊕' s F(k)/k], ⊕ the sum of the mode, ⊕' of the dual
  // (Bott & Duffin 1949; Guillemin, Synthesis of Passive Networks, §9.6). X < 0: the same on 1/F.
  Network bott_duffin(Fn f, Mode m, double w1, double X, int depth) {
    if (X < 0) return bott_duffin({f.d, f.n}, dual(m), w1, 1 / std::abs(X), depth);
    bott_duffin_used = true;
    const Poly& n = f.n;
    const Poly& d = f.d;
    const double L = X / w1;
    auto h = [&](double k) { return detail::eval(n, k) / detail::eval(d, k) / k - L; };
    // F(k)/k falls from +∞ (k → 0) to 0 (k → ∞): bracket a root in log k, then bisect.
    double lo = w1, hi = w1;
    int guard = 0;
    if (h(w1) > 0) {
      while (h(hi) > 0 && ++guard < 400) hi *= 2;
      lo = hi / 2;
    } else {
      while (h(lo) <= 0 && ++guard < 400) lo /= 2;
      hi = lo * 2;
    }
    for (int it = 0; it < 200 && hi / lo - 1 > 1e-16; ++it) {
      const double mid = std::sqrt(lo * hi);
      (h(mid) > 0 ? lo : hi) = mid;
    }
    const double k = std::sqrt(lo * hi);
    const double Fk = detail::eval(n, k) / detail::eval(d, k);
    const Poly sk{-k, 1.0};  // the common factor (s − k)
    const Poly Rn = detail::quotient(detail::add(detail::scaled(n, k), detail::mul({0.0, Fk}, d), -1.0), sk);
    const Poly Rd = detail::quotient(detail::add(detail::scaled(d, k * Fk), detail::mul({0.0, 1.0}, n), -1.0), sk);
    const Mode o = dual(m);
    Network b1 = group(join(o), {build({detail::scaled(Rn, Fk), Rd}, m, depth + 1), element(m, -1, k * Fk)});
    Network b2 = group(join(o), {build({detail::scaled(Rd, Fk), Rn}, m, depth + 1), element(m, 1, Fk / k)});
    return group(join(m), {std::move(b1), std::move(b2)});
  }
};

void unscale(Network& net, double g, double wc) {
  if (net.kind == K::Spring) net.value *= g * wc;
  if (net.kind == K::Damper) net.value *= g;
  if (net.kind == K::Inerter) net.value *= g / wc;
  for (auto& c : net.children) unscale(c, g, wc);
}

void number(Network& net, std::map<char, int>& next) {
  if (net.is_element()) {
    const char t = net.kind == K::Spring ? 'k' : net.kind == K::Damper ? 'c' : 'b';
    net.name = fmt::format("{}{}", t, ++next[t]);
  }
  for (auto& c : net.children) number(c, next);
}
}  // namespace

Synthesis synthesise(const Rational& y) {
  const PrTest pr = positive_real(y);
  if (!pr.positive_real) throw NetworkError("synthesise: the admittance is not positive real: " + pr.reason, 0);
  Poly N = detail::trimmed(y.num), D = detail::trimmed(y.den);
  while (N.size() > 1 && D.size() > 1 && N[0] == 0.0 && D[0] == 0.0) N.erase(N.begin()), D.erase(D.begin());
  // Y(s) = g·Ỹ(s/wc): synthesise Ỹ, then springs scale by g·wc, dampers by g, inerters by g/wc.
  const double wc = detail::characteristic_frequency(N, D);
  for (std::size_t i = 0; i < N.size(); ++i) N[i] *= std::pow(wc, static_cast<double>(i));
  for (std::size_t i = 0; i < D.size(); ++i) D[i] *= std::pow(wc, static_cast<double>(i));
  const double gn = detail::max_abs(N), gd = detail::max_abs(D);
  N = detail::scaled(N, 1 / gn);
  D = detail::scaled(D, 1 / gd);
  clean_zero_root(N);
  clean_zero_root(D);
  detail::cancel_common(N, D, kCancel);
  Synthesis out;
  out.degree = std::max(detail::degree(detail::trimmed(N, kTrim)), detail::degree(detail::trimmed(D, kTrim)));
  Synthesiser s;
  Network net = s.build({N, D}, Mode::Y, 0);
  unscale(net, gn / gd, wc);
  // Same-type elements directly in series or parallel merge; nested groups flatten.
  net = canonical(net);
  std::map<char, int> next;
  number(net, next);
  const ElementCounts c = count_elements(net);
  out.network = std::move(net);
  out.elements = c.elements;
  out.reactive = c.springs + c.inerters;
  out.bott_duffin = s.bott_duffin_used;
  out.minimal_reactive = out.reactive == out.degree;
  out.method = out.bott_duffin ? "Bott–Duffin" : "Foster/ladder";
  return out;
}

}  // namespace inerta::network
