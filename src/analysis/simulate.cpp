#include "inerta/analysis/simulate.hpp"

#include <algorithm>
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/output.hpp"
#include "inerta/numerics/phase_times.hpp"

namespace inerta::analysis {

namespace {

TimeHistory empty_history(const mbs::Model& m) {
  TimeHistory h;
  for (const auto& o : m.outputs) h.names.push_back(o.name);
  h.columns.resize(m.outputs.size());
  return h;
}

void record(TimeHistory& h, const mbs::Model& m, double t, const mbs::State& s, const mbs::Workspace& ws) {
  h.t.push_back(t);
  for (std::size_t k = 0; k < m.outputs.size(); ++k) h.columns[k].push_back(mbs::evaluate_output(m.outputs[k], m, t, s, ws));
}

bool needs_acc(const mbs::Model& m) {
  return std::any_of(m.outputs.begin(), m.outputs.end(), [](const mbs::Output& o) { return mbs::needs_accelerations(o); });
}

// At most max_samples output rows (issue 15): a sampling interval too fine for t_end is refused.
void check_samples(double t_end, double sample) {
  if (!(t_end / sample <= static_cast<double>(max_samples)))
    throw InvalidArgument(fmt::format("simulate: t_end = {:g} s sampled every {:g} s gives {:.3g} rows; at most {} are "
                                      "written (a larger sampling interval or a shorter run)",
                                      t_end, sample, t_end / sample, max_samples));
}

}  // namespace

Simulation simulate(const mbs::Model& model, const SimulateOptions& o, const TimeProgress& progress) {
  Simulation r;
  r.t_end = o.t_end > 0 ? o.t_end : model.options.t_end;
  r.sample = o.sample > 0 ? o.sample : model.options.sample;
  if (!(r.t_end > 0) || !(r.sample > 0) || !std::isfinite(r.t_end) || !std::isfinite(r.sample))
    throw InvalidArgument("simulate: t_end and the sampling interval must be positive numbers of seconds");
  check_samples(r.t_end, r.sample);
  mbs::State x = mbs::assemble(model, 0.0, &r.assembly);
  if (o.from_equilibrium) {
    r.equilibrium.emplace();
    mbs::static_equilibrium(model, 0.0, x, &*r.equilibrium);
    mbs::consistent_velocities(model, 0.0, x);  // the driving joints' f′(0), q̇ = 0 otherwise
  }
  r.history = empty_history(model);
  double next_report = 0;
  r.stats = solve::integrate(
      model, x, 0.0, r.t_end, r.sample, o.integrator,
      [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
        record(r.history, model, t, s, ws);
        if (progress && t >= next_report) progress(t, r.t_end), next_report += r.t_end / 50;
      },
      needs_acc(model));
  if (o.steady_from >= 0) r.steady = summarise(r.history, o.steady_from);
  return r;
}

std::vector<OutputSummary> summarise(const TimeHistory& h, double from) {
  std::vector<OutputSummary> out;
  for (std::size_t k = 0; k < h.names.size(); ++k) {
    OutputSummary s{h.names[k], h.columns[k].empty() ? 0.0 : h.columns[k].front(), INFINITY, -INFINITY, 0, 0};
    double sum = 0;
    for (std::size_t i = 0; i < h.t.size(); ++i)
      if (h.t[i] >= from - 1e-12) {
        const double v = h.columns[k][i];
        s.min = std::min(s.min, v), s.max = std::max(s.max, v), sum += v, ++s.samples;
      }
    s.mean = s.samples > 0 ? sum / static_cast<double>(s.samples) : NAN;
    out.push_back(s);
  }
  return out;
}

void check(const CoupledOptions& o) {
  require(spans_rule, o.spans, "spans");
  require(window_spans_rule, o.window_spans, "window_spans");
  if (!(o.t_end <= 0)) require(t_end_rule, o.t_end, "t_end");
  if (!(o.sample <= 0)) require(sample_rule, o.sample, "sample");
}

CoupledSimulation simulate_coupled(const std::vector<catenary::PantographOnLine>& pantographs,
                                   const catenary::Catenary& catenary, double speed, const CoupledOptions& o,
                                   const TimeProgress& progress) {
  check(o);
  if (!(o.t_end > 0)) {
    check_run_speed(catenary, speed, o.spans, o.allow_supercritical);
  } else {  // the run's length is given (t_end_rule): only the speed itself
    check_run_speed(catenary, speed, 0, o.allow_supercritical);
  }
  std::unique_ptr<catenary::Coupled> sys;
  {
    const numerics::PhaseTimer t("couple: the line, its windows' modes");
    sys = catenary.couple(pantographs, speed);
  }
  CoupledSimulation r;
  r.speed = speed;
  r.span = sys->span();
  const double T = r.span / speed;
  const bool line = std::isfinite(sys->line_length());  // a finite line: to its end, statistics over its section
  r.t_end = o.t_end > 0 ? o.t_end : line ? sys->end_time() : o.spans * T;
  if (line && r.t_end > sys->end_time() + 1e-9)
    throw InvalidArgument(fmt::format("simulate: t_end = {:g} s runs the leading pantograph off the line (at most {:g} s)",
                                      r.t_end, sys->end_time()));
  r.sample = o.sample > 0 ? o.sample : T / 400;
  if (!std::isfinite(r.t_end) || !std::isfinite(r.sample))
    throw InvalidArgument("simulate: t_end and the sampling interval must be finite numbers of seconds");
  check_samples(r.t_end, r.sample);
  if (line) check_filter_sampling(o.filter_cutoff, r.sample, speed);
  r.window_from = std::max(0.0, r.t_end - o.window_spans * T);
  if (line) r.section = sys->section();
  if (line)
    for (const catenary::Section& p : sys->overlaps())  // the overlaps' parts in the section
      if (std::max(p.from, r.section.from) < std::min(p.to, r.section.to))
        r.overlaps.push_back({std::max(p.from, r.section.from), std::min(p.to, r.section.to)});
  r.support_x = sys->support_x();
  r.supports.t.clear();
  r.supports.names = sys->support_names();
  r.supports.columns.resize(r.support_x.size());
  const int nc = sys->n_contacts();
  std::vector<std::vector<double>> window(static_cast<std::size_t>(nc));
  std::vector<std::vector<double>> force(static_cast<std::size_t>(nc));  // every sample's contact force
  r.contacts.resize(static_cast<std::size_t>(nc));
  for (int c = 0; c < nc; ++c) {
    TimeHistory h = empty_history(sys->model(sys->contact(c)));
    if (line) {  // m along the line; m above the wire's static height
      if (sys->wires() == 2)  // each contact wire's force (N) and uplift (m; nan where it is not) (issue 35)
        for (const char* n : {"F_contact_w1", "F_contact_w2", "wire_uplift_w1", "wire_uplift_w2"}) h.names.push_back(n);
      h.names.push_back("x_contact"), h.names.push_back("wire_uplift");
      h.columns.resize(h.names.size());
    }
    r.histories.push_back(std::move(h));
  }
  bool acc = false;
  for (int c = 0; c < nc; ++c) acc = acc || needs_acc(sys->model(sys->contact(c)));
  {
    const numerics::PhaseTimer t("static equilibrium");
    sys->equilibrate();
  }
  double next_report = 0;
  std::optional<numerics::PhaseTimer> steps(std::in_place, "time steps (with sampling)");
  r.stats = sys->advance(
        r.t_end, r.sample, o.integrator,
        [&](const catenary::Sample& s) {
          const auto c = static_cast<std::size_t>(s.contact.index);
          record(r.histories[c], s.model, s.t, s.state, s.ws);
          if (line) {
            auto& cols = r.histories[c].columns;
            cols.back().push_back(s.wire_uplift);
            cols[cols.size() - 2].push_back(s.x_contact);
            if (sys->wires() == 2) {
              const std::size_t b = cols.size() - 6;
              cols[b].push_back(s.force_wire[0]), cols[b + 1].push_back(s.force_wire[1]);
              cols[b + 2].push_back(s.uplift_wire[0]), cols[b + 3].push_back(s.uplift_wire[1]);
            }
          }
          if (c == 0 && !r.support_x.empty()) {
            r.supports.t.push_back(s.t);
            const std::vector<double> u = sys->support_uplift();
            for (std::size_t j = 0; j < u.size(); ++j) r.supports.columns[j].push_back(u[j]);
          }
          force[c].push_back(s.force);
          ContactSummary& cs = r.contacts[c];
          if (s.force <= 0) {
            if (cs.lost_samples++ == 0) cs.first_loss_t = s.t, cs.first_loss_x = s.x_contact;
          }
          if (line ? (s.x_contact >= r.section.from && s.x_contact <= r.section.to) : s.t >= r.window_from - 1e-9)
            window[c].push_back(s.force);
          if (progress && c == 0 && s.t >= next_report) progress(s.t, r.t_end), next_report += r.t_end / 50;
        },
        acc);
  steps.reset();
  const numerics::PhaseTimer stats("statistics");
  for (int c = 0; c < nc; ++c) r.contacts[static_cast<std::size_t>(c)].stats = statistics(window[static_cast<std::size_t>(c)]);
  if (line) {  // EN 50317 / 50318 outputs over the section
    for (int c = 0; c < nc; ++c) {
      const TimeHistory& h = r.histories[static_cast<std::size_t>(c)];
      r.quality.push_back(contact_quality(h.t, h.columns[h.columns.size() - 2], force[static_cast<std::size_t>(c)], r.section,
                                          {.cutoff = o.filter_cutoff, .order = o.filter_order}));
      if (!r.overlaps.empty())
        r.overlap_quality.push_back(part_statistics(h.t, h.columns[h.columns.size() - 2], force[static_cast<std::size_t>(c)],
                                                    r.section, r.overlaps, {.cutoff = o.filter_cutoff, .order = o.filter_order}));
    }
    std::vector<std::vector<double>> rows(r.supports.t.size(), std::vector<double>(r.support_x.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < r.support_x.size(); ++j) rows[i][j] = r.supports.columns[j][i];
    r.uplift = support_uplift(r.supports.t, r.support_x, rows, r.section.from, r.section.to);
  }
  r.uplift_limit = catenary.uplift_limit();
  r.uplift_limited = catenary.uplift_limited();
  return r;
}

}  // namespace inerta::analysis
