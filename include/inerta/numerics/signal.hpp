#pragma once
// Signal processing for contact-force outputs (EN 50317 / EN 50318 practice): a digital Butterworth
// low-pass, zero-phase (forward–backward) filtering, and one-sided power spectral densities.
//
// Butterworth low-pass of order n, cutoff f_c, sample rate f_s (T = 1/f_s), by the bilinear
// transform with frequency pre-warping:
//   analog prototype   |H_a(jΩ)|² = 1 / (1 + (Ω/Ω_c)^(2n)),  poles on the circle |s| = Ω_c at
//                      s_k = Ω_c·exp(jπ(2k + n − 1)/(2n)), k = 1..n (left half-plane);
//   pre-warping        Ω_c = (2/T)·tan(π f_c/f_s), so that the digital cutoff is exactly f_c;
//   bilinear map       s = (2/T)·(1 − z⁻¹)/(1 + z⁻¹).
// With W = tan(π f_c/f_s) and a_k = 2 sin(π(2k − 1)/(2n)), each conjugate pole pair (k = 1..⌊n/2⌋)
// gives the second-order section
//   H_k(z) = W²(1 + z⁻¹)² / [(1 + a_k W + W²) + 2(W² − 1) z⁻¹ + (1 − a_k W + W²) z⁻²],
// and an odd order adds the first-order section H(z) = W(1 + z⁻¹) / [(1 + W) + (W − 1) z⁻¹].
// Every section has unit gain at DC and a double zero at z = −1 (f_s/2). On the unit circle
// (1 − z⁻¹)/(1 + z⁻¹) = j·tan(π f/f_s), so the digital magnitude is exactly
//   |H(e^{j2πf/f_s})| = 1 / sqrt(1 + (tan(π f/f_s)/tan(π f_c/f_s))^(2n)),
// the analog response at the pre-warped frequency f_a = (f_s/π)·tan(π f/f_s): 1/√2 (−3 dB) at f_c.
//
// Zero-phase filtering (filtfilt) runs the sections forward, then backward over the reversed result:
// the phase cancels and the magnitude is |H|² — −6 dB (a gain of 1/2) at f_c, not −3 dB. The ends are
// extended by odd reflection (x_{−i} = 2x_0 − x_i, likewise at the end) over 3(n + 1) samples, and
// each pass starts every section in its steady state for a step of the first sample it sees, so a
// constant passes unchanged and a signal has no start-up transients at its ends (the conventions of
// MATLAB filtfilt / SciPy sosfiltfilt with padtype "odd"; the result agrees with SciPy's to
// rounding). The mean is taken out before and put back after (the filter is linear), which keeps
// the rounding relative to the fluctuation rather than the mean level.
//
// Power spectral density, one-sided, in units²/Hz at frequencies in Hz (Welch's method): segments of
// L samples with a given overlap (default 50 %), each with its own mean removed, multiplied by a
// window w (default Hann, periodic: w_i = sin²(πi/L)), transformed (X_k = Σ_i w_i x_i e^{−j2πik/L}),
// and averaged:
//   S(f_k) = c_k · |X_k|² / (f_s Σ_i w_i²),  f_k = k f_s/L,  k = 0..⌊L/2⌋,
// with c_k = 1 at k = 0 and at k = L/2 (even L), c_k = 2 otherwise (the negative frequencies folded
// in). Then Σ_k S(f_k) Δf (Δf = f_s/L) equals the mean over the segments of the windowed mean square
// Σ w_i² x_i² / Σ w_i² — Parseval: ∫ S df is the variance. White noise of variance σ² has
// S = 2σ²/f_s; a sine of amplitude A gives a peak at its frequency whose integral is A²/2. Samples
// after the last whole segment are not used. The periodogram is the one-segment case with a
// rectangular window (the whole record, mean removed).
#include <cstddef>
#include <vector>

namespace inerta::numerics {

/// One second-order section, transposed direct form II:
///   y = b0 x + z1,  z1 ← b1 x − a1 y + z2,  z2 ← b2 x − a2 y   (a0 = 1; a first-order section has b2 = a2 = 0).
struct Biquad {
  double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};

/// A cascade of second-order sections with the sample rate it was designed for.
struct SosFilter {
  std::vector<Biquad> sections;
  double sample_rate = 0;  ///< Hz
  int order = 0;           ///< order of the transfer function
  /// Complex response at frequency f (Hz): H(e^{j2πf/f_s}) = Π_k H_k, evaluated from the sections.
  /// Returns |H|; `phase` (rad), if given, receives arg H.
  double magnitude(double f, double* phase = nullptr) const;
  /// Gain at DC, Π_k (b0 + b1 + b2)/(1 + a1 + a2).
  double dc_gain() const;
};

/// Butterworth low-pass of `order` ≥ 1 (≤ 20), cutoff 0 < f_c < f_s/2, designed as above.
/// InvalidArgument names the bad value (a cutoff at or above Nyquist gives f_s/2).
SosFilter butterworth_lowpass(double cutoff, double sample_rate, int order = 4);

/// Causal filtering from rest (zero initial states): the sections in cascade.
std::vector<double> filter(const SosFilter& filter, const std::vector<double>& x);

/// Number of samples of the odd-reflection extension at each end in filtfilt: 3(order + 1).
std::size_t filtfilt_padding(const SosFilter& filter);

/// Zero-phase forward–backward filtering as described above (magnitude |H|², phase 0). Needs more
/// than filtfilt_padding(filter) samples (InvalidArgument saying how many); NaN or infinite samples
/// are refused.
std::vector<double> filtfilt(const SosFilter& filter, const std::vector<double>& x);

/// The sample rate 1/Δt of uniformly sampled times t (at least 2, strictly increasing, every step
/// within rel_tol of the mean step Δt = (t_last − t_first)/(n − 1)). InvalidArgument otherwise,
/// naming the first offending step (a repeated time, a gap, a step back).
double uniform_sample_rate(const std::vector<double>& t, double rel_tol = 1e-6);

/// A one-sided power spectral density: S[k] at f[k], units²/Hz.
struct Spectrum {
  std::vector<double> f;  ///< Hz, k f_s / L, k = 0..⌊L/2⌋
  std::vector<double> S;  ///< units²/Hz
  double resolution = 0;  ///< Δf = f_s / L, Hz
  int segments = 0;       ///< number of averaged segments
  /// ∫ S df by the rectangle rule Σ S_k Δf (the variance, by Parseval).
  double integral() const;
  /// ∫ S df over f_lo ≤ f_k ≤ f_hi.
  double integral(double f_lo, double f_hi) const;
};

enum class Window { Hann, Rectangular };

struct WelchOptions {
  /// Samples a segment, L ≥ 4 (0: automatic — the largest power of two ≤ n/4 if that is ≥ 16,
  /// giving 7 to 15 half-overlapping segments; otherwise the whole record as one segment).
  std::size_t segment = 0;
  double overlap = 0.5;  ///< fraction of a segment shared with the next, 0 ≤ overlap < 1
  Window window = Window::Hann;
};

/// Welch's PSD of x sampled at sample_rate (Hz). InvalidArgument for fewer than 4 samples, a
/// segment longer than the record or shorter than 4, a bad overlap or rate, non-finite samples.
Spectrum welch(const std::vector<double>& x, double sample_rate, const WelchOptions& options = {});

/// The periodogram: the whole record as one segment, mean removed, rectangular window by default.
Spectrum periodogram(const std::vector<double>& x, double sample_rate, Window window = Window::Rectangular);

}  // namespace inerta::numerics
