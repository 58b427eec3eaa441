// `inerta catenary fit | check-reduction` and `inerta catenary-response` (docs/cli.md).
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "report.hpp"
#include "inerta/report/run_reports.hpp"
#include "acceptance.hpp"

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
#include "inerta/io/data_dir.hpp"
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
#include "inerta/solve/integrator.hpp"

namespace inerta::cli {

namespace catenary_command {
namespace {

struct FitArgs {
  std::string catenary, out, table;
  int span = 0;
  std::vector<std::string> sets;
  double max_seconds = analysis::default_max_seconds;
};

// The lumped catenary of eq. 7.1 from a finite-element one (catenary::fit_lumped).
int cmd_catenary_fit(const FitArgs& a) {
  io::check_output_path(a.out, {a.catenary});
  io::check_output_path(a.table, {a.catenary, a.out});
  if (a.table == a.out) throw InvalidArgument(fmt::format("--table and --out are both '{}'; give two file names", a.out));
  const catenary::FeCatenaryData d = io::read_fe_catenary_data(a.catenary, a.sets);
  const io::CatenaryFile file = io::read_catenary_file(a.catenary, a.sets);
  // Building the line, then 220 static solves along one span (about as much again).
  {
    catenary::FeCatenaryData direct = d;
    direct.solver = catenary::FeCatenaryData::Solver::Direct;
    const catenary::FeCostEstimate e = catenary::estimate_cost(direct, {}, 1.0, d.time_step);
    cost_guard(2 * e.setup, e.bytes, a.max_seconds, "this fit", kFeCheaper);
  }
  const catenary::FeLine line(d);
  const catenary::LumpedFit fit = catenary::fit_lumped(line, a.span);
  const catenary::LumpedCatenary& c = fit.lumped;
  fmt::print("{}\n", line.describe());
  // Form-finding of the fitted span: dropper lengths and tensions, against the file's nominal lengths.
  fmt::print("form-finding, span {}: dropper x (m), unstretched length (m){}, static tension (N)\n", fit.span,
             d.nominal_dropper_length.empty() ? "" : " [nominal]");
  for (const auto& dr : line.droppers()) {
    if (dr.x < (fit.span - 1) * d.span || dr.x > fit.span * d.span) continue;
    const bool span_dropper = dr.kind == catenary::FeLine::Dropper::Kind::Span;
    const auto j = static_cast<std::size_t>(dr.index);
    fmt::print("  {:7.2f}  {:.4f}{}  {:7.2f}{}\n", dr.x, dr.length,
               d.nominal_dropper_length.empty() ? ""
               : span_dropper                   ? fmt::format(" [{:.3f}]", d.nominal_dropper_length[j])
                                                : std::string(" [  -  ]"),
               dr.tension, span_dropper ? "" : dr.on_stitch_wire ? "  (stitch dropper, on the stitch wire)" : "  (stitch dropper, on the messenger)");
  }
  fmt::print("fitted span {} ({:g} … {:g} m): elasticity {:.3f} … {:.3f} mm/N\n", fit.span, (fit.span - 1) * d.span,
             fit.span * d.span, 1e3 * *std::min_element(fit.elasticity.begin(), fit.elasticity.end()),
             1e3 * *std::max_element(fit.elasticity.begin(), fit.elasticity.end()));
  fmt::print("  k_c = [{:.5g}, {:.5g}, {:.5g}, {:.5g}] N/m\n  m_c = [{:.5g}, {:.5g}, {:.5g}, {:.5g}] kg\n"
             "  c_c = [{:.5g}, {:.5g}, {:.5g}, {:.5g}] N·s/m\n",
             c.k[0], c.k[1], c.k[2], c.k[3], c.m[0], c.m[1], c.m[2], c.m[3], c.c[0], c.c[1], c.c[2], c.c[3]);
  fmt::print("  natural frequency (1/2π) sqrt(k_c0/m_c0) = {:.3f} Hz\n", c.natural_frequency());
  fmt::print("  elasticity fit: max {:.1f} %, rms {:.1f} %; over one dropper spacing: max {:.1f} %, rms {:.1f} %\n",
             100 * fit.max_elasticity_error, 100 * fit.rms_error, 100 * fit.max_smoothed_error,
             100 * fit.rms_smoothed_error);
  io::write_lumped_catenary(a.out, fit, file.contact, a.catenary);
  fmt::print("wrote {}\n", a.out);
  if (!a.table.empty()) io::write_fit_table(a.table, fit), fmt::print("wrote {}\n", a.table);
  return 0;
}

struct CheckReductionArgs {
  std::string model, speeds;  ///< model: default the bundled 3-mass (io::data_dir())
  CatenaryArgs cat;
  double tolerance = 1.0;
  std::string acceptance;
  double max_seconds = analysis::default_max_seconds;
  std::string report;  ///< --report FILE.html
};

// The finite-element line's modal solve against its direct solve (docs/catenary-fe.md "Modal solver"):
// the same runs on both, the EN 50317 statistics side by side; exit 1 if σ (raw or 20 Hz) differs by
// more than --tolerance %.
int cmd_check_reduction(CheckReductionArgs a) {
  if (a.model.empty()) a.model = (io::data_dir() / "models" / "pantograph-3mass.yaml").string();
  std::vector<double> v;
  if (a.speeds.find(':') == std::string::npos) a.speeds += ":1:" + a.speeds;  // one speed
  for (double s : frequency_range(a.speeds, "--speeds")) {
    if (const std::string e = analysis::speed_rule.check(s, fmt::format("{:g}", s)); !e.empty())
      throw CLI::ValidationError("--speeds", e);  // the library's rule (Python's speeds)
    v.push_back(to_ms(s, a.cat.unit));
  }
  const io::CatenaryFile probe = io::read_catenary_file(a.cat.catenary, io::split_overrides(a.model, a.cat.sets).second);
  if (!probe.fe) throw ModelError(fmt::format("{}: check-reduction needs a finite-element catenary (type: finite_element)", a.cat.catenary));
  std::optional<analysis::AcceptanceCriteria> criteria;
  if (!a.acceptance.empty()) criteria = io::load_acceptance(a.acceptance);
  io::check_output_path(a.report, {a.model, a.cat.catenary});
  {  // both solves at every speed, each line built and (modal) decomposed once
    double total = 0, bytes = 0;
    for (const auto solver : {catenary::FeCatenaryData::Solver::Direct, catenary::FeCatenaryData::Solver::Modal}) {
      catenary::FeCatenaryData d = *probe.fe;
      d.solver = solver;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const catenary::FeCostEstimate e = catenary::estimate_cost(d, {0.0}, v[i], -1, i == 0, i == 0);
        total += e.total();
        bytes = std::max(bytes, e.bytes);
      }
    }
    cost_guard(total, bytes, a.max_seconds, fmt::format("this comparison at {} speed(s)", v.size()),
               "fewer spans with --set line.spans=N, a coarser mesh with mesh.element_length, or fewer --speeds");
  }
  CatenaryArgs direct = a.cat, modal = a.cat;
  direct.sets.push_back("solver.type=direct");
  modal.sets.push_back("solver.type=modal");
  auto [panto, ref] = pantograph_setup(a.model, direct);
  auto [panto2, cand] = pantograph_setup(a.model, modal);
  fmt::print("reference: {}\ncandidate: {}\n", ref.catenary->describe(), cand.catenary->describe());
  const std::vector<catenary::PantographOnLine> train{{panto, 0.0, ref.contact}};
  analysis::RunOptions ro;
  if (criteria) ro.filter_cutoff = criteria->filter_cutoff, ro.filter_order = criteria->filter_order;
  const auto rows = analysis::compare(train, *ref.catenary, *cand.catenary, v, ro);
  auto pct = [](double a_, double b_) { return a_ != 0 ? 100 * (b_ - a_) / std::abs(a_) : 0.0; };
  double worst = 0;
  for (const auto& r : rows) {
    const auto &d = r.reference, &m = r.candidate;
    const double up_d = d.support_uplift.empty() ? 0 : *std::max_element(d.support_uplift.begin(), d.support_uplift.end());
    const double up_m = m.support_uplift.empty() ? 0 : *std::max_element(m.support_uplift.begin(), m.support_uplift.end());
    fmt::print("\nv = {:.4g} {} (analysis section, EN 50317)\n  {:<16}{:>12}{:>12}{:>10}\n", a.cat.unit == "kmh" ? r.speed * 3.6 : r.speed,
               a.cat.unit == "kmh" ? "km/h" : "m/s", "quantity", "direct", "modal", "diff");
    // The difference relative to the direct solve (%), or where that means little in the quantity's own
    // unit: the minimum force (near 0 N) in N, the contact loss (a share) in percentage points.
    auto row = [&](const char* q, double x, double y, const char* unit = "%") {
      const double diff = std::string(unit) == "%" ? pct(x, y) : y - x;
      fmt::print("  {:<16}{:>12.4f}{:>12.4f}{:>+10.3f} {}\n", q, x, y, diff, unit);
    };
    row("mean N", d.stats.mean, m.stats.mean);
    row("sigma N", d.stats.std, m.stats.std);
    row("sigma 20 Hz N", d.filtered[0].std, m.filtered[0].std);
    row("max N", d.stats.max, m.stats.max);
    row("min N", d.stats.min, m.stats.min, "N");
    row("min 20 Hz N", d.filtered[0].min, m.filtered[0].min, "N");
    row("loss %", d.stats.loss_pct, m.stats.loss_pct, "pp");
    row("uplift max mm", 1e3 * up_d, 1e3 * up_m);
    row("wall s", r.reference_s, r.candidate_s);
    // Where the two solves lose contact differently (the leading pantograph, x = v t from x0 = 0).
    if (const auto diffs = analysis::loss_differences(d, m); !diffs.empty()) {
      std::vector<std::string> where;
      const catenary::Section sec = ref.catenary->section();
      for (std::size_t k = 0; k < diffs.size() && k < 6; ++k) {
        const auto& e = diffs[k];
        const double x0 = r.speed * e.t_from, x1 = r.speed * e.t_to;
        where.push_back(fmt::format("{} only at x = {}{}", e.candidate ? "modal" : "direct",
                                    e.t_to > e.t_from ? fmt::format("{:.2f}–{:.2f} m (t = {:.4f}–{:.4f} s)", x0, x1, e.t_from, e.t_to)
                                                      : fmt::format("{:.2f} m (t = {:.4f} s)", x0, e.t_from),
                                    x1 >= sec.from && x0 <= sec.to ? ", in the section" : ""));
      }
      fmt::print("  contact loss differs in {} place{} over the run: {}{}\n", diffs.size(), diffs.size() > 1 ? "s" : "",
                 fmt::join(where, "; "), diffs.size() > 6 ? "; …" : "");
    }
    worst = std::max({worst, std::abs(pct(d.stats.std, m.stats.std)), std::abs(pct(d.filtered[0].std, m.filtered[0].std))});
    if (criteria) {  // the same verdict from both solves? (reported; the exit code stays the σ tolerance's)
      const auto vd = analysis::verdict(*criteria, std::vector<analysis::SpeedResult>{d});
      const auto vm = analysis::verdict(*criteria, std::vector<analysis::SpeedResult>{m});
      std::vector<std::string> differ;
      for (std::size_t i = 0; i < vd.size() && i < vm.size(); ++i)
        if (io::status_text(vd[i].result) != std::string(io::status_text(vm[i].result)))
          differ.push_back(fmt::format("{} (direct {} {:.4g}, modal {} {:.4g})", vd[i].result.criterion, io::status_text(vd[i].result),
                                       vd[i].result.value, io::status_text(vm[i].result), vm[i].result.value));
      fmt::print("  acceptance {}: direct {}, modal {}{}\n", criteria->name, analysis::judge(vd).text(),
                 analysis::judge(vm).text(),
                 differ.empty() ? "; every criterion the same" : fmt::format("; criteria that differ: {}", fmt::join(differ, "; ")));
    }
  }
  fmt::print("\nlargest difference of sigma (raw or 20 Hz): {:.3f} % (tolerance {:g} %)\n", worst, a.tolerance);
  if (!a.report.empty()) {
    report::RunContext ctx = line_run_context(a.model, a.cat, *cand.catenary, criteria ? &*criteria : nullptr, {},
                                              {{"reference", "direct solve (solver.type=direct)"},
                                               {"candidate", "modal solve (solver.type=modal)"}});
    std::vector<analysis::VerdictRow> vm;
    if (criteria) {
      for (const auto& r : rows) {
        auto d = analysis::verdict(*criteria, std::vector<analysis::SpeedResult>{r.reference});
        auto m = analysis::verdict(*criteria, std::vector<analysis::SpeedResult>{r.candidate});
        ctx.verdict.insert(ctx.verdict.end(), d.begin(), d.end());
        vm.insert(vm.end(), m.begin(), m.end());
      }
    }
    report::Record record;
    write_report(a.report, report::reduction_report(ctx, rows, vm, a.tolerance, record));
  }
  if (worst > a.tolerance) {
    fmt::print(stderr, "check-reduction: the modal solve differs from the direct one by {:.3f} % in sigma, more than "
                       "--tolerance {:g} %: raise solver.cutoff or the window (solver.window_behind / window_ahead)\n",
               worst, a.tolerance);
    return 1;
  }
  return 0;
}

struct CatenaryResponseArgs {
  std::string catenary, fp, out;
  std::vector<std::string> sets;
  double force = 70;
};

int cmd_catenary_response(const CatenaryResponseArgs& a) {
  io::check_output_path(a.out, {a.catenary});
  io::CatenaryFile c = io::load_catenary(a.catenary, a.sets);
  const std::vector<double> fp = frequency_range(a.fp, "--fp");
  for (double f : fp)
    if (!(f > 0)) throw CLI::ValidationError("--fp", "pumping frequencies must be > 0");
  const catenary::LumpedCatenary* lumped = c.catenary->point_model();
  if (!lumped)
    throw ModelError(fmt::format("{}: catenary-response analyses the lumped catenary (eq. 7.1); this file is a {}",
                                 a.catenary, c.catenary->describe()));
  auto r = analysis::catenary_response(*lumped, a.force, fp);
  OutputFile file(a.out, {a.catenary});
  fmt::print(file.get(), "fp_hz,v_ms,v_kmh,acc_amplitude,disp_amplitude,mean_uplift,stable\n");
  std::size_t kmax = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    fmt::print(file.get(), "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{}\n", r[k].fp, r[k].speed,
               r[k].speed * 3.6, r[k].acc_amplitude, r[k].disp_amplitude, r[k].mean_uplift, r[k].stable() ? 1 : 0);
    if (r[k].stable() && (!r[kmax].stable() || r[k].acc_amplitude > r[kmax].acc_amplitude)) kmax = k;
  }
  file.commit();
  std::vector<double> unstable;
  for (const auto& x : r)
    if (!x.stable()) unstable.push_back(x.fp);
  std::FILE* info = a.out.empty() ? stderr : stdout;
  fmt::print(info,
             "catenary alone under {:g} N: natural frequency (1/2π)·sqrt(k_c0/m_c0) = {:.4f} Hz; largest steady "
             "acceleration amplitude {:.4g} m/s² at f_p = {:.4g} Hz (v = {:.4g} km/h)\n",
             a.force, lumped->natural_frequency(), r[kmax].acc_amplitude, r[kmax].fp, r[kmax].speed * 3.6);
  if (!unstable.empty())
    fmt::print(info,
               "note: no steady state (the response grows: parametric resonance of the time-varying stiffness) for "
               "f_p = {:.4g} … {:.4g} Hz ({} frequencies, column stable = 0)\n",
               unstable.front(), unstable.back(), unstable.size());
  if (!a.out.empty()) fmt::print(info, "wrote {}\n", a.out);
  return 0;
}

CatenaryResponseArgs ca;
FitArgs fit_args;
CheckReductionArgs cra;

}  // namespace
}  // namespace catenary_command

