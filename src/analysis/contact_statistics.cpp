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
#include <optional>

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
// pantograph is 1 m short of the end; statistics of each contact over the analysis section. What one
// system records over its pass: run_line's and each lane's of run_lanes (one code path).
class LineRecorder {
 public:
  // Equilibrates the system and checks the run (its exceptions are the run's).
  LineRecorder(catenary::Coupled& sys, const RunOptions& o) : sys_(sys), o_(o) {
    T_ = sys.span() / sys.speed();
    const auto nc = static_cast<std::size_t>(sys.n_contacts());
    r_.speed = sys.speed();
    sys.equilibrate();
    t_end_ = sys.end_time();
    if (!(t_end_ > 0))
      throw InvalidArgument(fmt::format("the line ({:g} m) is too short for a run", sys.line_length()));
    sec_ = sys.section();
    check_filter_sampling(o.filter_cutoff, T_ / o.samples_per_span, sys.speed());
    F_.resize(nc), ts_.resize(nc), xc_.resize(nc), Fall_.resize(nc);
    xs_ = sys.support_x();
    r_.support_x = xs_;  // then only those in the section
    r_.support_uplift.assign(xs_.size(), 0.0);
  }
  double t_end() const { return t_end_; }
  double dt() const { return T_ / o_.samples_per_span; }

  void sample(const catenary::Sample& s) {
    const auto c = static_cast<std::size_t>(s.contact.index);
    if (c == 0) {
      r_.t.push_back(s.t);
      const std::vector<double> u = sys_.support_uplift();
      for (std::size_t j = 0; j < u.size(); ++j) r_.support_uplift[j] = std::max(r_.support_uplift[j], u[j]);
    }
    if (s.x_contact >= sec_.from && s.x_contact <= sec_.to) F_[c].push_back(s.force);
    ts_[c].push_back(s.t), xc_[c].push_back(s.x_contact), Fall_[c].push_back(s.force);
    if (c == 0) r_.F.push_back(s.force);
  }

  // The statistics after the pass.
  SpeedResult finish() {
    for (std::size_t c = 0; c < F_.size(); ++c) {
      if (F_[c].empty())
        throw InvalidArgument(fmt::format(
            "pantograph {} never passes the analysis section [{:g}, {:g}] m before the end of the line", c + 1, sec_.from,
            sec_.to));
      r_.contacts.push_back(statistics(F_[c]));
      // EN 50317: the same after the 20 Hz low-pass (contact_quality.hpp).
      ContactQuality q = contact_quality(ts_[c], xc_[c], Fall_[c], sec_, {.cutoff = o_.filter_cutoff, .order = o_.filter_order});
      r_.filtered.push_back(q.filtered);
      r_.loss_runs.push_back(std::move(q.loss_runs));
      if (const std::vector<catenary::Section> parts = sys_.overlaps(); !parts.empty()) {
        const PartStatistics ps =
            part_statistics(ts_[c], xc_[c], Fall_[c], sec_, parts, {.cutoff = o_.filter_cutoff, .order = o_.filter_order});
        r_.overlap.push_back(ps.raw), r_.overlap_filtered.push_back(ps.filtered);
      }
    }
    r_.sample_dt = T_ / o_.samples_per_span;
    r_.stats = r_.contacts.front();
    r_.spans = static_cast<int>(std::lround(t_end_ / T_));
    std::vector<double> sx, su;
    for (std::size_t j = 0; j < xs_.size(); ++j)
      if (xs_[j] >= sec_.from && xs_[j] <= sec_.to) sx.push_back(xs_[j]), su.push_back(r_.support_uplift[j]);
    r_.support_x = std::move(sx), r_.support_uplift = std::move(su);
    return std::move(r_);
  }

 private:
  catenary::Coupled& sys_;
  const RunOptions& o_;
  double T_ = 0, t_end_ = 0;
  catenary::Section sec_;
  SpeedResult r_;
  std::vector<std::vector<double>> F_, ts_, xc_, Fall_;  // per contact: in the section; every sample's t, x, F
  std::vector<double> xs_;
};

SpeedResult run_line(catenary::Coupled& sys, const RunOptions& o) {
  LineRecorder rec(sys, o);
  sys.advance(rec.t_end(), rec.dt(), o.integrator, [&](const catenary::Sample& s) { rec.sample(s); });
  return rec.finish();
}

// run_speed's checks of the options and the speed.
void check_run(const catenary::Coupled& sys, const RunOptions& o) {
  check(o);
  check_speed(sys.span(), sys.line_length(), std::numeric_limits<double>::infinity(), sys.speed(), o.max_spans, true);
}

// What a sweep keeps of a run (no histories) and adds (the line's uplift limit).
void lighten(SpeedResult& r, const catenary::Catenary& catenary) {
  r.t.clear(), r.F.clear();
  r.uplift_limit = catenary.uplift_limit();
  r.uplift_limited = catenary.uplift_limited();
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
  check_run(sys, o);
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
  std::vector<std::exception_ptr> errors(speeds.size());
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
      lighten(r, catenary);  // keep sweeps light
      results[i] = std::move(r);
    } catch (...) {
      errors[i] = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress) progress(done, static_cast<int>(speeds.size()));
  });
  for (const std::exception_ptr& e : errors)  // the first speed's, whichever thread failed first
    if (e) std::rethrow_exception(e);
  return results;
}

