#include "polynomial.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace inerta::network::detail {

int degree(const Poly& p) {
  for (int i = static_cast<int>(p.size()) - 1; i >= 0; --i)
    if (p[static_cast<std::size_t>(i)] != 0.0) return i;
  return -1;
}

double max_abs(const Poly& p) {
  double m = 0;
  for (double c : p) m = std::max(m, std::abs(c));
  return m;
}

Poly trimmed(Poly p, double rel) {
  const double lim = rel * max_abs(p);
  while (p.size() > 1 && std::abs(p.back()) <= lim) p.pop_back();
  if (p.empty()) p.push_back(0.0);
  return p;
}

Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {0.0};
  Poly r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

Poly add(const Poly& a, const Poly& b, double beta) {
  Poly r(std::max(a.size(), b.size()), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += beta * b[i];
  return r;
}

Poly scaled(Poly p, double f) {
  for (double& c : p) c *= f;
  return p;
}

Poly derivative(const Poly& p) {
  if (p.size() <= 1) return {0.0};
  Poly r(p.size() - 1);
  for (std::size_t i = 1; i < p.size(); ++i) r[i - 1] = static_cast<double>(i) * p[i];
  return r;
}

double eval(const Poly& p, double x) {
  double v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + p[i];
  return v;
}

cd eval(const Poly& p, cd s) {
  cd v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * s + p[i];
  return v;
}

Poly quotient(const Poly& p, const Poly& d) {
  const Poly dd = trimmed(d);
  const int n = degree(p), m = degree(dd);
  if (m < 0) return {0.0};
  if (n < m) return {0.0};
  Poly r(p.begin(), p.begin() + n + 1), q(static_cast<std::size_t>(n - m + 1), 0.0);
  for (int k = n - m; k >= 0; --k) {
    const double c = r[static_cast<std::size_t>(k + m)] / dd[static_cast<std::size_t>(m)];
    q[static_cast<std::size_t>(k)] = c;
    for (int j = 0; j <= m; ++j) r[static_cast<std::size_t>(k + j)] -= c * dd[static_cast<std::size_t>(j)];
  }
  return q;
}

cd polish(const Poly& p, cd s) {
  const Poly dp = derivative(p);
  for (int it = 0; it < 4; ++it) {
    const cd v = eval(p, s), dv = eval(dp, s);
    if (dv == 0.0) break;
    const cd next = s - v / dv;
    if (!(std::abs(eval(p, next)) < std::abs(v))) break;
    s = next;
  }
  return s;
}

std::vector<cd> roots(const Poly& p0) {
  Poly p = trimmed(p0);
  std::vector<cd> out;
  std::size_t low = 0;
  while (low + 1 < p.size() && p[low] == 0.0) ++low;
  for (std::size_t i = 0; i < low; ++i) out.emplace_back(0.0, 0.0);
  Poly q(p.begin() + static_cast<std::ptrdiff_t>(low), p.end());
  const int n = degree(q);
  if (n <= 0) return out;
  if (n == 1) {
    out.emplace_back(-q[0] / q[1], 0.0);
    return out;
  }
  // Companion matrix of the monic polynomial (Golub & Van Loan, Matrix Computations, §7.4.6).
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i < n; ++i) C(i, i - 1) = 1.0;
  for (int i = 0; i < n; ++i) C(i, n - 1) = -q[static_cast<std::size_t>(i)] / q[static_cast<std::size_t>(n)];
  Eigen::EigenSolver<Eigen::MatrixXd> es(C, false);
  for (int i = 0; i < n; ++i) {
    cd r = polish(q, es.eigenvalues()[i]);
    // Roots of a real polynomial: keep real ones real.
    if (std::abs(r.imag()) <= 1e-14 * std::abs(r)) r = {r.real(), 0.0};
    out.push_back(r);
  }
  return out;
}

Poly even_part(const Poly& a, const Poly& b) {
  const int na = static_cast<int>(a.size()) - 1, nb = static_cast<int>(b.size()) - 1;
  Poly E(static_cast<std::size_t>((na + nb) / 2 + 1), 0.0);
  for (int i = 0; i <= na; ++i)
    for (int j = 0; j <= nb; ++j) {
      if ((i + j) % 2) continue;
      const int h = (i - j) / 2;  // j^i·conj(j^j) = j^(i−j) = (−1)^((i−j)/2)
      const double sign = (h % 2 == 0) ? 1.0 : -1.0;
      E[static_cast<std::size_t>((i + j) / 2)] += sign * a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
    }
  return E;
}

