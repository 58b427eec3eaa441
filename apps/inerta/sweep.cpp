// `inerta sweep MODEL --catenary … --speeds …` (docs/cli.md): contact-force statistics over speeds.
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
#include "inerta/report/run_reports.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::cli {

namespace sweep_command {
namespace {

// Exit code of a sweep with an unstable periodic solution at some speed (docs/cli.md).
constexpr int exit_unstable = 4;

struct SweepArgs {
  std::string model, out, speeds, integrator = "rk", method = "time";
  int harmonics = 8;
  CatenaryArgs cat;
  double rtol = 1e-6, atol = 1e-8;
  bool no_centripetal = false;
  cli::AcceptanceArgs acceptance;
  double max_seconds = analysis::default_max_seconds;
  std::string report;  ///< --report FILE.html
};

int cmd_sweep(const SweepArgs& a) {
  OutputFile file(a.out, {a.model, a.cat.catenary});  // checked before the sweep
  std::optional<analysis::AcceptanceCriteria> criteria;
  if (!a.acceptance.criteria.empty()) {
    criteria = io::load_acceptance(a.acceptance.criteria);
    io::check_output_path(cli::acceptance_path(a.out), {a.model, a.cat.catenary, a.out});
  }
  io::check_output_path(a.report, {a.model, a.cat.catenary, a.out});
  std::vector<double> v_user = frequency_range(a.speeds, "--speeds"), v;
  for (double s : v_user) {
    if (const std::string e = analysis::speed_rule.check(s, fmt::format("{:g}", s)); !e.empty())
      throw CLI::ValidationError("--speeds", e);  // the library's rule (Python's speeds)
    v.push_back(to_ms(s, a.cat.unit));
  }
  auto [panto, cat] = pantograph_setup(a.model, a.cat, a.no_centripetal,
                                       [&](const pantograph::Pantograph& p, const io::CatenaryFile& c) {
                                         if (a.method == "periodic") return;
                                         for (double s : v)
                                           analysis::check_run_speed(*c.catenary, s, analysis::RunOptions{}.max_spans,
                                                                     a.cat.allow_supercritical);
                                         if (const std::string w = analysis::speed_warning(
                                                 *c.catenary, *std::max_element(v.begin(), v.end()));
                                             !w.empty())
                                           fmt::print(stderr, "{}\n", w);
                                         cost_guard(analysis::estimated_sweep_seconds({{p, 0.0, c.contact}}, *c.catenary, v),
                                                    c.catenary->estimated_bytes({{p, 0.0, c.contact}}, 0, 0), a.max_seconds, fmt::format("this sweep of {} speeds", v.size()),
                                                    std::isfinite(c.catenary->line_length())
                                                        ? std::string(kFeCheaper) + ", or fewer --speeds"
                                                        : std::string("higher or fewer --speeds"));
                                       });
  for (const auto& note : panto.model.notes) fmt::print("note: {}\n", note);
  if (!a.out.empty())  // every input is read now (the line's CSV files too): no output may replace one
    for (const std::string& out : {a.out, cli::acceptance_path(a.out)}) io::check_output_path(out);
  io::check_output_path(a.report);
  analysis::RunOptions o;
  o.integrator.method = solve::parse_method(a.integrator);
  o.integrator.rtol = a.rtol;
  o.integrator.atol = a.atol;
  if (criteria) o.filter_cutoff = criteria->filter_cutoff, o.filter_order = criteria->filter_order;
  o.allow_supercritical = a.cat.allow_supercritical;
  const bool tty = isatty(STDOUT_FILENO);
  const auto wall0 = std::chrono::steady_clock::now();
  fmt::print("sweep: {} speeds, {} contact, {}, suspension {}\n", v.size(), catenary::kind_name(cat.contact.kind),
             cat.catenary->describe(), a.cat.suspension.empty() ? "from the model" : a.cat.suspension);
  std::vector<analysis::SpeedResult> results;
  if (a.method == "periodic")
    results = analysis::sweep_periodic(panto, *cat.catenary, cat.contact, v, a.harmonics);
  else
    results = analysis::sweep(panto, *cat.catenary, cat.contact, v, o, [&](int done, int total) {
      if (!tty) return;
      const int width = 40, filled = width * done / total;
      fmt::print("\r  [{}{}] {}/{} speeds", std::string(static_cast<std::size_t>(filled), '#'),
                 std::string(static_cast<std::size_t>(width - filled), '.'), done, total);
      std::fflush(stdout);
    });
  if (tty) fmt::print("\r{:70}\r", "");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::FILE* out = file.get();
  const bool line = !results.empty() && !results.front().filtered.empty();  // a finite line: EN 50317 columns
  const bool periodic = a.method == "periodic";
  // With --acceptance: the contact loss as the criteria count it (events of at least their minimum duration).
  std::vector<analysis::VerdictRow> verdict;
  if (criteria) verdict = analysis::verdict(*criteria, results);
  const bool counted = criteria && !criteria->contact_loss.empty();
  const bool overlaps = line && !results.front().overlap.empty();  // a line of tension sections (issue 35)
  fmt::print(out, "v_kmh,v_ms,mean,std,max,min,stat_max,stat_min,loss_pct{}{}{}{}\n",
             line ? ",f_mean,f_std,f_max,f_min,f_stat_max,f_stat_min,uplift_max_m" : "",
             overlaps ? ",mean_overlap,std_overlap,max_overlap,min_overlap,stat_max_overlap,stat_min_overlap,loss_pct_overlap,"
                        "f_mean_overlap,f_std_overlap,f_max_overlap,f_min_overlap,f_stat_max_overlap,f_stat_min_overlap"
                      : "",
             periodic ? ",floquet_max,stable" : ",converged", counted ? ",loss_counted_pct" : "");
  std::size_t worst = results.size();
  int spans_max = 0;
  std::vector<std::string> unstable, unsettled;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& s = results[i].stats;
    fmt::print(out, "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g}", v[i] * 3.6, v[i], s.mean, s.std,
               s.max, s.min, s.stat_max, s.stat_min, s.loss_pct);
    if (line) {
      const auto& f = results[i].filtered.front();
      const auto& up = results[i].support_uplift;
      fmt::print(out, ",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", f.mean, f.std, f.max, f.min, f.stat_max,
                 f.stat_min, up.empty() ? 0.0 : *std::max_element(up.begin(), up.end()));
    }
    if (overlaps) {
      const auto& o = results[i].overlap.front();
      const auto& f = results[i].overlap_filtered.front();
      fmt::print(out, ",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", o.mean,
                 o.std, o.max, o.min, o.stat_max, o.stat_min, o.loss_pct, f.mean, f.std, f.max, f.min, f.stat_max, f.stat_min);
    }
    if (periodic)
      fmt::print(out, ",{:.6g},{:d}", results[i].floquet, results[i].stable() ? 1 : 0);
    else
      fmt::print(out, ",{:d}", results[i].converged ? 1 : 0);
    if (counted) {
      double loss = NAN;
      for (const auto& x : verdict)
        if (x.speed == results[i].speed && x.pantograph == 1 && x.result.criterion == "contact_loss") loss = x.result.value;
      fmt::print(out, ",{:.6g}", loss);
    }
    fmt::print(out, "\n");
    const std::string speed = fmt::format("{:g}", a.cat.unit == "kmh" ? v[i] * 3.6 : v[i]);
    if (!results[i].stable()) unstable.push_back(fmt::format("{} (|μ| = {:.4g})", speed, results[i].floquet));
    if (!results[i].converged) unsettled.push_back(speed);
    if (results[i].stable() && (worst == results.size() || s.std > results[worst].stats.std)) worst = i;
    spans_max = std::max(spans_max, results[i].spans);
  }
  file.commit();
  if (!a.out.empty()) fmt::print("wrote {}\n", a.out);
  if (a.method == "periodic")
    fmt::print("wall {:.3f} s; periodic steady state by harmonic balance ({} harmonics of the pumping frequency)\n",
               wall, a.harmonics);
  else if (line)
    fmt::print("wall {:.2f} s; one pass along the line, statistics over its analysis section (raw, and f_*: after "
               "the 20 Hz low-pass); uplift_max_m: the largest support uplift over the run\n",
               wall);
  else
    fmt::print("wall {:.2f} s; statistics over the last 2 spans once σ changed < 0.5 % span to span (up to {} spans)\n",
               wall, spans_max);
  const char* unit = a.cat.unit == "kmh" ? "km/h" : "m/s";
  if (!unsettled.empty())
    fmt::print(stderr,
               "warning: σ did not settle within {} spans at {} {} (converged = 0): those statistics are of the last "
               "{} spans of a run still changing\n",
               o.max_spans, fmt::join(unsettled, ", "), unit, o.window_spans);
  if (worst < results.size())
    fmt::print("sigma_max = {:.3f} N at {:.4g} km/h ({:.4g} m/s); mean contact force there {:.2f} N{}\n",
               results[worst].stats.std, v[worst] * 3.6, v[worst], results[worst].stats.mean,
               unstable.empty() ? "" : " (over the stable speeds)");
  const int verdict_code =
      criteria ? cli::report_acceptance(a.out.empty() ? stderr : stdout, *criteria, verdict, a.out, a.acceptance.strict, a.cat.unit == "kmh") : 0;
  if (!a.report.empty()) {
    const report::RunContext ctx = line_run_context(
        a.model, a.cat, *cat.catenary, criteria ? &*criteria : nullptr, verdict,
        {{"method", periodic ? fmt::format("periodic, {} harmonics", a.harmonics)
                             : fmt::format("time ({} integrator, rtol {:g}, atol {:g})", a.integrator, a.rtol, a.atol)}});
    report::Record record;
    write_report(a.report, report::sweep_report(ctx, results, record));
  }
  if (!unstable.empty()) {
    fmt::print(stderr,
               "unstable: the periodic solution is unstable at {} {} (largest Floquet multiplier ≥ 1: parametric "
               "resonance, the response grows; stable = 0, statistics NaN); run those speeds with --method time\n",
               fmt::join(unstable, ", "), unit);
    return exit_unstable;
  }
  return verdict_code;
}

SweepArgs wa;

}  // namespace
}  // namespace sweep_command

