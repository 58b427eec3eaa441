#pragma once
// Identification from measurements (spec/06 §6.4, spec/03 §3.3; docs/identification.md).
// Input problems (a band without data, too few points, ...) raise inerta::ModelError.
#include <complex>
#include <functional>
#include <vector>

#include "inerta/analysis/frf.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::analysis {

// ---- Head suspension k2 ‖ c2 from the head and upper-arm FRFs (eqs. 4.14–4.20) -------------------
// FRF_H = a_H + i b_H, FRF_E = a_E + i b_E: vertical accelerations (m/s²) of the head and of the
// upper-arm top per N of contact force (compression positive, pushing the head down), ω = 2πf:
//   real: m_H a_H + (b_H − b_E)/ω · c2 + (a_E − a_H)/ω² · k2 + 1 = 0
//   imag: m_H b_H + (a_E − a_H)/ω · c2 + (b_E − b_H)/ω² · k2 = 0                    (4.19)

struct HeadSuspensionPoint {
  double f = 0;   ///< Hz
  double k2 = 0;  ///< N/m, eq. 4.19 solved at this frequency alone
  double c2 = 0;  ///< N·s/m
};

/// Eq. 4.19 at one frequency (f > 0): the 2×2 real system solved for (c2, k2).
HeadSuspensionPoint head_suspension_at(double m_H, double f, std::complex<double> H, std::complex<double> E);

struct HeadSuspensionFit {
  double k2 = 0, c2 = 0;  ///< least squares over the band (eq. 4.20)
  int points = 0;         ///< frequencies in the band
  double f_lo = 0, f_hi = 0;
  double rms_residual = 0;                         ///< of the stacked eqs. 4.19 (dimensionless)
  std::vector<HeadSuspensionPoint> per_frequency;  ///< every frequency, in or out of the band
};

/// Eq. 4.19 at every frequency and eq. 4.20: both equations of every frequency in [f_lo, f_hi]
/// stacked and solved for (c2, k2) in least squares. ModelError if the band holds no frequency.
HeadSuspensionFit fit_head_suspension(double m_H, const std::vector<double>& f,
                                      const std::vector<std::complex<double>>& H,
                                      const std::vector<std::complex<double>>& E, double f_lo, double f_hi);

// ---- Multi-parameter FRF fit (eqs. 4.21, 6.46, 6.47) ---------------------------------------------

/// Eq. 6.47: J = Σ_outputs Σ_f |H_model − H_meas|² (same outputs and frequencies, else ModelError).
double frf_misfit(const Frf& model, const Frf& measured);

/// The frequencies of `frf` in [f_lo, f_hi]; ModelError if none.
Frf frf_band(const Frf& frf, double f_lo, double f_hi);

/// The pantograph on its rig for parameter values (in the order of the variables).
using ModelOf = std::function<pantograph::Pantograph(const std::vector<double>& values)>;

struct FrfFit {
  std::vector<double> values;  ///< fitted parameters
  double cost = 0;             ///< eq. 6.47 at the fit, (m/s²/N)²
  double initial_cost = 0;     ///< at the first start (the centre of the box)
  int evaluations = 0;
  Frf fitted;  ///< model FRF at the fit
};

/// Minimises eq. 6.47 over the variables by the log-scaled pattern search (numerics::pattern_search,
/// multi-start, deterministic for the seed); the model FRF is frf_linear at the measured
/// frequencies. A model that fails numerically for some values costs +∞ there.
FrfFit fit_frf(const ModelOf& model_of, const std::vector<numerics::Variable>& vars, const Frf& measured,
               const numerics::Options& options);

// ---- Pneumatic actuator (spec/03 §3.3) ------------------------------------------------------------

struct LineFit {
  double slope = 0, intercept = 0;
  int points = 0;
  double rms = 0;  ///< residual
};
/// Least-squares line y = slope·x + intercept; ModelError for < 2 points or all x equal.
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

struct ActuatorStaticFit {
  LineFit forward, backward;  ///< F(v) for v > 0 and v < 0 (v in m/s, F in N)
  double F_c = 0;             ///< constant force = mean of the intercepts, N
  double F_r = 0;             ///< Coulomb friction = half their difference, N
  double c1 = 0;              ///< viscous damping = mean of the slopes, N·s/m
};
/// Constant-velocity tests (mean force F at velocity v; F = F_c + F_r sign(v) + c1 v at constant
/// velocity, the final-value theorem leaving only c1 of eq. 5.16): one line per stroke direction.
/// ModelError if a direction has fewer than 2 distinct velocities.
ActuatorStaticFit fit_actuator_static(const std::vector<double>& v, const std::vector<double>& F);

/// Eq. 5.16: Y(s) = 1 / (1/c1 + s/k1) at s = i 2πf (N·s/m).
std::complex<double> maxwell_admittance(double k1, double c1, double f);

/// Correlation method: complex amplitude Y of y(t) ≈ y0 + Re(Y e^{iωt}), ω = 2πf, by least squares
/// over the samples (equal to the Fourier correlation over whole periods; any sampling).
std::complex<double> harmonic_amplitude(const std::vector<double>& t, const std::vector<double>& y, double f);

struct DynamicTest {
  double f = 0;                 ///< excitation frequency, Hz
  std::vector<double> t, x, F;  ///< s, m (strut extension), N (strut force, steady state)
};

struct AdmittancePoint {
  double f = 0;
  std::complex<double> Y_E;  ///< estimated F_d/Δv, N·s/m
  double amplitude = 0;      ///< displacement amplitude |X|, m
};

struct ActuatorDynamicFit {
  double k1 = 0, c1 = 0;
  double cost = 0;  ///< eq. 5.25 at the fit
  std::vector<AdmittancePoint> points;
};

/// Eq. 5.25 cost: J = Σ_f |Y(f) − Y_E(f)| / |Y_E(f)| with Y the Maxwell admittance (eq. 5.16).
double admittance_cost(double k1, double c1, const std::vector<AdmittancePoint>& points);

/// Per test: dynamic force F_d = F − F_r sign(ẋ) − m_p ẍ (the constant force drops out of the
/// harmonic), Y_E = F_d / (iωX) by the correlation method; then k1 (and c1 if fit_c1, else the
/// given c1) minimising eq. 5.25 by the pattern search. ModelError for a test with < 8 samples,
/// shorter than one period or without motion.
ActuatorDynamicFit fit_actuator_dynamic(const std::vector<DynamicTest>& tests, double c1, double piston_mass,
                                        double friction, bool fit_c1 = false);

}  // namespace inerta::analysis
