#include "inerta/analysis/identification.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "inerta/error.hpp"

namespace inerta::analysis {

using cd = std::complex<double>;
using std::numbers::pi;

namespace {

// Least squares A p = b with the columns scaled to unit norm first (eq. 4.19's columns differ by ω).
Eigen::VectorXd least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  Eigen::VectorXd scale = A.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (!(scale[j] > 0)) scale[j] = 1;
  Eigen::VectorXd p = (A * scale.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(b);
  return p.cwiseQuotient(scale);
}

// The two rows of eq. 4.19 at one frequency: A [c2; k2] = b.
void head_rows(double m_H, double f, cd H, cd E, Eigen::Ref<Eigen::Matrix2d> A, Eigen::Ref<Eigen::Vector2d> b) {
  const double w = 2 * pi * f, aH = H.real(), bH = H.imag(), aE = E.real(), bE = E.imag();
  A << (bH - bE) / w, (aE - aH) / (w * w), (aE - aH) / w, (bE - bH) / (w * w);
  b << -(m_H * aH + 1), -m_H * bH;
}

}  // namespace

HeadSuspensionPoint head_suspension_at(double m_H, double f, cd H, cd E) {
  if (!(f > 0)) throw ModelError(fmt::format("eq. 4.19 needs f > 0, got {:g} Hz", f));
  Eigen::Matrix2d A;
  Eigen::Vector2d b;
  head_rows(m_H, f, H, E, A, b);
  const Eigen::Vector2d p = A.fullPivLu().solve(b);
  return {f, p[1], p[0]};
}

HeadSuspensionFit fit_head_suspension(double m_H, const std::vector<double>& f, const std::vector<cd>& H,
                                      const std::vector<cd>& E, double f_lo, double f_hi) {
  if (H.size() != f.size() || E.size() != f.size())
    throw ModelError("head suspension: FRF_H, FRF_E and the frequencies differ in length");
  if (!(m_H > 0)) throw ModelError(fmt::format("head suspension: the head mass must be > 0 kg, got {:g}", m_H));
  HeadSuspensionFit fit;
  fit.f_lo = f_lo, fit.f_hi = f_hi;
  std::vector<std::size_t> band;
  for (std::size_t k = 0; k < f.size(); ++k) {
    fit.per_frequency.push_back(head_suspension_at(m_H, f[k], H[k], E[k]));
    if (f[k] >= f_lo && f[k] <= f_hi) band.push_back(k);
  }
  if (band.empty())
    throw ModelError(fmt::format("head suspension: no frequency in the band {:g}–{:g} Hz (data cover {:g}–{:g} Hz)",
                                 f_lo, f_hi, f.empty() ? 0.0 : *std::min_element(f.begin(), f.end()),
                                 f.empty() ? 0.0 : *std::max_element(f.begin(), f.end())));
  // Eq. 4.20: both equations of every frequency in the band, in least squares.
  const Eigen::Index n = static_cast<Eigen::Index>(band.size());
  Eigen::MatrixXd A(2 * n, 2);
  Eigen::VectorXd b(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t k = band[static_cast<std::size_t>(i)];
    head_rows(m_H, f[k], H[k], E[k], A.middleRows<2>(2 * i), b.segment<2>(2 * i));
  }
  const Eigen::VectorXd p = least_squares(A, b);
  fit.c2 = p[0], fit.k2 = p[1];
  fit.points = static_cast<int>(n);
  fit.rms_residual = std::sqrt((A * p - b).squaredNorm() / static_cast<double>(2 * n));
  return fit;
}

double frf_misfit(const Frf& model, const Frf& measured) {
  if (model.outputs != measured.outputs || model.f.size() != measured.f.size())
    throw ModelError("FRF fit: model and measured FRFs differ in outputs or frequencies");
  double J = 0;
  for (std::size_t i = 0; i < measured.H.size(); ++i)
    for (std::size_t k = 0; k < measured.f.size(); ++k) J += std::norm(model.H[i][k] - measured.H[i][k]);  // eq. 6.47
  return J;
}

Frf frf_band(const Frf& frf, double f_lo, double f_hi) {
  Frf out;
  out.outputs = frf.outputs;
  out.H.resize(frf.H.size());
  for (std::size_t k = 0; k < frf.f.size(); ++k) {
    if (frf.f[k] < f_lo || frf.f[k] > f_hi) continue;
    out.f.push_back(frf.f[k]);
    for (std::size_t i = 0; i < frf.H.size(); ++i) out.H[i].push_back(frf.H[i][k]);
  }
  if (out.f.empty())
    throw ModelError(fmt::format("FRF fit: no measured frequency in the band {:g}–{:g} Hz (data cover {:g}–{:g} Hz)",
                                 f_lo, f_hi, frf.f.empty() ? 0.0 : *std::min_element(frf.f.begin(), frf.f.end()),
                                 frf.f.empty() ? 0.0 : *std::max_element(frf.f.begin(), frf.f.end())));
  return out;
}

FrfFit fit_frf(const ModelOf& model_of, const std::vector<numerics::Variable>& vars, const Frf& measured,
               const numerics::Options& options) {
  if (vars.empty()) throw ModelError("FRF fit: no parameter to fit");
  // The box centre (the first start) is evaluated outside the search so that input errors surface.
  std::vector<double> centre;
  for (const auto& v : vars) centre.push_back(std::sqrt(v.lo * v.hi));
  FrfFit fit;
  fit.initial_cost = frf_misfit(frf_linear(model_of(centre), measured.outputs, measured.f), measured);
  auto cost = [&](const std::vector<double>& values) {
    try {
      return frf_misfit(frf_linear(model_of(values), measured.outputs, measured.f), measured);
    } catch (const NumericalError&) {
      return double(INFINITY);  // e.g. no static equilibrium for these values
    }
  };
  const numerics::Result r = numerics::pattern_search(vars, cost, options);
  fit.values = r.values;
  fit.cost = r.cost;
  fit.evaluations = r.evaluations + 1;
  fit.fitted = frf_linear(model_of(r.values), measured.outputs, measured.f);
  return fit;
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw ModelError("line fit: x and y differ in length");
  if (x.size() < 2) throw ModelError(fmt::format("line fit: {} point(s); a line needs at least 2", x.size()));
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x[0]; }))
    throw ModelError(
        fmt::format("line fit: all {} points have x = {:g}; a line needs two different x", x.size(), x[0]));
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i)
    A(i, 0) = x[static_cast<std::size_t>(i)], A(i, 1) = 1, b[i] = y[static_cast<std::size_t>(i)];
  const Eigen::VectorXd p = least_squares(A, b);
  return {p[0], p[1], static_cast<int>(n), std::sqrt((A * p - b).squaredNorm() / static_cast<double>(n))};
}

