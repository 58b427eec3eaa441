#include "inerta/analysis/contact_statistics.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>

#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

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

SpeedResult run_speed(const mbs::Model& m, const RunOptions& o, bool bilateral) {
  int out = -1, cat = -1;
  for (std::size_t k = 0; k < m.outputs.size(); ++k)
    if (m.outputs[k].name == "F_contact") out = static_cast<int>(k);
  for (std::size_t k = 0; k < m.forces.size(); ++k)
    if (dynamic_cast<const catenary::CatenaryElement*>(m.forces[k].get())) cat = static_cast<int>(k);
  if (out < 0 || cat < 0) throw std::invalid_argument("run_speed needs a model coupled to a catenary");
  const auto& wire = static_cast<const catenary::CatenaryElement&>(*m.forces[static_cast<std::size_t>(cat)]);
  const double T = wire.catenary().span / o.speed;  // one span
  SpeedResult r;
  r.speed = o.speed;
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);  // no start-up jolt
  const mbs::Output& F_out = m.outputs[static_cast<std::size_t>(out)];
  std::vector<double> span_sigma;
  const double dt = T / o.samples_per_span;
  for (int k = 0; k < o.max_spans; ++k) {
    std::vector<double> F;
    solve::integrate(
        m, x, k * T, (k + 1) * T, dt, o.integrator,
        [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
          if (t == k * T && k > 0) return;  // first sample repeats the previous span's last
          const double f = mbs::evaluate_output(F_out, m, t, s, ws);
          if (bilateral && f < 0)
            throw NumericalError(fmt::format(
                "t = {:.6g} s (v = {:.4g} km/h): the bilateral contact force is {:.4g} N < 0 — the head "
                "pulls the wire down, so this run is invalid for a bilateral contact; use a penalty contact "
                "or check the static force",
                t, o.speed * 3.6, f));
          F.push_back(f);
          r.t.push_back(t);
          r.F.push_back(f);
        },
        true);
    span_sigma.push_back(statistics(F).std);
    r.spans = k + 1;
    if (o.fixed_spans) {
      if (r.spans >= o.min_spans) break;
      continue;
    }
    // Converged when σ changed by less than the tolerance over each of the last `settled_spans` spans
    // (one small change can happen in a slow beat near a resonance).
    if (k >= o.settled_spans) {
      r.sigma_change = 0;
      for (int j = 0; j < o.settled_spans; ++j) {
        const double a = span_sigma[span_sigma.size() - 2 - static_cast<std::size_t>(j)],
                     b = span_sigma[span_sigma.size() - 1 - static_cast<std::size_t>(j)];
        r.sigma_change = std::max(r.sigma_change, std::abs(b - a) / std::max(b, 1e-12));
      }
      if (r.spans >= o.min_spans && r.sigma_change < o.tolerance) break;
    }
  }
  // Window: the last window_spans spans.
  const long per = static_cast<long>(r.F.size()) / r.spans;
  const long n = std::min<long>(static_cast<long>(r.F.size()), per * o.window_spans);
  r.stats = statistics(std::vector<double>(r.F.end() - n, r.F.end()));
  return r;
}

std::vector<SpeedResult> sweep(const mbs::Model& pantograph, const catenary::LumpedCatenary& cat,
                               const catenary::Contact& contact, const std::vector<double>& speeds,
                               const RunOptions& options, const std::function<void(int, int)>& progress) {
  std::vector<SpeedResult> results(speeds.size());
  std::exception_ptr error;
  std::mutex mutex;
  int done = 0;
  const bool bilateral = contact.kind == catenary::Contact::Kind::Bilateral;
  tbb::parallel_for(std::size_t{0}, speeds.size(), [&](std::size_t i) {
    try {
      mbs::Model m =
          catenary::couple(pantograph, cat, contact, speeds[i], pantograph.contact_marker, pantograph.rig_joint);
      RunOptions o = options;
      o.speed = speeds[i];
      SpeedResult r = run_speed(m, o, bilateral);
      r.t.clear(), r.F.clear();  // keep sweeps light
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

}  // namespace inerta::analysis
