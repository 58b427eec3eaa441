#pragma once
// C²-smooth cubic spline through tabulated points (x_i, y_i), x strictly increasing, with either
// natural ends (s″ = 0 at both ends) or periodic ends (s, s′, s″ equal at both ends; needs
// y_0 = y_n). The second derivatives M_i solve the usual tridiagonal (cyclic for periodic) system
//   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (Δ_i − Δ_{i−1}),  Δ_i = (y_{i+1} − y_i)/h_i,
// solved once (sparse LDLᵀ). Evaluation is O(log n). Outside [x_0, x_n]: periodic splines wrap,
// natural ones continue with the end value and end slope (linear extrapolation).
#include <vector>

namespace inerta::numerics {

class CubicSpline {
 public:
  enum class Ends { Natural, Periodic };
  /// InvalidArgument for fewer than 2 points, non-increasing or non-finite x, non-finite y, or a
  /// periodic table whose last value differs from the first.
  CubicSpline(std::vector<double> x, std::vector<double> y, Ends ends = Ends::Natural);

  double value(double x) const;
  double slope(double x) const;      ///< ds/dx
  double curvature(double x) const;  ///< d²s/dx²
  double x_min() const { return x_.front(); }
  double x_max() const { return x_.back(); }
  Ends ends() const { return ends_; }
  /// Mean value over [x_0, x_n] (exact integral of the spline / length).
  double mean() const;

 private:
  struct Local {
    int i;
    double u;   ///< x − x_i within the segment
    double dx;  ///< beyond the ends (natural): distance outside, signed; 0 inside
  };
  Local locate(double x) const;
  std::vector<double> x_, y_, M_;
  Ends ends_;
};

}  // namespace inerta::numerics