Command add_catenary_response_command(CLI::App& app) {
  using namespace catenary_command;
  auto* crs = app.add_subcommand("catenary-response",
                                 "Lumped catenary alone under a constant upward force: acceleration amplitude vs f_p");
  crs->add_option("catenary", ca.catenary, "Catenary file (YAML)")->required();
  crs->add_option("--force", ca.force, "Constant upward force, N")->capture_default_str()->check(number_rule(analysis::force_rule));
  crs->add_option("--fp", ca.fp, "Pumping frequencies F0:DF:F1 in Hz (f_p = v / L)")->required();
  crs->add_option("--set", ca.sets, "Override a catenary value (repeatable)");
  crs->add_option("--out", ca.out, "CSV file (default: standard output)");
  return {crs, [] { return cmd_catenary_response(ca); }};
}

Command add_catenary_commands(CLI::App& app) {
  using namespace catenary_command;
  auto* cat_cmd = app.add_subcommand("catenary", "Catenary tools");
  auto* fit = cat_cmd->add_subcommand(
      "fit", "Fit the lumped catenary of eq. 7.1 to a finite-element catenary; write a lumped catenary file");
  fit->add_option("catenary", fit_args.catenary, "Finite-element catenary file (YAML)")->required();
  fit->add_option("--out", fit_args.out, "Lumped catenary file to write (YAML)")->required();
  fit->add_option("--span", fit_args.span, "Span to fit (1-based; default: the middle span)")->check(count_in(0, 100000));
  fit->add_option("--table", fit_args.table, "Also write the fit along the span (CSV: x, elasticity FE/fit, mass, damping)");
  fit->add_option("--set", fit_args.sets, "Override a catenary value (repeatable), e.g. messenger.tension=17000");
  fit->add_option("--max-seconds", fit_args.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));
  auto* crd = cat_cmd->add_subcommand(
      "check-reduction", "Run the finite-element line's modal and direct solves side by side and compare the statistics");
  crd->add_option("catenary", cra.cat.catenary, "Finite-element catenary file (YAML)")->required();
  crd->add_option("--model", cra.model, "Pantograph model file (default: the bundled 3-mass DSA 380)");
  auto* crd_speed = crd->add_option("--speed,--speeds", cra.speeds, "Speed V or speeds V0:DV:V1 in --unit")->required();
  (void)crd_speed;
  crd->add_option("--unit", cra.cat.unit, "Speed unit: ms (m/s) or kmh")->check(CLI::IsMember({"ms", "kmh"}))->capture_default_str();
  crd->add_option("--set", cra.cat.sets, "Override a catenary or model value (repeatable), e.g. solver.cutoff=150");
  crd->add_option("--tolerance", cra.tolerance, "Largest difference of sigma accepted, % (exit 1 beyond)")
      ->capture_default_str()
      ->check(number_in(0, 1e6, "a percentage"));
  crd->add_option("--acceptance", cra.acceptance,
                  "Also say whether both solves reach the same acceptance verdict (a preset or a criteria file)");
  add_report_option(crd, cra.report);
  crd->add_option("--max-seconds", cra.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));
  cat_cmd->require_subcommand(1);
  return {cat_cmd, [fit] { return fit->parsed() ? cmd_catenary_fit(fit_args) : cmd_check_reduction(cra); }};
}

}  // namespace inerta::cli
