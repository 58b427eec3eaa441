#include "inerta/numerics/cubic_spline.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "inerta/error.hpp"

namespace inerta::numerics {

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y, Ends ends)
    : x_(std::move(x)), y_(std::move(y)), ends_(ends) {
  const std::size_t n = x_.size();
  if (n < 2 || y_.size() != n)
    throw InvalidArgument("cubic spline: needs at least 2 points and as many values as abscissae");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw InvalidArgument("cubic spline: point " + std::to_string(i + 1) + " is not a finite number");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw InvalidArgument("cubic spline: x must increase strictly (point " + std::to_string(i + 1) + ")");
  }
  if (ends_ == Ends::Periodic && std::abs(y_.back() - y_.front()) > 1e-12 * (1 + std::abs(y_.front())))
    throw InvalidArgument("cubic spline: a periodic table must end with its first value");
  M_.assign(n, 0.0);
  const int segs = static_cast<int>(n) - 1;
  std::vector<double> hs(static_cast<std::size_t>(segs)), d(static_cast<std::size_t>(segs));
  for (int i = 0; i < segs; ++i) {
    hs[static_cast<std::size_t>(i)] = x_[static_cast<std::size_t>(i + 1)] - x_[static_cast<std::size_t>(i)];
    d[static_cast<std::size_t>(i)] = (y_[static_cast<std::size_t>(i + 1)] - y_[static_cast<std::size_t>(i)]) /
                                     hs[static_cast<std::size_t>(i)];
  }
  // Unknowns: natural M_1..M_{n−2} (M_0 = M_{n−1} = 0); periodic M_0..M_{n−2} (M_{n−1} = M_0).
  const bool periodic = ends_ == Ends::Periodic;
  const int first = periodic ? 0 : 1, m = periodic ? segs : segs - 1;
  if (m <= 0 || (periodic && segs < 2)) return;  // a line: M = 0
  std::vector<Eigen::Triplet<double>> T;
  Eigen::VectorXd rhs(m);
  for (int r = 0; r < m; ++r) {
    const int i = r + first;                    // node
    const int im = (i - 1 + segs) % segs;       // previous segment (wraps when periodic)
    const double hl = hs[static_cast<std::size_t>(periodic ? im : i - 1)], hr = hs[static_cast<std::size_t>(i % segs)];
    const double dl = d[static_cast<std::size_t>(periodic ? im : i - 1)], dr = d[static_cast<std::size_t>(i % segs)];
    T.emplace_back(r, r, 2 * (hl + hr));
    const int left = periodic ? (r - 1 + m) % m : r - 1, right = periodic ? (r + 1) % m : r + 1;
    if (left >= 0 && left != r) T.emplace_back(r, left, hl);
    if (right < m && right != r) T.emplace_back(r, right, hr);
    rhs[r] = 6 * (dr - dl);
  }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(T.begin(), T.end());  // duplicates (m = 2, periodic) are summed
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
  if (ldlt.info() != Eigen::Success) throw NumericalError("cubic spline: the spline system could not be factorised");
  const Eigen::VectorXd sol = ldlt.solve(rhs);
  for (int r = 0; r < m; ++r) M_[static_cast<std::size_t>(r + first)] = sol[r];
  if (periodic) M_.back() = M_.front();
}

CubicSpline::Local CubicSpline::locate(double x) const {
  const double a = x_.front(), b = x_.back();
  double dx = 0;
  if (ends_ == Ends::Periodic) {
    x = a + std::fmod(x - a, b - a);
    if (x < a) x += b - a;
  } else if (x < a) {
    dx = x - a, x = a;
  } else if (x > b) {
    dx = x - b, x = b;
  }
  auto it = std::upper_bound(x_.begin(), x_.end(), x);
  int i = static_cast<int>(it - x_.begin()) - 1;
  i = std::clamp(i, 0, static_cast<int>(x_.size()) - 2);
  return {i, x - x_[static_cast<std::size_t>(i)], dx};
}

// On segment i with h = x_{i+1} − x_i, u = x − x_i, w = h − u:
//   s = M_i w³/(6h) + M_{i+1} u³/(6h) + (y_i/h − M_i h/6) w + (y_{i+1}/h − M_{i+1} h/6) u
double CubicSpline::value(double x) const {
  const Local l = locate(x);
  const auto i = static_cast<std::size_t>(l.i);
  const double h = x_[i + 1] - x_[i], u = l.u, w = h - u;
  const double s = M_[i] * w * w * w / (6 * h) + M_[i + 1] * u * u * u / (6 * h) + (y_[i] / h - M_[i] * h / 6) * w +
                   (y_[i + 1] / h - M_[i + 1] * h / 6) * u;
  return l.dx == 0 ? s : s + l.dx * slope(x - l.dx);
}

double CubicSpline::slope(double x) const {
  const Local l = locate(x);
  const auto i = static_cast<std::size_t>(l.i);
  const double h = x_[i + 1] - x_[i], u = l.u, w = h - u;
  return -M_[i] * w * w / (2 * h) + M_[i + 1] * u * u / (2 * h) - (y_[i] / h - M_[i] * h / 6) +
         (y_[i + 1] / h - M_[i + 1] * h / 6);
}

double CubicSpline::curvature(double x) const {
  const Local l = locate(x);
  if (l.dx != 0) return 0.0;
  const auto i = static_cast<std::size_t>(l.i);
  const double h = x_[i + 1] - x_[i];
  return (M_[i] * (h - l.u) + M_[i + 1] * l.u) / h;
}

double CubicSpline::mean() const {
  // ∫ over a segment = h (y_i + y_{i+1})/2 − h³ (M_i + M_{i+1})/24.
  double I = 0;
  for (std::size_t i = 0; i + 1 < x_.size(); ++i) {
    const double h = x_[i + 1] - x_[i];
    I += h * (y_[i] + y_[i + 1]) / 2 - h * h * h * (M_[i] + M_[i + 1]) / 24;
  }
  return I / (x_.back() - x_.front());
}

}  // namespace inerta::numerics
