// `inerta simulate MODEL` (docs/cli.md): a time simulation, alone or under a catenary.
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "acceptance.hpp"
#include "report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/catenary_response.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/analysis/frf.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/analysis/modal.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/report/run_reports.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/lumped_fit_file.hpp"
#include "inerta/io/file_kind.hpp"
#include "inerta/io/linear_model_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/io/study_report.hpp"
#include "inerta/io/study_results.hpp"
#include "inerta/io/files.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/network/realisation.hpp"
#include "inerta/optim/report.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::cli {

namespace simulate_command {
namespace {

struct SimulateArgs {
  std::string model, out, positions;
  double t_end = -1, sample = -1, rtol = 1e-6, atol = 1e-8, steady_from = -1, max_step = 0;
  bool no_centripetal = false, from_equilibrium = false;
  std::string integrator = "rk";
  CatenaryArgs cat;
  double speed = -1;
  int spans = 12;
  cli::AcceptanceArgs acceptance;
  double max_seconds = analysis::default_max_seconds;
  std::string report;  ///< --report FILE.html (a run under a catenary)
};

// "0,200.5" → {0, 200.5}: positions along the line, m.
std::vector<double> parse_positions(const std::string& list) {
  std::vector<double> x;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    double v = 0;
    if (!CLI::detail::lexical_cast(item, v) || !std::isfinite(v))
      throw CLI::ValidationError("--positions", "expected comma-separated positions in m, got '" + list + "'");
    for (double w : x)
      if (w == v)
        throw CLI::ValidationError("--positions", fmt::format("{:g} m is given twice in '{}'; each pantograph needs its own position", v, list));
    x.push_back(v);
  }
  if (x.empty()) throw CLI::ValidationError("--positions", "expected at least one position");
  return x;
}

void print_steady(std::FILE* info, double from, const std::vector<analysis::OutputSummary>& steady,
                  const std::string& prefix = "") {
  if (steady.empty() || steady.front().samples == 0) return;
  fmt::print(info, "steady state t >= {:g} s ({} samples):\n", from, steady.front().samples);
  fmt::print(info, "  {:<14} {:>14} {:>14} {:>14} {:>14} {:>14}\n", "output", "initial", "min", "max", "peak-to-peak",
             "mean-initial");
  for (const auto& o : steady)
    fmt::print(info, "  {:<14} {:>14.6g} {:>14.6g} {:>14.6g} {:>14.6g} {:>14.6g}\n", prefix + o.name, o.initial, o.min,
               o.max, o.max - o.min, o.mean - o.initial);
}

// Writes histories that share their time samples side by side: t, then each one's columns.
void write_csv(std::FILE* out, const std::vector<const analysis::TimeHistory*>& hs,
               const std::vector<std::string>& prefixes) {
  std::string line = "t";
  for (std::size_t p = 0; p < hs.size(); ++p)
    for (const auto& n : hs[p]->names) line += "," + prefixes[p] + n;
  line += '\n';
  std::fputs(line.c_str(), out);
  const std::size_t rows = hs.front()->t.size();
  for (std::size_t i = 0; i < rows; ++i) {
    line.clear();
    append_number(line, hs.front()->t[i]);
    for (const auto* h : hs)
      for (const auto& c : h->columns) {
        line += ',';
        append_number(line, i < c.size() ? c[i] : NAN);
      }
    line += '\n';
    std::fputs(line.c_str(), out);
  }
}

// A finite line (the finite-element catenary): EN 50317 statistics per pantograph, raw and
// after the 20 Hz low-pass, and the uplift of the supports in the section.
void print_line_outputs(std::FILE* info, const analysis::CoupledSimulation& r,
                        const std::vector<catenary::PantographOnLine>& train) {
  fmt::print(info, "analysis section {:g} … {:g} m (EN 50317 quantities; filtered: zero-phase 4th-order Butterworth "
                   "low-pass at 20 Hz)\n",
             r.section.from, r.section.to);
  fmt::print(info, "  {:<22} {:>8} {:>8} {:>10} {:>10} {:>8} {:>8} {:>7}\n", "pantograph", "mean N", "std N",
             "Fm+3s N", "Fm-3s N", "max N", "min N", "loss %");
  for (std::size_t k = 0; k < r.quality.size(); ++k) {
    const auto& q = r.quality[k];
    const std::string who = fmt::format("{} (x0 = {:g} m)", k + 1, train[k].x0);
    for (int f = 0; f < 2; ++f) {
      const analysis::ContactStatistics& c = f == 0 ? q.raw : q.filtered;
      fmt::print(info, "  {:<22} {:8.2f} {:8.2f} {:10.2f} {:10.2f} {:8.2f} {:8.2f} {:7.2f}\n",
                 f == 0 ? who + " raw" : std::string(who.size(), ' ') + " 20 Hz", c.mean, c.std, c.stat_max,
                 c.stat_min, c.max, c.min, f == 0 ? q.loss_pct : c.loss_pct);
    }
    const auto& cs = r.contacts[k];
    if (cs.lost_samples > 0)
      fmt::print(info, "  pantograph {}: contact lost in {} samples over the run; first at t = {:.6g} s, x = {:.6g} m\n",
                 k + 1, cs.lost_samples, cs.first_loss_t, cs.first_loss_x);
  }
  if (!r.overlap_quality.empty()) {  // a line of tension sections: the overlap spans alone (issue 35)
    std::string where;
    for (const auto& p : r.overlaps) where += fmt::format("{}{:g} … {:g}", where.empty() ? "" : ", ", p.from, p.to);
    fmt::print(info, "overlap spans in the section ({} m; two contact wires, the force their sum):\n", where);
    for (std::size_t k = 0; k < r.overlap_quality.size(); ++k) {
      const std::string who = fmt::format("{} (x0 = {:g} m)", k + 1, train[k].x0);
      for (int f = 0; f < 2; ++f) {
        const analysis::ContactStatistics& c = f == 0 ? r.overlap_quality[k].raw : r.overlap_quality[k].filtered;
        fmt::print(info, "  {:<22} {:8.2f} {:8.2f} {:10.2f} {:10.2f} {:8.2f} {:8.2f} {:7.2f}\n",
                   f == 0 ? who + " raw" : std::string(who.size(), ' ') + " 20 Hz", c.mean, c.std, c.stat_max, c.stat_min,
                   c.max, c.min, c.loss_pct);
      }
    }
  }
  if (r.uplift.empty()) {  // issue 38: not "max 0 mm at x = 0 m", a support outside the section
    fmt::print(info, "support uplift in the section: no support in the section (a line of one span has none)\n");
    return;
  }
  double worst = r.uplift.front().max_uplift, x_worst = r.uplift.front().x;
  for (const auto& u : r.uplift)
    if (u.max_uplift > worst) worst = u.max_uplift, x_worst = u.x;
  fmt::print(info, "support uplift in the section: max {:.2f} mm at the support x = {:g} m ({} supports)\n",
             1e3 * worst, x_worst, r.uplift.size());
}

std::string line_file_stem(const std::string& out) {
  return out.size() > 4 && out.ends_with(".csv") ? out.substr(0, out.size() - 4) : out;
}

// Beside OUT.csv: OUT.supports.csv (uplift of every support over time) and OUT.psd.csv (PSD of each
// pantograph's contact force in the section).
void write_line_files(std::FILE* info, const std::string& out, const analysis::CoupledSimulation& r) {
  const std::string stem = line_file_stem(out);
  {
    OutputFile f(stem + ".supports.csv");
    std::vector<const analysis::TimeHistory*> hs{&r.supports};
    write_csv(f.get(), hs, {""});
    f.commit();
  }
  OutputFile f(stem + ".psd.csv");
  std::string line = "f";
  for (std::size_t k = 0; k < r.quality.size(); ++k) line += fmt::format(",S_p{}", k + 1);
  line += '\n';
  std::fputs(line.c_str(), f.get());
  const std::size_t n = r.quality.front().psd.f.size();
  for (std::size_t i = 0; i < n; ++i) {
    line.clear();
    append_number(line, r.quality.front().psd.f[i]);
    for (const auto& q : r.quality) {
      line += ',';
      append_number(line, i < q.psd.S.size() ? q.psd.S[i] : NAN);
    }
    line += '\n';
    std::fputs(line.c_str(), f.get());
  }
  f.commit();
  fmt::print(info, "wrote {0}.supports.csv (support uplift, m) and {0}.psd.csv (contact-force PSD, N²/Hz)\n", stem);
}
int cmd_simulate(const SimulateArgs& a) {
  solve::IntegratorOptions opt;
  opt.method = solve::parse_method(a.integrator);
  opt.rtol = a.rtol;
  opt.atol = a.atol;
  opt.max_step = a.max_step;
  std::FILE* info = a.out.empty() ? stderr : stdout;  // keep a CSV on stdout clean
  OutputFile file(a.out, {a.model, a.cat.catenary});  // checked before the run; complete only once committed
  const bool show_progress = isatty(STDERR_FILENO) && a.out.size() > 0;
  auto progress = [&](double t, double t_end) {
    if (show_progress) fmt::print(stderr, "\r  t = {:.4g} / {:.4g} s ({:3.0f} %)", t, t_end, 100 * t / t_end);
  };
  auto clear_progress = [&] {
    if (show_progress) fmt::print(stderr, "\r{:60}\r", "");
  };
  auto run_line = [&](const std::string& name, double t_end, const solve::RunStats& st, bool centripetal) {
    fmt::print(info,
               "simulated {} to t = {:g} s: {} steps, {} RHS evaluations, wall {:.3f} s, "
               "max constraint violation {:.3g} (velocity {:.3g}); integrator {}, rtol {:g}, atol {:g}, centripetal {}\n",
               name, t_end, st.steps, st.rhs_evals, st.wall_s, st.max_violation, st.max_velocity_violation,
               solve::method_name(opt.method), opt.rtol, opt.atol, centripetal ? "on" : "off");
  };

  if (!a.cat.catenary.empty()) {
    // Pantographs under a catenary: from the coupled static equilibrium (no start-up jolt).
    if (!(a.speed > 0)) throw CLI::ValidationError("--speed", "a run under a catenary needs --speed > 0");
    std::optional<analysis::AcceptanceCriteria> criteria;
    if (!a.acceptance.criteria.empty()) criteria = io::load_acceptance(a.acceptance.criteria);
    io::check_output_path(cli::acceptance_path(a.out), {a.model, a.cat.catenary, a.out});
    io::check_output_path(a.report, {a.model, a.cat.catenary, a.out});
    const double v = to_ms(a.speed, a.cat.unit);
    const std::vector<double> x0s = a.positions.empty() ? std::vector<double>{0.0} : parse_positions(a.positions);
    auto [panto, cat] = pantograph_setup(a.model, a.cat, a.no_centripetal,
                                         [&](const pantograph::Pantograph& p, const io::CatenaryFile& c) {
                                           analysis::check_run_speed(*c.catenary, v, a.t_end > 0 ? 0 : a.spans,
                                                                     a.cat.allow_supercritical);
                                           if (const std::string w = analysis::speed_warning(*c.catenary, v); !w.empty())
                                             fmt::print(stderr, "{}\n", w);
                                           std::vector<catenary::PantographOnLine> tr;
                                           for (double x0 : x0s) tr.push_back({p, x0, c.contact});
                                           // a point model's run: --spans spans unless --t-end is given
                                           const double t_run = a.t_end > 0 || std::isfinite(c.catenary->line_length())
                                                                    ? a.t_end
                                                                    : a.spans * c.catenary->span() / v;
                                           cost_guard(c.catenary->estimated_seconds(tr, v, t_run),
                                                      c.catenary->estimated_bytes(tr, v, a.t_end), a.max_seconds,
                                                      "this run",
                                                      std::isfinite(c.catenary->line_length())
                                                          ? std::string(kFeCheaper) + ", or a shorter --t-end"
                                                          : std::string("a higher --speed, fewer --spans or a shorter --t-end"));
                                         });
    for (const auto& note : panto.model.notes) fmt::print(info, "note: {}\n", note);
    if (!a.out.empty())  // every input is read now (the line's CSV files too): no output may replace one
      for (const std::string& o : {a.out, cli::acceptance_path(a.out), line_file_stem(a.out) + ".supports.csv",
                                   line_file_stem(a.out) + ".psd.csv"})
        io::check_output_path(o);
    io::check_output_path(a.report);
    std::vector<catenary::PantographOnLine> train;
    for (double x0 : x0s) train.push_back({panto, x0, cat.contact});
    analysis::CoupledOptions co;
    co.spans = a.spans;
    co.t_end = a.t_end;
    co.sample = a.sample;
    co.integrator = opt;
    if (criteria) co.filter_cutoff = criteria->filter_cutoff, co.filter_order = criteria->filter_order;
    co.allow_supercritical = a.cat.allow_supercritical;
    const analysis::CoupledSimulation r = analysis::simulate_coupled(train, *cat.catenary, v, co, progress);
    clear_progress();
    std::vector<const analysis::TimeHistory*> hs;
    std::vector<std::string> prefixes;
    for (std::size_t k = 0; k < r.histories.size(); ++k)
      hs.push_back(&r.histories[k]), prefixes.push_back(train.size() > 1 ? fmt::format("p{}.", k + 1) : "");
    write_csv(file.get(), hs, prefixes);
    file.commit();
    run_line(panto.model.name, r.t_end, r.stats, panto.model.options.centripetal);
    fmt::print(info, "catenary: {}; {} contact, v = {:.4g} km/h\n", cat.catenary->describe(),
               catenary::kind_name(cat.contact.kind), v * 3.6);
    if (a.steady_from >= 0)
      for (std::size_t k = 0; k < r.histories.size(); ++k)
        print_steady(info, a.steady_from, analysis::summarise(r.histories[k], a.steady_from), prefixes[k]);
    if (!r.quality.empty()) {
      print_line_outputs(info, r, train);
      if (!a.out.empty()) write_line_files(info, a.out, r);
    }
    for (std::size_t k = 0; k < r.contacts.size() && r.quality.empty(); ++k) {
      const auto& c = r.contacts[k];
      const analysis::ContactStatistics& cs = c.stats;
      fmt::print(info,
                 "{}contact force over the last {} spans (t >= {:.4g} s): mean {:.2f} N, std {:.2f} N, max {:.2f} N, "
                 "min {:.2f} N, mean ± 3σ {:.2f} / {:.2f} N, contact loss {:.2f} %\n",
                 train.size() > 1 ? fmt::format("pantograph {} (x0 = {:g} m): ", k + 1, train[k].x0) : "",
                 co.window_spans, r.window_from, cs.mean, cs.std, cs.max, cs.min, cs.stat_max, cs.stat_min,
                 cs.loss_pct);
      if (c.lost_samples > 0)
        fmt::print(info, "  contact lost in {} of {} samples; first at t = {:.6g} s, x = {:.6g} m along the line\n",
                   c.lost_samples, r.histories[k].t.size(), c.first_loss_t, c.first_loss_x);
    }
    if (!a.out.empty()) fmt::print(info, "wrote {}\n", a.out);
    std::vector<analysis::VerdictRow> verdict;
    if (criteria) verdict = analysis::verdict(*criteria, r);
    const int code = criteria ? cli::report_acceptance(info, *criteria, verdict, a.out, a.acceptance.strict, a.cat.unit == "kmh") : 0;
    if (!a.report.empty()) {
      const report::RunContext ctx = line_run_context(
          a.model, a.cat, *cat.catenary, criteria ? &*criteria : nullptr, verdict,
          {{"integrator", fmt::format("{} (rtol {:g}, atol {:g}, max step {:g} s)", solve::method_name(opt.method), opt.rtol,
                                      opt.atol, opt.max_step)},
           {"pantographs at x0, m", fmt::format("{}", fmt::join(x0s, ", "))}});
      report::Record record;
      write_report(a.report, report::simulate_report(ctx, r, cat.catenary->features(), record));
    }
    return code;
  }
  if (!a.acceptance.criteria.empty()) throw CLI::ValidationError("--acceptance", "needs --catenary FILE");
  if (!a.report.empty()) throw CLI::ValidationError("--report", "needs --catenary FILE (a report of a run under a line)");
  if (a.speed > 0) throw CLI::ValidationError("--speed", "needs --catenary FILE");
  if (!a.positions.empty()) throw CLI::ValidationError("--positions", "needs --catenary FILE");
  mbs::Model model = io::load_model(a.model, a.cat.sets);
  if (a.no_centripetal) model.options.centripetal = false;
  for (const auto& note : model.notes) fmt::print(info, "note: {}\n", note);
  analysis::SimulateOptions so;
  so.t_end = a.t_end;
  so.sample = a.sample;
  so.integrator = opt;
  so.from_equilibrium = a.from_equilibrium;
  so.steady_from = a.steady_from;
  const analysis::Simulation r = analysis::simulate(model, so, progress);
  clear_progress();
  if (r.assembly.initial_residual > 1e-9) print_assembly(info, model, r.assembly);
  if (r.equilibrium) {
    fmt::print(info, "static equilibrium: {} iteration(s)", r.equilibrium->iterations);
    if (r.equilibrium->max_move > 0)
      fmt::print(info, ", largest move {:.4g} on {}", r.equilibrium->max_move, model.coord_name(r.equilibrium->largest));
    fmt::print(info, "\n");
  }
  write_csv(file.get(), {&r.history}, {""});
  file.commit();
  run_line(model.name, r.t_end, r.stats, model.options.centripetal);
  print_steady(info, a.steady_from, r.steady);
  if (!a.out.empty()) fmt::print(info, "wrote {}\n", a.out);
  return 0;
}

SimulateArgs sa;

}  // namespace
}  // namespace simulate_command

