#pragma once
// Test-rig FRFs (spec/04 §4.2, eq. 6.25): the head's vertical displacement is imposed through the
// pantograph's rig joint (a driving joint); FRF_i(f) = Fourier component of output i (a vertical
// acceleration) over that of the contact force (the rig joint's reaction on the head,
// Pantograph::rig_force), at the excitation frequency.
#include <complex>
#include <string>
#include <vector>

#include "inerta/error.hpp"

#include "inerta/mbs/model.hpp"
#include "inerta/pantograph/pantograph.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::analysis {

struct Frf {
  std::vector<double> f;                             ///< Hz
  std::vector<std::string> outputs;                  ///< output names
  std::vector<std::vector<std::complex<double>>> H;  ///< H[i][k]: output i at f[k], per N of contact force
};

/// Linear FRF from the model linearised about its static equilibrium with the head held: per
/// frequency the complex system [−ω²M + iωC + K (+ network states), C_qᵀ; C_q, 0] is solved for a
/// unit harmonic displacement of the rig joint (exact in the frequency domain, no Baumgarte).
Frf frf_linear(const pantograph::Pantograph& rig, const std::vector<std::string>& outputs, const std::vector<double>& f);

struct SteppedSine {
  double vc = 0.06;   ///< constant mean velocity amplitude V_c, m/s: A(f) = V_c / (2π f)
  int cycles = 100;   ///< cycles simulated per frequency
  int analysed = 50;  ///< last cycles analysed
  int samples_per_cycle = 100;
  solve::IntegratorOptions integrator;
};

/// Each frequency of an FRF or a pumping frequency: InvalidArgument "f: 0 is out of range; …".
inline constexpr NumberRule frequency_rule{1e-300, 1e6, "> 0 Hz, at most 1e6 Hz"};

/// The rules of SteppedSine's fields (the CLI's --vc, --cycles, --analysed and Python's vc, cycles, analysed).
inline constexpr NumberRule vc_rule{1e-300, 1e300, "> 0 m/s"};
inline constexpr CountRule cycles_rule{1, 100000};
inline constexpr CountRule analysed_rule{1, 100000};
inline constexpr CountRule samples_per_cycle_rule{4, 100000};  ///< 4: a sine is still resolved
/// InvalidArgument "vc: …", "cycles: …", "analysed: …" (also "analysed: 60 is more than cycles (50)"),
/// "samples_per_cycle: …".
void check(const SteppedSine& options);

/// Stepped-sine FRF by time simulation of the nonlinear model (frequencies in parallel, oneTBB).
Frf frf_stepped_sine(const pantograph::Pantograph& rig, const std::vector<std::string>& outputs, const std::vector<double>& f,
                     const SteppedSine& options);

}  // namespace inerta::analysis
