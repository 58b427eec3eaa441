#pragma once
// Synthetic "measurements" for the identification tests (spec/06 §6.4: no measured data exists):
// models with known parameters, plus seeded noise. Independent of the estimators they test.
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "inerta/analysis/identification.hpp"

namespace inerta::testing {

using cd = std::complex<double>;

/// Head m_H on k2 ‖ c2 on the upper-arm top (mass m_E on k_E ‖ c_E to ground); the contact force
/// p pushes the head down (compression positive, as F_contact).
struct HeadArm {
  double m_H = 5.41, k2 = 5562, c2 = 78;  // Table 6.4 head suspension
  double m_E = 11.33, k_E = 40e3, c_E = 150;
};

/// (FRF_H, FRF_E): accelerations per N of contact force at f Hz, from the 2×2 complex dynamic
/// stiffness [Z_H + Z_2, −Z_2; −Z_2, Z_E + Z_2] x = [−1; 0], a = −ω² x.
inline std::pair<cd, cd> head_arm_frf(const HeadArm& p, double f) {
  const double w = 2 * std::numbers::pi * f;
  const cd z2(p.k2, w * p.c2), zE(p.k_E, w * p.c_E);
  const cd a11 = -w * w * p.m_H + z2, a12 = -z2, a22 = -w * w * p.m_E + zE + z2;
  const cd det = a11 * a22 - a12 * a12;
  const cd xH = -a22 / det, xE = a12 / det;  // Cramer's rule with rhs [−1; 0]
  return {-w * w * xH, -w * w * xE};
}

/// Multiplicative complex noise: H (1 + rel (n1 + i n2)), n1, n2 standard normal.
inline cd noisy(cd H, double rel, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const double n1 = n(rng), n2 = n(rng);
  return H * cd(1 + rel * n1, rel * n2);
}

/// Actuator under constant-velocity tests: F = F_c + F_r sign(v) + c1 v + noise (σ N).
struct ActuatorTruth {
  double F_c = 5460, F_r = 53, c1 = 10440, k1 = 141e3, m_p = 3.45;
};

inline std::pair<std::vector<double>, std::vector<double>> actuator_static_data(const ActuatorTruth& a, double sigma,
                                                                                unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, sigma);
  std::vector<double> v, F;
  for (double mm : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0})
    for (double s : {1.0, -1.0}) {
      v.push_back(s * mm * 1e-3);
      F.push_back(a.F_c + a.F_r * s + a.c1 * v.back() + n(rng));
    }
  return {v, F};
}

/// Sinusoidal tests x = X sin(ωt + 0.3) (the phase keeps samples off the velocity's zeros): the Maxwell force Ḟ_d = k1
/// (ẋ − F_d / c1) integrated by RK4 from F_d = 0 (step ≤ 1e-4 s), the first `run_in` seconds discarded; strut force F =
/// F_c + F_r sign(ẋ) + m_p ẍ + F_d + noise (σ_F N), displacement noise σ_x m.
inline std::vector<analysis::DynamicTest> actuator_dynamic_data(const ActuatorTruth& a, double X,
                                                                const std::vector<double>& freqs, double sigma_F,
                                                                double sigma_x, unsigned seed, int cycles = 6,
                                                                double run_in = 1.5) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> nF(0.0, sigma_F), nx(0.0, sigma_x);
  std::vector<analysis::DynamicTest> tests;
  for (double f : freqs) {
    const double w = 2 * std::numbers::pi * f, T = 1 / f;
    const int per_cycle = 100, sub = std::max(1, static_cast<int>(std::ceil(T / per_cycle / 1e-4)));
    const double dt = T / per_cycle / sub;
    const double phi = 0.3;
    auto v = [&](double t) { return X * w * std::cos(w * t + phi); };
    auto rhs = [&](double t, double Fd) { return a.k1 * (v(t) - Fd / a.c1); };
    analysis::DynamicTest test;
    test.f = f;
    double t = 0, Fd = 0;
    const long n_total = static_cast<long>(std::ceil((run_in + cycles * T) / T * per_cycle));
    for (long i = 0; i <= n_total; ++i) {
      if (t >= run_in - 1e-12) {
        const double vel = v(t), acc = -X * w * w * std::sin(w * t + phi);
        test.t.push_back(t);
        test.x.push_back(X * std::sin(w * t + phi) + nx(rng));
        test.F.push_back(a.F_c + a.F_r * (vel > 0 ? 1 : vel < 0 ? -1 : 0) + a.m_p * acc + Fd + nF(rng));
      }
      for (int s = 0; s < sub; ++s) {
        const double k1 = rhs(t, Fd), k2 = rhs(t + dt / 2, Fd + dt / 2 * k1), k3 = rhs(t + dt / 2, Fd + dt / 2 * k2),
                     k4 = rhs(t + dt, Fd + dt * k3);
        Fd += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        t += dt;
      }
    }
    tests.push_back(std::move(test));
  }
  return tests;
}

}  // namespace inerta::testing