Command add_simulate_command(CLI::App& app) {
  using namespace simulate_command;
  auto* sim = app.add_subcommand("simulate", "Time simulation; writes a CSV of the model's outputs");
  sim->add_option("model", sa.model, "Model file (YAML)")->required();
  sim->add_option("--t-end", sa.t_end, "End time, s (default: options.t_end of the model)")->check(number_rule(analysis::t_end_rule));
  sim->add_option("--sample", sa.sample, "Output sampling interval, s (default: options.sample)")->check(number_rule(analysis::sample_rule));
  sim->add_option("--out", sa.out, "CSV file to write (default: standard output)");
  sim->add_flag("--no-centripetal", sa.no_centripetal, "Switch off the inerter centripetal correction (eq. 3.8)");
  sim->add_option("--rtol", sa.rtol, "Relative tolerance")->capture_default_str()->check(number_rule(solve::rtol_rule));
  sim->add_option("--atol", sa.atol, "Absolute tolerance (m, rad, m/s, rad/s)")->capture_default_str()->check(number_rule(solve::atol_rule));
  sim->add_option("--integrator", sa.integrator, "rk (explicit Dormand-Prince) or bdf (CVODE BDF, stiff)")
      ->check(CLI::IsMember({"rk", "bdf"}))
      ->capture_default_str();
  sim->add_option("--max-step", sa.max_step, "Largest integrator step, s (0 = unlimited)")->check(number_rule(solve::max_step_rule));
  sim->add_flag("--from-equilibrium", sa.from_equilibrium, "Start from the static equilibrium under all loads");
  sim->add_option("--steady-from", sa.steady_from, "Print min/max/peak-to-peak/mean of every output for t >= T")
      ->check(number_in(0, 1e7, ">= 0 s"));
  add_catenary_options(sim, sa.cat, false);
  sim->add_option("--speed", sa.speed, "Train speed (with --catenary), in --unit")->check(number_in(0, 1e4, "0 … 1e4"));
  sim->add_option("--spans", sa.spans, "Spans to simulate under a catenary (t_end = spans · L / v)")
      ->capture_default_str()
      ->check(count_rule(analysis::spans_rule));
  sim->add_option("--positions", sa.positions,
                  "Several pantographs (copies of the model) at these positions along the line, m, e.g. 0,200")
      ->check(CLI::Validator(
          [](std::string& v) {
            return v.empty() ? std::string("empty; expected comma-separated positions in m, e.g. 0,200") : std::string();
          },
          "X,..."));
  cli::add_acceptance_options(sim, sa.acceptance);
  add_report_option(sim, sa.report);
  sim->add_option("--max-seconds", sa.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));
  return {sim, [] { return cmd_simulate(sa); }};
}

}  // namespace inerta::cli
