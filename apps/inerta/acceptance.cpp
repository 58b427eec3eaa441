// The acceptance verdict in the CLI and `inerta pantograph aero-fit` (docs/cli.md).
#include "acceptance.hpp"

#include "common.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "checks.hpp"
#include "inerta/analysis/aero_fit.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/file_kind.hpp"
#include "inerta/io/model_file.hpp"

namespace inerta::cli {

void add_acceptance_options(CLI::App* app, AcceptanceArgs& a) {
  CLI::Option* acc =
      app->add_option("--acceptance", a.criteria,
                      "Judge the run by an acceptance criteria set: a preset (en50367-ac, en50367-ac15, en50367-dc3, en50367-dc1.5) or a criteria file "
                      "(docs/contact-quality.md); prints the verdict and writes OUT.acceptance.csv")
          ->check(CLI::Validator(
              [](std::string& s) {
                return s.empty() ? std::string("an empty name: give a preset (en50367-ac, en50367-ac15, en50367-dc3, en50367-dc1.5) or a criteria file")
                                 : std::string();
              },
              "PRESET|FILE"));
  app->add_flag("--strict", a.strict,
                "With --acceptance: exit 6 unless the verdict is PASS (a criterion failed, or nothing could be assessed; "
                "default: a report, exit 0)")
      ->needs(acc);
}

std::string acceptance_path(const std::string& out) {
  if (out.empty()) return "";
  const std::string stem = out.size() > 4 && out.ends_with(".csv") ? out.substr(0, out.size() - 4) : out;
  return stem + ".acceptance.csv";
}

namespace {
// A value in the unit a reader expects: uplift in mm, forces in N, loss in %.
std::string shown(const analysis::CriterionResult& r, double x) {
  if (std::isnan(x)) return "-";
  if (r.unit == "m") return fmt::format("{:.1f} mm", 1e3 * x);
  if (r.unit == "%") return fmt::format("{:.3f} %", x);
  return fmt::format("{:.2f} N", x);
}
}  // namespace

int report_acceptance(std::FILE* info, const analysis::AcceptanceCriteria& c, const std::vector<analysis::VerdictRow>& rows,
                      const std::string& out, bool strict, bool kmh) {
  fmt::print(info, "\nacceptance: {} ({}); force statistics over the analysis section, filtered: {:g} Hz low-pass of order {}\n",
             c.name, c.source, c.filter_cutoff, c.filter_order);
  const char* unit = kmh ? "km/h" : "m/s";
  fmt::print(info, "  {:>8} {:>5}  {:<26} {:>12} {:>12} {:>12}  {}\n", fmt::format("v {}", unit), "panto", "criterion", "value",
             "limit", "margin", "verdict");
  // Each criterion's statistic and source, once (issue 53): [assumed] marks a number not verified publicly.
  struct Sourced {
    std::string criteria, statistic, source;
    bool assumed;
  };
  std::vector<Sourced> sources;
  std::map<std::string, int> failed;  // criterion → rows that failed
  std::vector<std::string> failing_speeds;
  double last = NAN;
  for (const auto& x : rows) {
    const analysis::CriterionResult& r = x.result;
    const double v = kmh ? 3.6 * x.speed : x.speed;
    const bool judged = !r.statistic.empty();  // an entry of the set covers this speed
    fmt::print(info, "  {:>8.4g} {:>5}  {:<26} {:>12} {:>12} {:>12}  {}{}\n", v, x.pantograph,
               r.criterion + (judged && r.assumed ? " [assumed]" : ""), shown(r, r.value), shown(r, r.limit), shown(r, r.margin),
               io::status_text(r), r.note.empty() ? "" : " (" + r.note + ")");
    if (judged) {
      auto same = [&](const Sourced& s) { return s.statistic == r.statistic && s.source == r.source && s.assumed == r.assumed; };
      if (auto it = std::find_if(sources.begin(), sources.end(), same); it == sources.end())
        sources.push_back({r.criterion, r.statistic, r.source, r.assumed});
      else if (it->criteria.find(r.criterion) == std::string::npos)
        it->criteria += ", " + r.criterion;
    }
    if (r.assessed && !r.passed) {
      ++failed[r.criterion];
      if (last != x.speed) failing_speeds.push_back(fmt::format("{:.4g}", v)), last = x.speed;
    }
  }
  if (!sources.empty()) {
    fmt::print(info, "criteria, their statistic and source ([assumed]: not verified against a public source; check it against "
                     "the standard before an approval):\n");
    for (const Sourced& s : sources)
      fmt::print(info, "  {}{} ({}): {}\n", s.criteria, s.assumed ? " [assumed]" : "", s.statistic,
                 s.source.empty() ? "no source given" : s.source);
  }
  if (const std::string arcing = analysis::arcing_text(c); !arcing.empty()) fmt::print(info, "{}\n", arcing);
  const analysis::Verdict verdict = analysis::judge(rows);
  std::vector<std::string> which;
  for (const auto& [k, n] : failed) which.push_back(fmt::format("{} ({} row{})", k, n, n > 1 ? "s" : ""));
  const std::string unassessed =
      verdict.not_assessed.empty() ? "" : fmt::format("; not assessed: {}", fmt::join(verdict.not_assessed, ", "));
  switch (verdict.status) {
    case analysis::Verdict::Status::kPass:
      fmt::print(info, "verdict: PASS ({}){}\n",
                 verdict.not_assessed.empty() ? "every criterion at every speed" : "every assessed criterion at every speed",
                 unassessed);
      break;
    case analysis::Verdict::Status::kFail:
      fmt::print(info, "verdict: FAIL at {} {}: {}{}\n", fmt::join(failing_speeds, ", "), unit, fmt::join(which, ", "), unassessed);
      break;
    case analysis::Verdict::Status::kNotAssessed:
      fmt::print(info, "verdict: NOT ASSESSED (no criterion could be judged on this run: see the notes above){}\n",
                 strict ? "; --strict: exit status 6" : "");
      break;
  }
  if (const std::string path = acceptance_path(out); !path.empty()) {
    io::write_acceptance_csv(path, rows);
    fmt::print(info, "wrote {}\n", path);
  }
  return verdict.pass() || !strict ? 0 : exit_acceptance_failed;
}

// ---- inerta pantograph aero-fit -------------------------------------------------------------------

namespace {

struct AeroFitArgs {
  std::string model, catenary, criteria, unit = "ms", speeds, suspension, working_range = "0.1:0.1";
  double speed = 0, max_seconds = analysis::default_max_seconds;
  std::vector<std::string> sets, params;
};
AeroFitArgs aero_args;
CLI::App* aero_cmd = nullptr;

// "V0:DV:V1" → the speeds, at most 1000 steps (common.hpp's range of --freq).
std::vector<double> speed_list(const std::string& spec) { return frequency_range(spec, "--speeds", {true, 1001}); }

int aero_fit() {
  const AeroFitArgs& a = aero_args;
  const analysis::AcceptanceCriteria c = io::load_acceptance(a.criteria);
  if (!c.has_target)
    throw ModelError(fmt::format("{}: the criteria set '{}' has no mean-force 'target' curve; aero-fit needs one", c.source, c.name));
  const auto [panto_sets, cat_sets] = io::split_overrides(a.model, a.sets);
  const pantograph::Pantograph p = io::load_pantograph(a.model, panto_sets);
  const io::CatenaryFile cat = io::load_catenary(a.catenary, cat_sets);
  const double k = a.unit == "kmh" ? 1 / 3.6 : 1.0;  // to m/s
  if (!c.target.covers(a.speed * k * 3.6))  // the curve's source gives it over its speeds only (issue 53)
    throw ModelError(fmt::format("{}: the mean-force target of '{}' at {:.4g} km/h: not assessed; its source gives it {} only",
                                 c.source, c.name, a.speed * k * 3.6, analysis::range_text(c.target.speeds)));
  const double v = a.speed * k, target = c.target.at(v * 3.6);
  // A point model (lumped line, wire profile) has no 20 Hz statistics: its raw mean is used (and said).
  const analysis::Statistics stats = c.mean.empty() || !std::isfinite(cat.catenary->line_length())
                                         ? analysis::Statistics::Raw
                                         : c.mean.front().statistics;
  analysis::RunOptions o;
  o.filter_cutoff = c.filter_cutoff, o.filter_order = c.filter_order;
  fmt::print("aero-fit: {} on {}; target mean contact force at {:.4g} km/h: {:.2f} N ({}: {:g} v² + {:g} v + {:g}, v in km/h)\n",
             a.model, cat.catenary->describe(), v * 3.6, target, c.name, c.target.v2, c.target.v1, c.target.v0);
  {  // the cost guard (analysis/cost_guard.hpp): about 4 runs at V, then the --speeds sweep
    std::vector<double> vs;
    if (!a.speeds.empty())
      for (double x : speed_list(a.speeds)) vs.push_back(x * k);
    const std::vector<catenary::PantographOnLine> train{{p, 0.0, cat.contact}};
    const double seconds = 4 * cat.catenary->estimated_seconds(train, v, -1) +
                           (vs.empty() ? 0.0 : analysis::estimated_sweep_seconds(train, *cat.catenary, vs));
    if (a.max_seconds > 0)
      analysis::check_cost(seconds, a.max_seconds, "this fit", "give --max-seconds",
                           "fewer spans with --set line.spans=N, fewer --speeds");
    if (const std::string note = analysis::cost_note(seconds, "this fit"); !note.empty()) fmt::print(stderr, "{}\n", note);
  }
  // Commissioning (analysis/commission.hpp): the --suspension relaxed at standstill on this line, the
  // trim, the static contact force over the working range (a model with a rig).
  std::optional<network::Network> net;
  if (!a.suspension.empty()) try {
      net = network::resolve(a.suspension, parse_params(a.params));
    } catch (const network::NetworkError& e) {
      throw ModelError(fmt::format("--suspension '{}': {}", a.suspension, e.what()));
    }
  else if (!a.params.empty())
    throw CLI::ValidationError("--param", "needs --suspension LAYOUT");
  analysis::WorkingRange range;
  {
    const auto colon = a.working_range.find(':');
    const bool decimal = a.working_range.find_first_not_of("0123456789.eE+-:") == std::string::npos;  // no hex, inf, nan
    if (colon == std::string::npos || !decimal || !CLI::detail::lexical_cast(a.working_range.substr(0, colon), range.below) ||
        !CLI::detail::lexical_cast(a.working_range.substr(colon + 1), range.above) || !(range.below >= 0 && range.below <= 2) ||
        !(range.above >= 0 && range.above <= 2) || range.below + range.above <= 0)
      throw CLI::ValidationError("--working-range", fmt::format("'{}': expected BELOW:ABOVE in m, each 0 … 2, not both 0", a.working_range));
  }
  analysis::Trim trim;
  trim.speed = v, trim.target = target, trim.statistics = stats, trim.options = o;
  const analysis::Commissioned com = analysis::commission(p, net ? &*net : nullptr, *cat.catenary, cat.contact, trim,
                                                          p.rig_joint >= 0 ? &range : nullptr);
  const analysis::Commissioning& rec = com.record;
  analysis::AeroFit fit;
  fit.reached = rec.reached, fit.a = rec.a, fit.mean = rec.mean, fit.runs = rec.runs, fit.target = target;
  fit.mean_without = rec.mean_without;
  if (net)
    fmt::print("suspension {}: relaxed at standstill on this line (actuator length {:.6g} m); static stiffness G(0) = lim s→0 "
               "s·Y(s) = {:.6g} N/m\n",
               network::to_string(*net, true), rec.operating_length, rec.static_stiffness);
  if (!std::isnan(rec.static_force))
    fmt::print("static contact force at standstill: {:.2f} N (the head {:+.1f} mm from its rig position)\n", rec.static_force,
               1e3 * rec.head_offset);
  if (!rec.range_force.empty()) {
    fmt::print("over the working range (the wire {:+g} … {:+g} m around this line's height): {:.2f} … {:.2f} N ({:+.1f} … "
               "{:+.1f} % of {:.2f} N): the stock static force held by the lifting device, plus what the suspension's "
               "static stiffness adds\n",
               -range.below, range.above, rec.range_min(), rec.range_max(), 100 * (rec.range_min() / rec.static_force - 1),
               100 * (rec.range_max() / rec.static_force - 1), rec.static_force);
    fmt::print("  height m {:>8.3f}\n  force N  {:>8.2f}\n  model N  {:>8.2f}  (the model alone, its frame springs included)\n",
               fmt::join(rec.range_height, " "), fmt::join(rec.range_force, " "), fmt::join(rec.range_model, " "));
  }
  fmt::print("mean contact force without aerodynamic uplift: {:.2f} N ({})\n", fit.mean_without,
             stats == analysis::Statistics::Filtered                ? fmt::format("{:g} Hz statistics", c.filter_cutoff)
             : std::isfinite(cat.catenary->line_length()) ? std::string("raw statistics")
                                                          : std::string("raw statistics: a point model of the line has no 20 Hz ones"));
  if (!fit.reached) {
    if (fit.mean_without > target)
      fmt::print(stderr, "aero-fit: no a >= 0 reaches the target: the mean force without uplift, {:.2f} N, is already above "
                         "{:.2f} N; lower the pantograph's static uplift\n", fit.mean_without, target);
    else
      fmt::print(stderr, "aero-fit: no a >= 0 reached {:.2f} N within 0.05 N in {} runs (last a = {:.6g} N·s²/m², mean {:.2f} N)\n",
                 target, fit.runs, fit.a, fit.mean);
    return 2;
  }
  fmt::print("a = {:.6g} N·s²/m² (b = c = 0): aerodynamic uplift {:.2f} N at {:.4g} km/h; mean contact force {:.2f} N ({} runs)\n",
             fit.a, fit.a * v * v, v * 3.6, fit.mean, fit.runs);
  const std::string section = io::file_kind(a.model) == io::FileKind::LumpedPantograph ? "lumped_pantograph" : "pantograph";
  fmt::print("in the model file: {0}: {{aerodynamic: {{a: {1:.6g}, b: 0, c: 0}}}}, or --set {0}.aerodynamic.a={1:.6g}\n",
             section, fit.a);
  if (!a.speeds.empty()) {
    std::vector<double> vs;
    for (double s : speed_list(a.speeds)) vs.push_back(s * k);
    const auto rs = analysis::sweep(com.pantograph, *cat.catenary, cat.contact, vs, o);
    fmt::print("  {:>8} {:>10} {:>10} {:>10}\n", "v km/h", "target N", "mean N", "diff N");
    for (const auto& r : rs) {
      const double m = stats == analysis::Statistics::Filtered && !r.filtered.empty() ? r.filtered.front().mean : r.stats.mean;
      if (!c.target.covers(r.speed * 3.6))
        fmt::print("  {:>8.4g} {:>10} {:>10.2f} {:>10}  (target not assessed: {})\n", r.speed * 3.6, "-", m, "-",
                   analysis::range_text(c.target.speeds));
      else
        fmt::print("  {:>8.4g} {:>10.2f} {:>10.2f} {:>+10.2f}\n", r.speed * 3.6, c.target.at(r.speed * 3.6), m,
                   m - c.target.at(r.speed * 3.6));
    }
  }
  return 0;
}

}  // namespace

CLI::App* add_pantograph_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("pantograph", "Pantograph tools");
  aero_cmd = cmd->add_subcommand("aero-fit",
                                 "Find the aerodynamic uplift a v² that brings the mean contact force to the criteria set's "
                                 "target at a speed (writes nothing)");
  AeroFitArgs& a = aero_args;
  aero_cmd->add_option("model", a.model, "Pantograph model file (YAML)")->required();
  aero_cmd->add_option("--catenary", a.catenary, "Catenary file")->required();
  aero_cmd->add_option("--acceptance", a.criteria, "Criteria set with a 'target' curve: a preset (en50367-ac, …) or a file")->required();
  aero_cmd->add_option("--speed", a.speed, "Speed of the fit, in --unit")->required()->check(number_in(1e-3, 1e4, "0.001 … 1e4"));
  aero_cmd->add_option("--unit", a.unit, "Speed unit: ms (m/s) or kmh")->check(CLI::IsMember({"ms", "kmh"}))->capture_default_str();
  aero_cmd->add_option("--speeds", a.speeds, "Also print the mean force with the fitted a at V0:DV:V1 (in --unit)");
  aero_cmd->add_option("--set", a.sets, "Override a model or catenary value NAME.KEY=VALUE (repeatable)");
  aero_cmd->add_option("--suspension", a.suspension,
                       "Commission this layout or expression in place of the actuator's network: relaxed at standstill "
                       "on this line (as a study with trim: does)");
  aero_cmd->add_option("--param", a.params, "Suspension element value NAME=VALUE (repeatable)");
  aero_cmd->add_option("--working-range", a.working_range,
                       "Contact-wire heights BELOW:ABOVE (m) around this line's over which the static contact force is "
                       "printed (the head held; a model with a rig)")
      ->capture_default_str();
  aero_cmd->add_option("--max-seconds", a.max_seconds,
                       "Refuse (exit 2) a fit whose estimated wall time on a 2-core machine is above S seconds (default 600)")
      ->check(number_rule(analysis::max_seconds_rule));
  cmd->require_subcommand(1);
  return cmd;
}

int run_pantograph() { return aero_cmd && aero_cmd->parsed() ? aero_fit() : 0; }

}  // namespace inerta::cli
