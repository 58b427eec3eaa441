#include "inerta/analysis/contact_quality.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/error.hpp"

namespace inerta::analysis {

namespace {
constexpr const char* kWhat = "contact quality";

void check_section(double from, double to) {
  if (!std::isfinite(from) || !std::isfinite(to) || from > to)
    throw InvalidArgument(fmt::format("{}: section [{}, {}] m: needs finite x_from <= x_to", kWhat, from, to));
}

template <class F>
auto with_context(F&& f) {
  try {
    return f();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(fmt::format("{}: {}", kWhat, e.what()));
  }
}
}  // namespace

ContactQuality contact_quality(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& F,
                               double x_from, double x_to, const ContactQualityOptions& o) {
  const std::size_t n = t.size();
  if (x.size() != n || F.size() != n)
    throw InvalidArgument(fmt::format("{}: {} times, {} contact positions and {} forces: need as many of each", kWhat,
                                      n, x.size(), F.size()));
  check_section(x_from, x_to);
  if (n == 0) throw InvalidArgument(fmt::format("{}: the history is empty", kWhat));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(F[i]))
      throw InvalidArgument(fmt::format("{}: sample {} (t = {} s): x_contact = {}, F = {}: not finite", kWhat, i, t[i],
                                        x[i], F[i]));

  // The section: every sample with x in [from, to], consecutive.
  std::size_t first = n, last = 0, count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (x[i] >= x_from && x[i] <= x_to) first = std::min(first, i), last = i, ++count;
  if (count == 0) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    throw InvalidArgument(fmt::format(
        "{}: the section [{:g}, {:g}] m contains no samples: the run covered x_contact from {:g} to {:g} m", kWhat, x_from,
        x_to, *lo, *hi));
  }
  if (count != last - first + 1)
    throw InvalidArgument(fmt::format(
        "{}: the samples in the section [{}, {}] m are not consecutive (from t = {} s to t = {} s, {} of {} inside): "
        "x_contact must move through the section once",
        kWhat, x_from, x_to, t[first], t[last], count, last - first + 1));

  ContactQuality q;
  q.x_from = x_from, q.x_to = x_to;
  q.first = first;
  q.t_from = t[first], q.t_to = t[last];
  q.cutoff = o.cutoff, q.order = o.order;
  q.sample_rate = with_context([&] { return numerics::uniform_sample_rate(t, o.uniform_tolerance); });
  const numerics::SosFilter lowpass =
      with_context([&] { return numerics::butterworth_lowpass(o.cutoff, q.sample_rate, o.order); });
  const std::size_t pad = numerics::filtfilt_padding(lowpass);
  if (n <= pad)
    throw InvalidArgument(fmt::format(
        "{}: too few samples for the {} Hz low-pass of order {}: it needs more than {} samples of history, got {}",
        kWhat, o.cutoff, o.order, pad, n));
  if (count < 8)
    throw InvalidArgument(fmt::format(
        "{}: the section [{}, {}] m has {} samples: too few for its power spectral density (at least 8)", kWhat,
        x_from, x_to, count));

  const auto begin = static_cast<std::ptrdiff_t>(first), end = static_cast<std::ptrdiff_t>(last + 1);
  const std::vector<double> raw(F.begin() + begin, F.begin() + end);
  const std::vector<double> smooth = numerics::filtfilt(lowpass, F);  // the whole history, then the cut
  q.raw = statistics(raw);
  q.filtered = statistics(std::vector<double>(smooth.begin() + begin, smooth.begin() + end));
  q.loss_pct = q.raw.loss_pct;
  q.loss_runs = loss_runs(raw);
  q.psd = with_context([&] { return numerics::welch(raw, q.sample_rate, {.segment = o.psd_segment}); });
  return q;
}

PartStatistics part_statistics(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& F,
                               const catenary::Section& section, const std::vector<catenary::Section>& parts,
                               const ContactQualityOptions& o) {
  const ContactQuality q = contact_quality(t, x, F, section, o);  // the checks, the rate
  const numerics::SosFilter lowpass = with_context([&] { return numerics::butterworth_lowpass(o.cutoff, q.sample_rate, o.order); });
  const std::vector<double> smooth = numerics::filtfilt(lowpass, F);
  std::vector<double> raw, filtered;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] >= section.from && x[i] <= section.to)) continue;
    for (const catenary::Section& p : parts)
      if (x[i] >= p.from && x[i] <= p.to) {
        raw.push_back(F[i]), filtered.push_back(smooth[i]);
        break;
      }
  }
  return {statistics(raw), statistics(filtered)};
}

ContactQuality contact_quality(const std::vector<double>& t, const std::vector<double>& x_contact,
                               const std::vector<double>& F, const catenary::Section& section,
                               const ContactQualityOptions& options) {
  return contact_quality(t, x_contact, F, section.from, section.to, options);
}

std::vector<SupportUplift> support_uplift(const std::vector<double>& t, const std::vector<double>& support_x,
                                          const std::vector<std::vector<double>>& uplift, double x_from,
                                          double x_to) {
  const char* what = "support uplift";
  if (uplift.size() != t.size())
    throw InvalidArgument(fmt::format("{}: {} rows of uplift for {} times: need one row a time", what, uplift.size(),
                                      t.size()));
  if (!std::isfinite(x_from) || !std::isfinite(x_to) || x_from > x_to)
    throw InvalidArgument(fmt::format("{}: section [{}, {}] m: needs finite x_from <= x_to", what, x_from, x_to));
  if (support_x.empty()) return {};  // a line of one span: no support to report (issue 38)
  if (t.empty()) throw InvalidArgument(fmt::format("{}: the history is empty", what));
  for (std::size_t i = 0; i < uplift.size(); ++i)
    if (uplift[i].size() != support_x.size())
      throw InvalidArgument(fmt::format("{}: row {} (t = {} s) has {} values for {} supports", what, i, t[i],
                                        uplift[i].size(), support_x.size()));
  std::vector<SupportUplift> out;
  for (std::size_t k = 0; k < support_x.size(); ++k) {
    if (!(support_x[k] >= x_from && support_x[k] <= x_to)) continue;
    SupportUplift s;
    s.support = k, s.x = support_x[k];
    s.max_uplift = -INFINITY;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double u = uplift[i][k];
      if (!std::isfinite(u))
        throw InvalidArgument(fmt::format("{}: support {} at x = {} m, t = {} s: uplift {} is not finite", what, k,
                                          support_x[k], t[i], u));
      if (u > s.max_uplift) s.max_uplift = u, s.t_max = t[i];
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace inerta::analysis