ActuatorStaticFit fit_actuator_static(const std::vector<double>& v, const std::vector<double>& F) {
  if (v.size() != F.size()) throw ModelError("actuator static fit: velocity and force differ in length");
  std::vector<double> vf, Ff, vb, Fb;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] > 0) vf.push_back(v[k]), Ff.push_back(F[k]);
    if (v[k] < 0) vb.push_back(v[k]), Fb.push_back(F[k]);
  }
  auto distinct = [](const std::vector<double>& x) { return std::set<double>(x.begin(), x.end()).size(); };
  for (auto [name, x] : {std::pair{"forward (v > 0)", &vf}, std::pair{"backward (v < 0)", &vb}})
    if (distinct(*x) < 2)
      throw ModelError(
          fmt::format("actuator static fit: the {} stroke has {} distinct velocit{}; its line needs at least 2", name,
                      distinct(*x), distinct(*x) == 1 ? "y" : "ies"));
  ActuatorStaticFit r;
  r.forward = fit_line(vf, Ff);
  r.backward = fit_line(vb, Fb);
  r.F_c = 0.5 * (r.forward.intercept + r.backward.intercept);  // F_c + F_r and F_c − F_r
  r.F_r = 0.5 * (r.forward.intercept - r.backward.intercept);
  r.c1 = 0.5 * (r.forward.slope + r.backward.slope);
  return r;
}

cd maxwell_admittance(double k1, double c1, double f) { return 1.0 / (1.0 / c1 + cd(0, 2 * pi * f) / k1); }

