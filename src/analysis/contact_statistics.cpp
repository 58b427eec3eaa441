#include "inerta/analysis/contact_statistics.hpp"

#include <fmt/format.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>

#include "inerta/analysis/contact_quality.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/error.hpp"

namespace inerta::analysis {

ContactStatistics statistics(const std::vector<double>& F) {
  ContactStatistics s;
  s.samples = static_cast<long>(F.size());
  if (F.empty()) return s;
  double sum = 0, lost = 0;
  s.max = -INFINITY, s.min = INFINITY;
  for (double f : F) sum += f, s.max = std::max(s.max, f), s.min = std::min(s.min, f), lost += f <= 0;
  s.mean = sum / static_cast<double>(F.size());
  double sq = 0;
  for (double f : F) sq += (f - s.mean) * (f - s.mean);
  s.std = std::sqrt(sq / static_cast<double>(F.size()));
  s.stat_max = s.mean + 3 * s.std, s.stat_min = s.mean - 3 * s.std;
  s.loss_pct = 100 * lost / static_cast<double>(F.size());
  return s;
}

void check_filter_sampling(double cutoff, double dt, double speed) {
  if (!(cutoff < 0.5 / dt))
    throw InvalidArgument(fmt::format(
        "the filtered statistics' low-pass cutoff {:g} Hz (an acceptance set's filter.cutoff; EN 50317: 20 Hz) is not "
        "below the Nyquist frequency {:.4g} Hz of this run's sampling (a sample every {:.4g} ms at {:.4g} m/s); lower "
        "the cutoff or sample more finely",
        cutoff, 0.5 / dt, 1e3 * dt, speed));
}

namespace {
// check_run_speed from the catenary's figures (a Coupled system has them too, but no wave speed).
void check_speed(double span, double line_length, double wave, double speed, int spans, bool allow_supercritical) {
  constexpr double limit = t_end_rule.hi;
  if (!(speed <= max_run_speed))
    throw ModelError(fmt::format("speed {:.4g} m/s ({:.4g} km/h) is above the fastest run accepted, {:g} m/s ({:g} km/h): "
                                 "no train runs there, and the statistics would be of a line that barely moves",
                                 speed, speed * 3.6, max_run_speed, max_run_speed * 3.6));
  const bool line = std::isfinite(line_length);
  const double length = line ? line_length : spans * span;
  if (spans > 0 && !(length / speed <= limit))
    throw ModelError(fmt::format("speed {:.4g} m/s ({:.4g} km/h): a run over {} ({:g} m) would last {:.3g} s, beyond the "
                                 "limit of {:g} s (that of --t-end); the slowest speed accepted here is {:.3g} m/s",
                                 speed, speed * 3.6, line ? std::string("the line") : fmt::format("{} spans", spans),
                                 length, length / speed, limit, length / limit));
  if (speed > wave && !allow_supercritical)
    throw ModelError(fmt::format("speed {:.4g} km/h is above the contact wire's wave speed sqrt(T/rho A) = {:.4g} km/h "
                                 "(inerta check prints it): the wire cannot carry the pantograph's wave ahead of it and "
                                 "the results (large contact loss) are not those of a catenary in service; keep below "
                                 "about 70 % of it, raise the contact-wire tension, or give --allow-supercritical "
                                 "(Python: allow_supercritical=True) to run it anyway",
                                 speed * 3.6, wave * 3.6));
}


// A finite line (the finite-element catenary): one pass from the static state until the leading
// pantograph is 1 m short of the end; statistics of each contact over the analysis section.
SpeedResult run_line(catenary::Coupled& sys, const RunOptions& o) {
  const double T = sys.span() / sys.speed();
  const int nc = sys.n_contacts();
  SpeedResult r;
  r.speed = sys.speed();
  sys.equilibrate();
  const double t_end = sys.end_time();
  if (!(t_end > 0))
    throw InvalidArgument(fmt::format("the line ({:g} m) is too short for a run", sys.line_length()));
  const catenary::Section sec = sys.section();
  check_filter_sampling(o.filter_cutoff, T / o.samples_per_span, sys.speed());
  std::vector<std::vector<double>> F(static_cast<std::size_t>(nc)), ts(F.size()), xc(F.size()), Fall(F.size());
  const std::vector<double> xs = sys.support_x();
  r.support_x = xs;  // then only those in the section
  r.support_uplift.assign(xs.size(), 0.0);
  sys.advance(t_end, T / o.samples_per_span, o.integrator, [&](const catenary::Sample& s) {
    const auto c = static_cast<std::size_t>(s.contact.index);
    if (c == 0) {
      r.t.push_back(s.t);
      const std::vector<double> u = sys.support_uplift();
      for (std::size_t j = 0; j < u.size(); ++j) r.support_uplift[j] = std::max(r.support_uplift[j], u[j]);
    }
    if (s.x_contact >= sec.from && s.x_contact <= sec.to) F[c].push_back(s.force);
    ts[c].push_back(s.t), xc[c].push_back(s.x_contact), Fall[c].push_back(s.force);
    if (c == 0) r.F.push_back(s.force);
  });
  for (int c = 0; c < nc; ++c) {
    if (F[static_cast<std::size_t>(c)].empty())
      throw InvalidArgument(fmt::format(
          "pantograph {} never passes the analysis section [{:g}, {:g}] m before the end of the line", c + 1, sec.from,
          sec.to));
    r.contacts.push_back(statistics(F[static_cast<std::size_t>(c)]));
    // EN 50317: the same after the 20 Hz low-pass (contact_quality.hpp).
    const auto cc = static_cast<std::size_t>(c);
    ContactQuality q = contact_quality(ts[cc], xc[cc], Fall[cc], sec, {.cutoff = o.filter_cutoff, .order = o.filter_order});
    r.filtered.push_back(q.filtered);
    r.loss_runs.push_back(std::move(q.loss_runs));
    if (const std::vector<catenary::Section> parts = sys.overlaps(); !parts.empty()) {
      const PartStatistics ps = part_statistics(ts[cc], xc[cc], Fall[cc], sec, parts, {.cutoff = o.filter_cutoff, .order = o.filter_order});
      r.overlap.push_back(ps.raw), r.overlap_filtered.push_back(ps.filtered);
    }
  }
  r.sample_dt = T / o.samples_per_span;
  r.stats = r.contacts.front();
  r.spans = static_cast<int>(std::lround(t_end / T));
  std::vector<double> sx, su;
  for (std::size_t j = 0; j < xs.size(); ++j)
    if (xs[j] >= sec.from && xs[j] <= sec.to) sx.push_back(xs[j]), su.push_back(r.support_uplift[j]);
  r.support_x = std::move(sx), r.support_uplift = std::move(su);
  return r;
}
}  // namespace

void check(const RunOptions& o) {
  static constexpr CountRule spans{1, 10000}, settled{1, 1000}, samples{10, 1000000};
  require(spans, o.min_spans, "min_spans");
  require(spans, o.max_spans, "max_spans");
  if (o.max_spans < o.min_spans)
    throw InvalidArgument(fmt::format("max_spans: {} is less than min_spans ({})", o.max_spans, o.min_spans));
  require(settled, o.settled_spans, "settled_spans");
  require(spans, o.window_spans, "window_spans");
  require(samples, o.samples_per_span, "samples_per_span");
  require(NumberRule{0, 1, "0 … 1"}, o.tolerance, "tolerance");
}

void check_run_speed(const catenary::Catenary& catenary, double speed, int spans, bool allow_supercritical) {
  check_speed(catenary.span(), catenary.line_length(), catenary.wave_speed(), speed, spans, allow_supercritical);
}

std::string speed_warning(const catenary::Catenary& catenary, double speed) {
  const double wave = catenary.wave_speed();
  if (!(speed >= 0.7 * wave)) return {};
  return fmt::format("warning: {:.4g} km/h is {:.0f} % of the contact wire's wave speed ({:.4g} km/h); the usual design "
                     "rule keeps a pantograph below 70 % of it (wave reflections, contact loss)",
                     speed * 3.6, 100 * speed / wave, wave * 3.6);
}

SpeedResult run_speed(catenary::Coupled& sys, const RunOptions& o) {
  check(o);
  check_speed(sys.span(), sys.line_length(), std::numeric_limits<double>::infinity(), sys.speed(), o.max_spans, true);
  if (std::isfinite(sys.line_length())) return run_line(sys, o);
  const double T = sys.span() / sys.speed();  // one span
  const int nc = sys.n_contacts();
  SpeedResult r;
  r.speed = sys.speed();
  sys.equilibrate();  // no start-up jolt
  std::vector<std::vector<double>> all(static_cast<std::size_t>(nc));  // every contact, all spans
  std::vector<std::vector<double>> span_sigma(static_cast<std::size_t>(nc));
  const double dt = T / o.samples_per_span;
  for (int k = 0; k < o.max_spans; ++k) {
    std::vector<std::vector<double>> F(static_cast<std::size_t>(nc));
    sys.advance((k + 1) * T, dt, o.integrator, [&](const catenary::Sample& s) {
      const auto c = static_cast<std::size_t>(s.contact.index);
      F[c].push_back(s.force);
      all[c].push_back(s.force);
      if (c == 0) r.t.push_back(s.t);
    });
    for (int c = 0; c < nc; ++c)
      span_sigma[static_cast<std::size_t>(c)].push_back(statistics(F[static_cast<std::size_t>(c)]).std);
    r.spans = k + 1;
    if (o.fixed_spans) {
      if (r.spans >= o.min_spans) break;
      continue;
    }
    // Converged when σ changed by less than the tolerance over each of the last `settled_spans` spans
    // (one small change can happen in a slow beat near a resonance), for every contact.
    if (k >= o.settled_spans) {
      r.sigma_change = 0;
      for (const auto& ss : span_sigma)
        for (int j = 0; j < o.settled_spans; ++j) {
          const double a = ss[ss.size() - 2 - static_cast<std::size_t>(j)], b = ss[ss.size() - 1 - static_cast<std::size_t>(j)];
          r.sigma_change = std::max(r.sigma_change, std::abs(b - a) / std::max(b, 1e-12));
        }
      if (r.spans >= o.min_spans && r.sigma_change < o.tolerance) break;
    }
  }
  // Not settled within max_spans (issue 15): flagged, not reported like a converged speed.
  r.converged = o.fixed_spans || (r.spans >= o.min_spans && r.spans > o.settled_spans && r.sigma_change < o.tolerance);
  // Window: the last window_spans spans.
  for (const auto& F : all) {
    const long per = static_cast<long>(F.size()) / r.spans;
    const long n = std::min<long>(static_cast<long>(F.size()), per * o.window_spans);
    r.contacts.push_back(statistics(std::vector<double>(F.end() - n, F.end())));
  }
  r.stats = r.contacts.front();
  r.F = std::move(all.front());
  return r;
}

double estimated_sweep_seconds(const std::vector<catenary::PantographOnLine>& pantographs,
                               const catenary::Catenary& catenary, const std::vector<double>& speeds) {
  // The line's one-off work (setup, first modes) once, before the parallel loop; the runs shared.
  const double once = catenary.estimated_setup_seconds(pantographs);
  double total = 0;
  for (double v : speeds)
    if (v > 0) total += catenary.estimated_seconds(pantographs, v, -1) - once;
  const int cores = std::max(1, std::min(tbb::info::default_concurrency(), static_cast<int>(speeds.size())));
  return once + total / cores;
}

std::vector<SpeedResult> sweep(const std::vector<catenary::PantographOnLine>& pantographs,
                               const catenary::Catenary& catenary, const std::vector<double>& speeds,
                               const RunOptions& options, const std::function<void(int, int)>& progress) {
  std::vector<SpeedResult> results(speeds.size());
  std::exception_ptr error;
  std::mutex mutex;
  int done = 0;
  check(options);                 // before any work
  for (double v : speeds) require(speed_rule, v, "speeds");
  for (double v : speeds) check_run_speed(catenary, v, options.max_spans, options.allow_supercritical);
  catenary.prepare(pantographs);  // once, before the runs (a finite-element line's modes)
  tbb::parallel_for(std::size_t{0}, speeds.size(), [&](std::size_t i) {
    try {
      auto sys = catenary.couple(pantographs, speeds[i]);
      SpeedResult r = run_speed(*sys, options);
      r.t.clear(), r.F.clear();  // keep sweeps light
      r.uplift_limit = catenary.uplift_limit();
      r.uplift_limited = catenary.uplift_limited();
      results[i] = std::move(r);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress) progress(done, static_cast<int>(speeds.size()));
  });
  if (error) std::rethrow_exception(error);
  return results;
}

std::vector<SpeedResult> sweep(const pantograph::Pantograph& pantograph, const catenary::Catenary& catenary,
                               const catenary::Contact& contact, const std::vector<double>& speeds,
                               const RunOptions& options, const std::function<void(int, int)>& progress) {
  return sweep(std::vector<catenary::PantographOnLine>{{pantograph, 0.0, contact}}, catenary, speeds, options,
               progress);
}

std::vector<RunComparison> compare(const std::vector<catenary::PantographOnLine>& pantographs,
                                   const catenary::Catenary& reference, const catenary::Catenary& candidate,
                                   const std::vector<double>& speeds, const RunOptions& options) {
  std::vector<RunComparison> out;
  for (double v : speeds)
    for (const catenary::Catenary* c : {&reference, &candidate}) check_run_speed(*c, v, options.max_spans, options.allow_supercritical);
  auto timed = [&](const catenary::Catenary& c, double v, double& seconds) {
    const auto t0 = std::chrono::steady_clock::now();
    auto sys = c.couple(pantographs, v);
    SpeedResult r = run_speed(*sys, options);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  };
  for (double v : speeds) {
    RunComparison c;
    c.speed = v;
    c.reference = timed(reference, v, c.reference_s);
    c.candidate = timed(candidate, v, c.candidate_s);
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<LossDifference> loss_differences(const SpeedResult& a, const SpeedResult& b) {
  std::vector<LossDifference> out;
  const std::size_t n = std::min({a.t.size(), a.F.size(), b.t.size(), b.F.size()});
  bool open = false;  // the previous sample differed, in the last entry's direction
  for (std::size_t i = 0; i < n; ++i) {
    const bool la = a.F[i] <= 0, lb = b.F[i] <= 0;
    if (la == lb) {
      open = false;
    } else if (open && out.back().candidate == lb) {
      out.back().t_to = a.t[i];
    } else {
      out.push_back({a.t[i], a.t[i], lb}), open = true;
    }
  }
  return out;
}

}  // namespace inerta::analysis
