#pragma once
// EN 50317 / EN 50318 contact-quality outputs of one pantograph over an analysis section of the
// line (docs/contact-quality.md): the contact-force statistics raw and after a low-pass filter, the
// power spectral density of the contact force, and the maximum uplift at the supports.
//
// Conventions
// - Input: one pantograph's uniformly sampled history — times t (s), the contact point's position
//   along the line x_contact (m) and the contact force F (N, compression positive) — and a section
//   [x_from, x_to] (m along the line).
// - Section samples: exactly those with x_from ≤ x_contact ≤ x_to (they must be consecutive, as
//   for a pantograph moving along the line).
// - Raw statistics: analysis::statistics (contact_statistics.hpp) of the section samples —
//   mean F_m, standard deviation σ (population, 1/n), F_m ± 3σ, actual max/min, samples.
// - Filtered statistics: the same of the low-passed force. The filter — a Butterworth low-pass of
//   order 4 at 20 Hz by default, zero-phase (forward–backward, numerics/signal.hpp; its magnitude is
//   |H|², so −6 dB at the cutoff) — is applied to the whole history first, then the section is cut,
//   so the section sees no filter end effects.
// - Contact loss: the share, in %, of section samples whose raw force is ≤ 0 (`loss_pct`, equal to
//   raw.loss_pct). `filtered.loss_pct` counts filtered samples ≤ 0 in the same way; it is
//   informative only — filtering hides short losses — and the raw value is the reported one.
// - PSD: Welch's one-sided density of the raw section force (numerics::welch: Hann window, 50 %
//   overlap, each segment's mean removed), N²/Hz at frequencies in Hz.
#include <cstddef>
#include <vector>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/numerics/signal.hpp"

namespace inerta::analysis {

struct ContactQualityOptions {
  double cutoff = 20;           ///< Hz, low-pass cutoff (EN 50317 / EN 50318: 20 Hz)
  int order = 4;                ///< Butterworth order of each pass
  std::size_t psd_segment = 0;  ///< Welch segment, samples (0: automatic, numerics::WelchOptions)
  double uniform_tolerance = 1e-6;  ///< allowed relative deviation of a time step from the mean step
};

struct ContactQuality {
  double x_from = 0, x_to = 0;  ///< the section, m
  double t_from = 0, t_to = 0;  ///< times of its first and last sample, s
  std::size_t first = 0;        ///< index of the first section sample in the history
  double sample_rate = 0;       ///< Hz
  double cutoff = 0;            ///< Hz
  int order = 0;
  ContactStatistics raw;        ///< of the raw section force
  ContactStatistics filtered;   ///< of the low-passed force over the section (loss_pct informative)
  double loss_pct = 0;          ///< % of section samples with raw F ≤ 0 (the reported contact loss)
  std::vector<long> loss_runs;  ///< lengths (samples) of the section's maximal runs of raw F ≤ 0, in order
  numerics::Spectrum psd;       ///< of the raw section force, N²/Hz
};

/// The EN 50317 statistics of one pantograph over [x_from, x_to] as described above.
/// InvalidArgument: sizes differ; times not uniform (numerics::uniform_sample_rate); x_from > x_to;
/// a section with no samples (naming the section and the range of x the run covered); section
/// samples not consecutive; a history too short for the filter (it needs more than 3(order + 1)
/// samples) or a cutoff at or above f_s/2; fewer than 8 section samples for the PSD; non-finite data.
ContactQuality contact_quality(const std::vector<double>& t, const std::vector<double>& x_contact,
                               const std::vector<double>& F, double x_from, double x_to,
                               const ContactQualityOptions& options = {});
/// The raw and low-passed statistics of the samples with x in one of `parts` and in [x_from, x_to]
/// (the overlaps of a line of tension sections, issue 35): the same low-pass over the whole history,
/// then the cut. Both empty (samples 0) when no sample lies there; the errors of contact_quality.
struct PartStatistics {
  ContactStatistics raw, filtered;
};
PartStatistics part_statistics(const std::vector<double>& t, const std::vector<double>& x_contact,
                               const std::vector<double>& F, const catenary::Section& section,
                               const std::vector<catenary::Section>& parts, const ContactQualityOptions& options = {});
/// Over the catenary's analysis section (catenary::Catenary::section()).
ContactQuality contact_quality(const std::vector<double>& t, const std::vector<double>& x_contact,
                               const std::vector<double>& F, const catenary::Section& section,
                               const ContactQualityOptions& options = {});

/// The largest uplift of one support over the run.
struct SupportUplift {
  std::size_t support = 0;  ///< index in the list of supports given
  double x = 0;             ///< its position along the line, m
  double max_uplift = 0;    ///< m (up positive, from the static state without pantographs)
  double t_max = 0;         ///< time of the maximum, s (the first if it repeats)
};

/// For each support with x_from ≤ support_x[k] ≤ x_to, in the order given: its maximum uplift over
/// the whole history and when it happened. `uplift[i][k]` is the uplift of support k at time t[i]
/// (one row a sample, as catenary::Coupled::support_uplift() gives it). InvalidArgument for a count
/// of rows other than t's, x_from > x_to, an empty history (unless there is no support at all: a
/// line of one span), a row whose length is not the supports' count, or a value that is not finite.
/// No support in the section gives an empty result.
std::vector<SupportUplift> support_uplift(const std::vector<double>& t, const std::vector<double>& support_x,
                                          const std::vector<std::vector<double>>& uplift, double x_from,
                                          double x_to);

}  // namespace inerta::analysis