cd harmonic_amplitude(const std::vector<double>& t, const std::vector<double>& y, double f) {
  const double w = 2 * pi * f;
  const Eigen::Index n = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double ti = t[static_cast<std::size_t>(i)];
    A(i, 0) = 1, A(i, 1) = std::cos(w * ti), A(i, 2) = std::sin(w * ti);
    b[i] = y[static_cast<std::size_t>(i)];
  }
  const Eigen::VectorXd p = A.colPivHouseholderQr().solve(b);
  return {p[1], -p[2]};  // y0 + a cos ωt + b sin ωt = y0 + Re((a − i b) e^{iωt})
}

double admittance_cost(double k1, double c1, const std::vector<AdmittancePoint>& points) {
  double J = 0;
  for (const auto& p : points) J += std::abs(maxwell_admittance(k1, c1, p.f) - p.Y_E) / std::abs(p.Y_E);  // eq. 5.25
  return J;
}

ActuatorDynamicFit fit_actuator_dynamic(const std::vector<DynamicTest>& tests, double c1, double piston_mass,
                                        double friction, bool fit_c1) {
  if (tests.empty()) throw ModelError("actuator dynamic fit: no test");
  if (!fit_c1 && !(c1 > 0 && std::isfinite(c1)))
    throw ModelError(fmt::format("actuator dynamic fit: c1 must be a finite number > 0 N·s/m, got {:g}", c1));
  if (!(piston_mass >= 0 && std::isfinite(piston_mass)))
    throw ModelError(fmt::format("actuator dynamic fit: piston mass must be a finite number >= 0 kg, got {:g}", piston_mass));
  if (!(friction >= 0 && std::isfinite(friction)))
    throw ModelError(fmt::format("actuator dynamic fit: friction must be a finite number >= 0 N, got {:g}", friction));
  ActuatorDynamicFit fit;
  for (const auto& T : tests) {
    const std::size_t n = T.t.size();
    if (T.x.size() != n || T.F.size() != n) throw ModelError("actuator dynamic fit: t, x and F differ in length");
    if (!(T.f > 0)) throw ModelError(fmt::format("actuator dynamic fit: frequency {:g} Hz; expected > 0", T.f));
    if (n < 8)
      throw ModelError(
          fmt::format("actuator dynamic fit: {:g} Hz: {} sample(s); the correlation needs at least 8", T.f, n));
    const auto [t0, t1] = std::minmax_element(T.t.begin(), T.t.end());
    if (*t1 - *t0 < 1 / T.f * (1 - 1e-9))
      throw ModelError(
          fmt::format("actuator dynamic fit: {:g} Hz: the samples span {:g} s, less than one period ({:g} s)", T.f,
                      *t1 - *t0, 1 / T.f));
    const double w = 2 * pi * T.f;
    const cd X = harmonic_amplitude(T.t, T.x, T.f);
    if (!(std::abs(X) > 0))
      throw ModelError(fmt::format("actuator dynamic fit: {:g} Hz: no displacement at this frequency", T.f));
    std::vector<double> F = T.F;
    if (friction != 0)
      for (std::size_t k = 0; k < n; ++k) {
        const double v = std::real(cd(0, w) * X * std::exp(cd(0, w * T.t[k])));
        F[k] -= friction * (v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0);
      }
    const cd Fd = harmonic_amplitude(T.t, F, T.f) + piston_mass * w * w * X;  // − m_p ẍ, ẍ = −ω² X
    fit.points.push_back({T.f, Fd / (cd(0, w) * X), std::abs(X)});
  }
  std::vector<numerics::Variable> vars{{"k1", 1e2, 1e9, false, false}};
  if (fit_c1) vars.push_back({"c1", 1e0, 1e8, false, false});
  numerics::Options o;
  o.starts = 3;
  o.min_step = 1e-7;
  o.max_evaluations = 20000;
  const numerics::Result r = numerics::pattern_search(
      vars, [&](const std::vector<double>& p) { return admittance_cost(p[0], fit_c1 ? p[1] : c1, fit.points); }, o);
  fit.k1 = r.values[0];
  fit.c1 = fit_c1 ? r.values[1] : c1;
  fit.cost = r.cost;
  return fit;
}

}  // namespace inerta::analysis
