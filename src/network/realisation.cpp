#include "inerta/network/realisation.hpp"

#include <algorithm>
#include <cmath>

namespace inerta::network {

namespace {

Poly mul(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
Poly add(const Poly& a, const Poly& b) {
  Poly r(std::max(a.size(), b.size()), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
  return r;
}
void trim(Poly& p) {
  while (p.size() > 1 && p.back() == 0.0) p.pop_back();
}
std::complex<double> eval(const Poly& p, std::complex<double> s) {
  std::complex<double> v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * s + p[i];
  return v;
}

}  // namespace

std::complex<double> Rational::operator()(std::complex<double> s) const { return eval(num, s) / eval(den, s); }

Rational rational_admittance(const Network& net) {
  using K = Network::Kind;
  switch (net.kind) {
    case K::Spring: return {{net.value}, {0.0, 1.0}};  // k/s
    case K::Damper: return {{net.value}, {1.0}};       // c
    case K::Inerter: return {{0.0, net.value}, {1.0}}; // b s
    case K::Admittance: return {net.num, net.den};
    case K::Parallel:
    case K::Series: {
      Rational acc = rational_admittance(net.children.front());
      for (std::size_t i = 1; i < net.children.size(); ++i) {
        Rational r = rational_admittance(net.children[i]);
        if (net.kind == K::Parallel) acc = {add(mul(acc.num, r.den), mul(r.num, acc.den)), mul(acc.den, r.den)};
        else acc = {mul(acc.num, r.num), add(mul(acc.den, r.num), mul(r.den, acc.num))};  // 1/Y = Σ 1/Y_i
        // Common factors s (exact zeros of the lowest coefficients) cancel.
        while (acc.num.size() > 1 && acc.den.size() > 1 && acc.num[0] == 0.0 && acc.den[0] == 0.0) {
          acc.num.erase(acc.num.begin());
          acc.den.erase(acc.den.begin());
        }
        trim(acc.num);
        trim(acc.den);
      }
      return acc;
    }
    case K::Open:
    case K::Rigid: break;
  }
  throw NetworkError("an open or rigid network has no finite admittance", 0);
}

std::complex<double> Realisation::dynamic_stiffness(std::complex<double> s) const {
  std::complex<double> g = d0 + d1 * s + d2 * s * s;
  if (n_states() > 0) {
    const int n = n_states();
    Eigen::MatrixXcd M = s * Eigen::MatrixXcd::Identity(n, n) - A.cast<std::complex<double>>();
    Eigen::VectorXcd x = M.partialPivLu().solve(B.cast<std::complex<double>>());
    g += C.cast<std::complex<double>>().dot(x);  // dot conjugates the first argument; C is real
  }
  return g;
}

double Realisation::static_stiffness() const {
  return n_states() ? d0 + C.dot(steady_state(1.0)) : d0;
}

Eigen::VectorXd Realisation::steady_state(double u) const {
  if (n_states() == 0) return {};
  return -A.partialPivLu().solve(B * u);
}

Realisation realise(const Network& net) {
  // G(s) = s Y(s) = s P / Q, with common factors s cancelled.
  Rational y = rational_admittance(net);
  Poly N = mul({0.0, 1.0}, y.num), D = y.den;
  while (N.size() > 1 && D.size() > 1 && N[0] == 0.0 && D[0] == 0.0) {
    N.erase(N.begin());
    D.erase(D.begin());
  }
  trim(N);
  trim(D);
  // Monic denominator.
  const double lead = D.back();
  for (double& v : N) v /= lead;
  for (double& v : D) v /= lead;
  const int n = static_cast<int>(D.size()) - 1;
  if (static_cast<int>(N.size()) - 1 > n + 2) throw NetworkError("network admittance of unexpected degree", 0);
  // Polynomial division N = q D + r, deg q ≤ 2, deg r < n.
  Poly r = N, q(3, 0.0);
  for (int k = static_cast<int>(r.size()) - 1; k >= n; --k) {
    double c = r[static_cast<std::size_t>(k)];
    q[static_cast<std::size_t>(k - n)] = c;
    for (int j = 0; j <= n; ++j) r[static_cast<std::size_t>(k - n + j)] -= c * D[static_cast<std::size_t>(j)];
  }
  r.resize(static_cast<std::size_t>(n), 0.0);
  Realisation R;
  R.d0 = q[0], R.d1 = q[1], R.d2 = q[2];
  R.A = Eigen::MatrixXd::Zero(n, n);
  R.B = Eigen::VectorXd::Zero(n);
  R.C = Eigen::VectorXd::Zero(n);
  if (n == 0) return R;
  // Controllable canonical form: ẋ_i = x_{i+1}, ẋ_n = −Σ a_j x_{j+1} + u, r/D = Σ r_j x_{j+1} ...
  // scaled by x = T x̃, T = diag(ω0^i / a0), ω0 = |a0|^(1/n), so that x̃_1 = a0 x_1 → u at steady state.
  const double a0 = D[0];
  const double w0 = std::pow(std::abs(a0), 1.0 / n);
  Eigen::VectorXd T(n);
  for (int i = 0; i < n; ++i) T[i] = std::pow(w0, i) / a0;
  for (int i = 0; i + 1 < n; ++i) R.A(i, i + 1) = T[i + 1] / T[i];
  for (int j = 0; j < n; ++j) R.A(n - 1, j) = -D[static_cast<std::size_t>(j)] * T[j] / T[n - 1];
  R.B[n - 1] = 1.0 / T[n - 1];
  for (int j = 0; j < n; ++j) R.C[j] = r[static_cast<std::size_t>(j)] * T[j];
  return R;
}

}  // namespace inerta::network