std::vector<LaneResult> run_lanes(catenary::CoupledLanes& lanes, const RunOptions& o) {
  const auto n = static_cast<std::size_t>(lanes.lanes());
  std::vector<LaneResult> out(n);
  std::vector<std::optional<LineRecorder>> rec(n);
  for (int i = 0; i < lanes.lanes(); ++i) {
    if (!lanes.running(i)) continue;
    catenary::Coupled& sys = lanes.lane(i);
    if (!std::isfinite(sys.line_length()))
      throw InvalidArgument("run_lanes: lanes run on a finite line only (a periodic line's runs settle span by span)");
    try {
      check_run(sys, o);
      rec[static_cast<std::size_t>(i)].emplace(sys, o);  // equilibrates: its exception fails this lane alone
    } catch (...) {
      lanes.fail(i, std::current_exception());
    }
  }
  const LineRecorder* first = nullptr;
  for (const auto& r : rec)
    if (r) {
      if (!first) first = &*r;
      if (r->t_end() != first->t_end() || r->dt() != first->dt())
        throw InvalidArgument(fmt::format("run_lanes: the lanes' runs end at {:g} s and {:g} s: lanes run the same line, "
                                          "speed and positions", first->t_end(), r->t_end()));
    }
  if (first)
    lanes.advance(first->t_end(), first->dt(), o.integrator,
                  [&](int i, const catenary::Sample& s) { rec[static_cast<std::size_t>(i)]->sample(s); });
  for (int i = 0; i < lanes.lanes(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (lanes.running(i)) try {
        out[k].result = rec[k]->finish();
        continue;
      } catch (...) {
        lanes.fail(i, std::current_exception());
      }
    out[k].error = lanes.error(i);
  }
  return out;
}

namespace {
// Several trains at one speed on a finite line: their lanes (a sweep's light results), or, if they
// cannot be coupled together (a train the catenary refuses), each train as sweep runs it.
std::vector<LaneResult> lanes_at(const std::vector<std::vector<catenary::PantographOnLine>>& trains,
                                 const catenary::Catenary& catenary, double speed, const RunOptions& o) {
  std::vector<LaneResult> out(trains.size());
  std::unique_ptr<catenary::CoupledLanes> lanes;
  try {
    lanes = catenary.couple_lanes(trains, speed);
  } catch (...) {
    for (std::size_t i = 0; i < trains.size(); ++i) try {
        auto sys = catenary.couple(trains[i], speed);
        out[i].result = run_speed(*sys, o);
        lighten(out[i].result, catenary);
      } catch (...) {
        out[i].error = std::current_exception();
      }
    return out;
  }
  try {
    out = run_lanes(*lanes, o);
  } catch (...) {  // not one lane's: every lane's
    for (LaneResult& r : out) r.error = std::current_exception();
    return out;
  }
  for (LaneResult& r : out)
    if (!r.error) lighten(r.result, catenary);
  return out;
}
}  // namespace

std::vector<LaneSweep> sweep_lanes(const std::vector<std::vector<catenary::PantographOnLine>>& trains,
                                   const catenary::Catenary& catenary, const std::vector<double>& speeds,
                                   const RunOptions& options) {
  std::vector<LaneSweep> out(trains.size());
  auto fail_all = [&] {
    for (LaneSweep& t : out) t.error = std::current_exception();
  };
  try {  // sweep's checks before any work: every train's
    check(options);
    for (double v : speeds) require(speed_rule, v, "speeds");
    for (double v : speeds) check_run_speed(catenary, v, options.max_spans, options.allow_supercritical);
  } catch (...) {
    fail_all();
    return out;
  }
  if (!std::isfinite(catenary.line_length())) {  // a periodic line: each train's sweep (σ settles per run)
    tbb::parallel_for(std::size_t{0}, trains.size(), [&](std::size_t i) {
      try {
        out[i].results = sweep(trains[i], catenary, speeds, options);
      } catch (...) {
        out[i].error = std::current_exception();
      }
    });
    return out;
  }
  std::vector<std::size_t> live;  // the trains whose line could be prepared
  std::vector<std::vector<catenary::PantographOnLine>> run;
  for (std::size_t i = 0; i < trains.size(); ++i) try {
      catenary.prepare(trains[i]);  // a finite-element line's modes: once (cached for the positions)
      live.push_back(i), run.push_back(trains[i]);
    } catch (...) {
      out[i].error = std::current_exception();
    }
  if (live.empty()) return out;
  std::vector<std::vector<LaneResult>> at(speeds.size());
  tbb::parallel_for(std::size_t{0}, speeds.size(), [&](std::size_t k) { at[k] = lanes_at(run, catenary, speeds[k], options); });
  for (std::size_t j = 0; j < live.size(); ++j) {
    LaneSweep& t = out[live[j]];
    for (std::size_t k = 0; k < speeds.size() && !t.error; ++k) t.error = at[k][j].error;  // the first speed's, as sweep
    if (t.error) continue;
    for (std::size_t k = 0; k < speeds.size(); ++k) t.results.push_back(std::move(at[k][j].result));
  }
  return out;
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