Minimum minimum_ratio(const Poly& E0, const Poly& M0) {
  const Poly E = trimmed(E0), M = trimmed(M0);
  auto r = [&](double x) { return eval(E, x) / eval(M, x); };
  std::vector<double> xs{0.0};
  // Stationary points: roots of P = E'M − EM'. Evaluating r at extra points cannot hide a
  // negative value, so every root with a positive real part is a candidate.
  Poly P = add(mul(derivative(E), M), mul(E, derivative(M)), -1.0);
  P = trimmed(P, 1e-14);
  if (degree(P) > 0)
    for (cd z : roots(P)) {
      if (!(z.real() > 0)) continue;
      double x = z.real();
      if (std::abs(z.imag()) <= 1e-6 * std::abs(z)) {  // Newton polish of a real root
        const Poly dP = derivative(P);
        for (int it = 0; it < 3; ++it) {
          const double d = eval(dP, x);
          if (d == 0) break;
          const double nx = x - eval(P, x) / d;
          if (!(nx > 0) || !(std::abs(eval(P, nx)) < std::abs(eval(P, x)))) break;
          x = nx;
        }
      }
      xs.push_back(x);
    }
  Minimum m;
  m.value = r(0.0);
  m.x = 0.0;
  m.magnitude = std::abs(m.value);
  for (double x : xs) {
    const double v = r(x);
    m.magnitude = std::max(m.magnitude, std::abs(v));
    if (v < m.value) m.value = v, m.x = x;
  }
  // x → ∞: E_n/M_n if deg E = deg M (deg E ≤ deg M here), 0 if deg E < deg M.
  const int de = degree(E), dm = degree(M);
  double vinf = 0;
  if (de > dm) vinf = E.back() > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  else if (de == dm) vinf = E.back() / M.back();
  if (std::isfinite(vinf)) m.magnitude = std::max(m.magnitude, std::abs(vinf));
  if (vinf < m.value) m.value = vinf, m.x = std::numeric_limits<double>::infinity();
  return m;
}

double characteristic_frequency(const Poly& n, const Poly& d) {
  // Median of log|r| over the nonzero roots: robust to a stray root from a rounding-level
  // coefficient (a root at 1e-16 or 1e14).
  std::vector<double> logs;
  for (const Poly* p : {&n, &d})
    for (cd r : roots(*p))
      if (std::abs(r) > 0 && std::isfinite(std::abs(r))) logs.push_back(std::log(std::abs(r)));
  if (logs.empty()) return 1.0;
  std::sort(logs.begin(), logs.end());
  const std::size_t m = logs.size() / 2;
  return std::exp(logs.size() % 2 ? logs[m] : 0.5 * (logs[m - 1] + logs[m]));
}

void clean_rounding(Poly& p, double rel) {
  const double lim = rel * max_abs(p);
  while (p.size() > 1 && std::abs(p.back()) <= lim) p.pop_back();
  for (std::size_t i = 0; i + 1 < p.size() && std::abs(p[i]) <= lim && p[i] != 0.0; ++i) p[i] = 0.0;
}

void cancel_common(Poly& n, Poly& d, double tol) {
  for (int guard = 0; guard < 64; ++guard) {
    if (degree(n) < 1 || degree(d) < 1) return;
    const std::vector<cd> rn = roots(n), rd = roots(d);
    bool found = false;
    for (cd a : rn) {
      for (cd b : rd) {
        const double scale = std::max(std::abs(a), std::abs(b));
        if (std::abs(a - b) <= tol * scale || (std::abs(a) <= tol && std::abs(b) <= tol)) {
          const cd r = 0.5 * (a + b);
          Poly f;
          if (a == 0.0 && b == 0.0) f = {0.0, 1.0};
          else if (std::abs(r.imag()) <= tol * std::abs(r)) f = {-r.real(), 1.0};
          else f = {std::norm(r), -2 * r.real(), 1.0};
          n = quotient(n, f);
          d = quotient(d, f);
          found = true;
          break;
        }
      }
      if (found) break;
    }
    if (!found) return;
  }
}

}  // namespace inerta::network::detail