Command add_sweep_command(CLI::App& app) {
  using namespace sweep_command;
  auto* swp = app.add_subcommand("sweep", "Contact-force statistics over a range of speeds under a catenary (CSV)");
  swp->add_option("model", wa.model, "Pantograph model file (YAML)")->required();
  swp->add_option("--speeds", wa.speeds, "Speeds V0:DV:V1 in --unit")->required();
  swp->add_option("--out", wa.out, "CSV file (default: standard output)");
  add_catenary_options(swp, wa.cat, true);
  swp->add_option("--integrator", wa.integrator, "rk or bdf")
      ->check(CLI::IsMember({"rk", "bdf"}))
      ->capture_default_str();
  swp->add_option("--rtol", wa.rtol, "Relative tolerance")->capture_default_str()->check(number_rule(solve::rtol_rule));
  swp->add_option("--atol", wa.atol, "Absolute tolerance")->capture_default_str()->check(number_rule(solve::atol_rule));
  swp->add_flag("--no-centripetal", wa.no_centripetal, "Switch off the inerter centripetal correction");
  swp->add_option("--method", wa.method, "time (simulation, the reference) or periodic (harmonic balance, fast)")
      ->check(CLI::IsMember({"time", "periodic"}))
      ->capture_default_str();
  swp->add_option("--harmonics", wa.harmonics, "Periodic method: harmonics of the pumping frequency")
      ->capture_default_str()
      ->check(count_rule(analysis::harmonics_rule));
  cli::add_acceptance_options(swp, wa.acceptance);
  add_report_option(swp, wa.report);
  swp->add_option("--max-seconds", wa.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));
  return {swp, [] { return cmd_sweep(wa); }};
}

}  // namespace inerta::cli
