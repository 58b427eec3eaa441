// `inerta optimise STUDY` (docs/cli.md, docs/studies.md).
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "linear.hpp"
#include "networks.hpp"
#include "inerta/io/data_dir.hpp"
#include "install.hpp"
#include "inerta/io/model_study_results.hpp"
#include "inerta/io/study_outcome.hpp"
#include "inerta/optim/study_run.hpp"

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
#include "inerta/report/study_report.hpp"
#include "report.hpp"
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

// `inerta optimise STUDY` of a model study (objective rms | hinf | peak): the study engine (optim::run_study),
// its table, its files.
namespace {
// After the searches: the table (io::model_study_table), and for layouts: all the structure summary.
void print_model_study(const optim::ModelStudyResult& run) {
  fmt::print("{}", io::model_study_table(run));
  if (run.study.all) {
    print_structure(run.entries, run.baseline_cost.J, "", 0);
    int evaluations = 0;
    for (const auto& e : run.entries) evaluations += e.evaluations;
    fmt::print("{} networks, {} evaluations in {:.1f} s ({:.0f} evaluations/s)\n", run.entries.size(), evaluations,
               run.seconds, evaluations / run.seconds);
  }
}

int optimise_model_study(const std::string& path, const std::string& out, bool plots) {
  const optim::ModelStudy study = io::load_model_study(path);
  const bool tty = isatty(STDOUT_FILENO);
  fmt::print("study {}: model {}, strut '{}', objective {}, {} layouts, {} starts (seed {})\n", study.name, study.model.name,
             study.model.forces[static_cast<std::size_t>(study.strut)]->name(), optim::Objective::name(study.objective.kind),
             study.layouts.size(), study.search.starts, study.search.seed);
  if (study.all)
    fmt::print("every network of up to {} elements ({} networks), each also started from its best sub-network\n",
               study.all->max_elements, study.layouts.size());
  // The engine's events (optim::StudyEvents): a line per layout, the structure progress, the table, the bounds.
  struct Printer : optim::StudyEvents {
    const optim::ModelStudy& study;
    bool tty;
    optim::StructureProgressFn structure = structure_progress("");
    std::function<void(const optim::AdmittanceBound&)> print_bound;
    Printer(const optim::ModelStudy& s, bool t) : study(s), tty(t) {}
    using optim::StudyEvents::searched;
    void searching(std::size_t l, int start, int evals, double best) override {
      if (tty) fmt::print("\r  [{}/{}] {:<14} start {}  evaluations {:>5}  best {:.6g}   ", l + 1, study.layouts.size(),
                          study.layouts[l], start + 1, evals, best);
      std::fflush(stdout);
    }
    void searched(std::size_t l, const optim::ModelLayoutResult& r) override {
      if (tty) fmt::print("\r{:90}\r", "");
      fmt::print("  [{}/{}] {:<14} J = {:.6g}{} after {} evaluations\n", l + 1, study.layouts.size(), study.layouts[l], r.cost.J,
                 r.cost.feasible ? "" : " (a limit is exceeded)", r.evaluations);
    }
    void network(const optim::StructureProgress& p) override { structure(p); }
    void searches_done(const optim::StudyOutcome& o) override {
      print_model_study(*o.model);
      print_bound = print_admittance_bound(o.model->baseline_cost.J, "");
    }
    void bound(const optim::AdmittanceBound& b) override { print_bound(b); }
  } printer(study, tty);
  optim::StudyOptions options;
  options.report = !out.empty();  // the figures: what --out writes
  const optim::StudyOutcome run = optim::run_study(study, options, &printer);
  if (out.empty()) return 0;
  auto written = io::write_study_outcome(out, run);
  written.push_back(report::write_study_report(out, run_provenance({{"study", path}}), run));
  fmt::print("wrote");
  for (const auto& w : written) fmt::print(" {}", std::filesystem::path(w).filename().string());
  fmt::print(" in {}\n", out);
  if (plots) {
    std::fflush(stdout);
    if (study.all && !run_script("plot-structure", out))
      fmt::print("note: no pareto.png (scripts/plot-structure needs /usr/bin/python3 with matplotlib); pareto.csv is complete\n");
    if (!run_script("plot-model-study", out))
      fmt::print("note: no plots (scripts/plot-model-study needs /usr/bin/python3 with matplotlib); the CSV files in {} are complete\n", out);
  }
  return 0;
}
}  // namespace

namespace optimise_command {
namespace {

struct OptimiseArgs {
  std::string study, out;
  int map = 15;
  bool no_plots = false, force = false, no_early_stops = false;
  int workers = 0;        ///< > 0: a local Dask cluster of this many processes
  std::string scheduler;  ///< a Dask scheduler's address
  double max_seconds = 0;  ///< > 0: refuse a study whose estimate (at its limit of evaluations) is above
};

// `optimise --workers N | --scheduler ADDRESS`: the study on Dask, by the Python module's driver
// (python/inerta/distributed.py), which this process becomes (exit code and Ctrl-C are its).
int run_distributed(const OptimiseArgs& a) {
  if (a.map != 15) throw InvalidArgument("--map: not available with --workers/--scheduler (the report uses the default map)");
  if (a.max_seconds > 0)
    throw InvalidArgument("--max-seconds: not available with --workers/--scheduler (the cluster's cost is not estimated); "
                          "run without it");
  std::vector<std::string> args{INERTA_PYTHON, "-m", "inerta.distributed", "optimise", a.study};
  if (a.workers > 0) args.insert(args.end(), {"--workers", std::to_string(a.workers)});
  else args.insert(args.end(), {"--scheduler", a.scheduler});
  if (!a.out.empty()) args.insert(args.end(), {"--out", a.out});
  if (a.force) args.push_back("--force");
  if (a.no_plots) args.push_back("--no-plots");
  if (a.no_early_stops) args.push_back("--no-early-stops");
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = inerta::cli::python_package_dir() + (old && *old ? std::string(":") + old : std::string());
  ::setenv("PYTHONPATH", path.c_str(), 1);
  ::setenv("INERTA_DATA_DIR", io::data_dir().c_str(), 0);  // the driver's module reads this program's data
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  ::execv(INERTA_PYTHON, argv.data());
  throw InvalidArgument(fmt::format("--workers/--scheduler: cannot run {} ({}); the distributed driver needs Debian's "
                                    "python3 with python3-distributed (scripts/install-deps)",
                                    INERTA_PYTHON, std::strerror(errno)));
}

// Draws the PNGs of an `optimise --out DIR` with scripts/plot-study (python3 + matplotlib); without
// them, a note: the CSV files are complete either way.
void draw_plots(const std::string& dir) {
  if (!inerta::cli::run_script("plot-study", dir))
    fmt::print(
        "note: no plots (scripts/plot-study needs python3 with matplotlib and numpy: Debian's python3-matplotlib, "
        "python3-numpy, installed by scripts/install-deps); the CSV files in {} are complete, draw them later with "
        "`scripts/plot-study {}`\n",
        dir, dir);
}

OptimiseArgs oa;

// The CLI's view of a J2 study's progress (optim::StudyEvents): a line per layout (its search on a
// terminal), the structure search's progress, the tables after the searches, the bounds, the report's steps.
class Printer : public optim::StudyEvents {
 public:
  Printer(const optim::Study& study, bool tty)
      : study_(study), tty_(tty), u_(optim::objective_unit(study)), structure_(structure_progress(optim::objective_unit(study))) {}
  using optim::StudyEvents::searched;

  void searching(std::size_t i, int start, int evals, double best) override {
    if (tty_)
      fmt::print("\r  {:<12} start {}/{}  evaluations {:>5}  best J {:.4f} N   ", study_.layouts[i], start + 1,
                 study_.search.starts, evals, best);
    std::fflush(stdout);
  }
  void searched(std::size_t i, const optim::LayoutResult& r) override {
    if (tty_) fmt::print("\r{:80}\r", "");
    const std::string& layout = study_.layouts[i];
    if (study_.coarse)
      fmt::print("  {:<12} coarse J = {:.4f} N after {} evaluations; here {:.4f} N → refined {:.4f} N ({:+.1f} %) after {} "
                 "evaluations{}{}\n",
                 layout, r.coarse_cost.J, r.coarse_evaluations, r.coarse_here.J, r.cost.J,
                 100 * (r.cost.J - r.coarse_here.J) / r.coarse_here.J, r.evaluations,
                 r.budget_exhausted ? " (budget exhausted)" : "", r.cost.feasible ? "" : "; outside the limits: " + r.cost.violation);
    else
      fmt::print("  {:<12} J = {:.4f} N after {} evaluations{}{}{}\n", layout, r.cost.J, r.evaluations,
                 r.budget_exhausted ? " (budget exhausted: max_evaluations reached before min_step)" : "",
                 r.unstable ? fmt::format("; {} unstable designs refused", r.unstable) : "",
                 r.cost.feasible ? "" : "; outside the limits: " + r.cost.violation);
    std::fflush(stdout);
  }
  void network(const optim::StructureProgress& p) override { structure_(p); }
  void screening(const std::vector<std::size_t>& entries) override {
    fmt::print("\nscreening the best {} distinct reduced networks of the coarse search on this study, each at its coarse "
               "optimum (one evaluation each: {} catenaries × {} speeds); the best {} by that are refined\n",
               entries.size(), study_.catenaries.size(), study_.speeds.size(), study_.refine_networks);
    std::fflush(stdout);
    screen_start_ = std::chrono::steady_clock::now();
  }
  void refining(const std::vector<std::size_t>& entries) override {
    if (screen_start_)
      fmt::print("the screen: {:.0f} s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - *screen_start_).count());
    fmt::print("\nrefining the best {} distinct reduced networks of the {} on this study ({} catenaries × {} "
               "speeds, {}; at most {} evaluations each):\n",
               entries.size(), study_.refine_screen > study_.refine_networks ? "screen" : "coarse search", study_.catenaries.size(), study_.speeds.size(),
               study_.method == optim::Study::Method::Time ? "time domain" : "periodic fast path", study_.refine.max_evaluations);
    std::fflush(stdout);
  }
  void refined(std::size_t k, const optim::LayoutResult& r) override {
    fmt::print("  {:>2}. {:<28} here {:.4f}{} → refined {:.4f}{} after {} evaluations{}{}\n", k + 1, r.expression,
               r.coarse_here.J, *u_ ? " N" : "", r.cost.J, *u_ ? " N" : "", r.evaluations, r.budget_exhausted ? " (budget exhausted)" : "",
               r.cost.feasible ? "" : "; outside the limits: " + r.cost.violation);
    std::fflush(stdout);
  }
  void searches_done(const optim::StudyOutcome& o) override {
    if (study_.all && study_.coarse) {
      int evaluations = 0;
      for (const auto& e : o.entries) evaluations += e.evaluations;
      fmt::print("coarse search: {} networks, {} evaluations; the default there {:.4f}{}\n", o.entries.size(), evaluations,
                 o.coarse_default_cost.J, *u_ ? " N" : "");
      print_refined(o);
    } else if (study_.all) {
      print_structure(o.entries, o.default_cost.J, "N");
      int evaluations = 0;
      for (const auto& e : o.entries) evaluations += e.evaluations;
      fmt::print("{} networks, {} evaluations in {:.1f} s ({:.0f} evaluations/s)\n", o.entries.size(), evaluations, o.seconds,
                 evaluations / o.seconds);
      print_rechecks(o);
    } else {
      fmt::print("{}", io::study_table(study_, o.default_cost, o.results));
    }
    fmt::print("default suspension ({}) {} = {} at {:.0f} km/h; wall {:.1f} s\n", network::to_string(o.baseline, true),
               optim::objective_name(study_), *u_ ? fmt::format("{:.3f} N", o.default_cost.J) : fmt::format("{:.4f}", o.default_cost.J),
               o.default_cost.speed * 3.6, o.seconds);
    bound_ = print_admittance_bound(o.default_cost.J, "N");
    std::fflush(stdout);
  }
  void bound(const optim::AdmittanceBound& b) override { bound_(b); }
  void report(int step, int steps, const std::string& what, int done, int total) override {
    if (step == 1 && !what.empty()) fmt::print("post-processing for the figures:\n");
    if (!what.empty()) {
      current_ = fmt::format("  [{}/{}] {}", step, steps, what);
      t0_ = std::chrono::steady_clock::now();
      fmt::print("{}{}", current_, tty_ ? "" : " ...");
    }
    if (tty_ && done < total && total > 1) fmt::print("\r{}: {}/{}", current_, done, total);
    if (done == total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
      if (tty_)
        fmt::print("\r{}: {:.1f} s{:12}\n", current_, s, "");
      else
        fmt::print(" {:.1f} s\n", s);
    }
    std::fflush(stdout);
  }

 private:
  // The fast path linearises about the static state: the best few distinct designs, re-checked by the
  // time-domain reference and ranked by it (where the fast path is off by a few per cent, its order can
  // be wrong: issue 24).
  void print_rechecks(const optim::StudyOutcome& o) const {
    fmt::print("\ntime-domain re-check of the best {} distinct designs (analysis::sweep, all catenaries and speeds), "
               "ranked by the time-domain J2 (within the limits first):\n",
               std::min<std::size_t>(5, o.entries.size()));
    fmt::print("  {:<44} {:>13} {:>13} {:>9} {:>6} {:>9}\n", "reduced network", "periodic [N]", "time [N]", "periodic", "rank",
               "settles");
    for (const optim::Recheck& c : o.rechecks) {
      const auto& e = o.entries[c.entry];
      if (!c.failure.empty()) {
        fmt::print("  {:<44} {:>13.4f} {:>13}  ({})\n", e.reduced, e.J, "failed", c.failure);
        continue;
      }
      if (c.stopped) {  // early stops: behind the best, its remaining runs skipped
        fmt::print("  {:<44} {:>13.4f} {:>13} {:>9} {:>6}  stopped: J2 ≥ {:.4f} N{}\n", e.reduced, e.J, "-", "-", c.periodic_rank,
                   c.time.J, c.time.feasible ? "" : ", outside: " + c.time.violation);
        continue;
      }
      const double J = c.time.J, settle = c.settling_spans;
      const bool slow = settle > analysis::RunOptions{}.max_spans;
      fmt::print("  {:<44} {:>13.4f} {:>13.4f} {:>+8.2f}% {:>6} {:>9}{}\n", e.reduced, e.J, J, 100 * (e.J - J) / J,
                 c.periodic_rank, settle > 0 ? fmt::format("{:.0f} sp", std::ceil(settle)) : "-",
                 slow && std::abs(e.J - J) > 0.01 * J ? "  a free vibration outlasts the time-domain run: neither J2 is settled"
                 : std::abs(e.J - J) > 0.01 * J      ? "  the fast path is off by more than 1 %"
                                                     : "");
    }
    if (o.best.verified && o.rechecks.front().periodic_rank != 1)
      fmt::print("  the time domain ranks them differently: the best verified design is {} (fast path's #{}); "
                 "the figures and the summary below are of it\n",
                 o.entries[o.rechecks.front().entry].reduced, o.rechecks.front().periodic_rank);
  }

  // Multi-fidelity layouts: all: the refined networks ranked by this study's J2 (the final table).
  void print_refined(const optim::StudyOutcome& o) const {
    const char* J = optim::objective_name(study_);
    const std::string unit = *optim::objective_unit(study_) ? fmt::format(" [{}]", optim::objective_unit(study_)) : "";
    if (!o.screened.empty()) {
      fmt::print("\nthe screen: the best {} distinct reduced networks of the coarse search, each at its coarse optimum here, "
                 "ranked by this study's {}:\n", o.screened.size(), J);
      fmt::print("  {:>4} {:<44} {:>10} {:>6} {:>10}  {}\n", "rank", "network", "coarse", "c.rank", J, "");
      for (std::size_t k = 0; k < o.screened.size(); ++k) {
        const optim::Screened& c = o.screened[k];
        if (c.stopped)  // early stops: it could no longer be among the refined
          fmt::print("  {:>4} {:<44} {:>10.4f} {:>6} {:>10}  stopped: {} ≥ {:.4f}{}\n", k + 1, o.entries[c.entry].reduced,
                     o.entries[c.entry].J, c.coarse_rank, "-", J, c.cost.J, c.cost.feasible ? "" : ", outside: " + c.cost.violation);
        else
          fmt::print("  {:>4} {:<44} {:>10.4f} {:>6} {:>10.4f}  {}{}\n", k + 1, o.entries[c.entry].reduced, o.entries[c.entry].J,
                     c.coarse_rank, c.cost.J, c.refined ? "refined" : "",
                     !c.failure.empty() ? "failed: " + c.failure : c.cost.feasible ? "" : "; outside: " + c.cost.violation);
      }
    }
    fmt::print("\nthe refined networks{}, ranked by this study's {} (default {:.4f}{}):\n",
               study_.commissioned() ? " and the stock suspension, each commissioned on the reference line" : "", J,
               o.default_cost.J, unit);
    fmt::print("  {:>4} {:<44} {:>10} {:>6} {:>10} {:>10} {:>8}  {}\n", "rank", "network (refined values)", "coarse",
               "c.rank", "start", J, "vs def.", "limits");
    for (std::size_t k = 0; k < o.results.size(); ++k) {
      const optim::LayoutResult& r = o.results[k];
      const bool stock = o.refinements[k].entry == optim::Refinement::kStock;
      std::string limits = r.cost.feasible ? "kept" : "outside: " + r.cost.violation;
      if (!r.cost.binding.empty())
        limits += fmt::format("; binds: {} ({:+.1f} %)", r.cost.binding, 100 * r.cost.binding_margin);
      if (const auto& c = r.cost.commissioning)
        limits += fmt::format("; a = {:.4g}, G(0) = {:.4g} N/m, static {:.1f} … {:.1f} N", c->a, c->static_stiffness, c->range_min(),
                              c->range_max());
      const std::string name = network::to_string(optim::design_network(r.layout, r.values), true);
      if (stock)
        fmt::print("  {:>4} {:<44} {:>10.4f} {:>6} {:>10} {:>10.4f} {:>8}  {}\n", k + 1, "default " + name, o.coarse_default_cost.J,
                   "-", "-", r.cost.J, "", limits);
      else
        fmt::print("  {:>4} {:<44} {:>10.4f} {:>6} {:>10.4f} {:>10.4f} {:>+7.1f}%  {}\n", k + 1, name,
                   o.entries[o.refinements[k].entry].J, o.refinements[k].coarse_rank, r.coarse_here.J, r.cost.J,
                   100 * (r.cost.J - o.default_cost.J) / o.default_cost.J, limits);
    }
    if (!o.screened.empty() && !std::isnan(o.rank_agreement))
      fmt::print("  rank agreement with this study's order of the refined networks (Spearman): the screen's {:.3f}, "
                 "the coarse search's {:.3f}\n",
                 o.rank_agreement, o.coarse_rank_agreement);
    else if (!std::isnan(o.rank_agreement))
      fmt::print("  rank agreement of the coarse stage and this study over the refined networks (Spearman): {:.3f}\n",
                 o.rank_agreement);
    if (o.stock_best) {
      std::size_t next = o.results.size();
      for (std::size_t k = 0; k < o.results.size(); ++k)
        if (!o.results[k].stock) {
          next = k;
          break;
        }
      fmt::print("  no refined network beats the stock suspension{}: it stays the recommendation", study_.limits.acceptance
                                                                                                    ? " within every criterion"
                                                                                                    : "");
      if (next < o.results.size()) {
        const optim::LayoutResult& r = o.results[next];
        fmt::print("; the closest is {} at {:.4f}{} ({:+.1f} %), {}", network::to_string(optim::design_network(r.layout, r.values), true),
                   r.cost.J, unit, 100 * (r.cost.J - o.default_cost.J) / o.default_cost.J,
                   r.cost.feasible ? fmt::format("binding {} ({:+.1f} %)", r.cost.binding, 100 * r.cost.binding_margin)
                                   : "outside the limits: " + r.cost.violation);
      }
      fmt::print("\n");
    }
  }

  const optim::Study& study_;
  bool tty_;
  const char* u_;  ///< the objective's unit ("N" or "")
  std::optional<std::chrono::steady_clock::time_point> screen_start_;  ///< a screen's start (its time, printed)
  optim::StructureProgressFn structure_;
  std::function<void(const optim::AdmittanceBound&)> bound_;
  std::string current_;
  std::chrono::steady_clock::time_point t0_;
};

// Structure-based design (spec/07): the study engine (optim::run_study), its progress printed, its files written.
int cmd_optimise(const OptimiseArgs& a) {
  if (a.workers > 0 || !a.scheduler.empty()) return run_distributed(a);
  if (!a.out.empty()) io::prepare_output_folder(a.out, io::study_output_names(), a.force);  // before any computation
  if (io::is_model_study(a.study)) return inerta::cli::optimise_model_study(a.study, a.out, !a.no_plots);
  optim::Study study = io::load_study(a.study);
  const bool tty = isatty(STDOUT_FILENO);
  if (study.all && study.coarse)
    fmt::print("study {}: every network of up to {} elements ({} networks) searched on the coarse study ({} catenaries, {} "
               "speeds, {}), then the best {} refined here ({} catenaries, {} speeds, {})\n",
               study.name, study.all->max_elements, study.layouts.size(), study.coarse->catenaries.size(),
               study.coarse->speeds.size(),
               study.coarse->method == optim::Study::Method::Time ? "time domain" : "periodic fast path",
               study.refine_screen > study.refine_networks
                   ? fmt::format("{} distinct reduced networks screened here at their coarse optima and the best {} of them",
                                 study.refine_screen, study.refine_networks)
                   : fmt::format("{} distinct reduced networks", study.refine_networks),
               study.catenaries.size(), study.speeds.size(),
               study.method == optim::Study::Method::Time ? "time domain" : "periodic fast path");
  else if (study.all)
    fmt::print("study {}: every network of up to {} elements ({} networks), {} catenaries, {} speeds, {} starts (seed {}) and "
               "a warm start from the best sub-network, periodic fast path\n",
               study.name, study.all->max_elements, study.layouts.size(), study.catenaries.size(), study.speeds.size(),
               study.search.starts, study.search.seed);
  else if (study.coarse)
    fmt::print("study {}: {} layouts; each searched on the coarse study ({} catenaries, {} speeds, {} starts, seed {}, {}), "
               "then refined here ({} catenaries, {} speeds, {}; at most {} evaluations from {})\n",
               study.name, study.layouts.size(), study.coarse->catenaries.size(), study.coarse->speeds.size(),
               study.coarse->search.starts, study.coarse->search.seed,
               study.coarse->method == optim::Study::Method::Time ? "time domain" : "periodic fast path",
               study.catenaries.size(), study.speeds.size(),
               study.method == optim::Study::Method::Time ? "time domain" : "periodic fast path", study.refine.max_evaluations,
               study.refine_candidates == 1 ? std::string("the coarse optimum")
                                            : fmt::format("each of the {} best coarse end points", study.refine_candidates));
  else
    fmt::print("study {}: {} layouts, {} catenaries, {} speeds, {} starts (seed {}), {}\n", study.name,
               study.layouts.size(), study.catenaries.size(), study.speeds.size(), study.search.starts, study.search.seed,
               study.method == optim::Study::Method::Time ? "time domain" : "periodic fast path");
  {  // every stage: the search (or the coarse search) and the refinement (optim::estimated_study_seconds)
    const optim::StudyEstimate est = optim::estimated_study_seconds(study);
    if (const double e = optim::estimated_evaluation_seconds(study); e > 1)
      fmt::print("one evaluation ≈ {:.1f} s (estimated: {} catenaries × {} speeds in the time domain)\n", e,
                 study.catenaries.size(), study.speeds.size());
    std::string what = fmt::format("this study ({} search evaluations ≈ {:.0f} s", est.search_evaluations, est.search_seconds);
    if (study.coarse) what += fmt::format(", {} refinement evaluations at their limit ≈ {:.0f} s", est.refine_evaluations, est.refine_seconds);
    what += ")";
    cost_guard(est.seconds(), 0, a.max_seconds, what,
               "fewer layouts or networks (networks: {max_elements}), fewer starts or search.max_evaluations, fewer speeds, "
               "a smaller refine: budget, or a coarse: stage");
  }
  std::fflush(stdout);
  optim::StudyOptions options;
  options.report = !a.out.empty();  // the figures' data: what --out writes
  options.report_options.map_size = a.map;
  options.early_stops = !a.no_early_stops;
  Printer printer(study, tty);
  const optim::StudyOutcome o = optim::run_study(study, options, &printer);
  if (!a.out.empty()) {
    auto files = io::write_study_outcome(a.out, o);
    files.push_back(report::write_study_report(a.out, run_provenance({{"study", a.study}}), o));
    fmt::print("wrote");
    for (const auto& f : files) fmt::print(" {}", std::filesystem::path(f).filename().string());
    fmt::print(" in {}\n", a.out);
    for (const auto& c : o.report->centripetal) {
      const optim::StudyCost on = optim::worst_of(c.on), off = optim::worst_of(c.off);
      if (c.off_simulated)
        fmt::print("centripetal correction, {}: J2 = {:.4f} N on, {:.4f} N off ({:+.3f} %)\n", c.design.label, on.J,
                   off.J, 100 * (off.J - on.J) / on.J);
      else
        fmt::print("centripetal correction, {}: no inerter, nothing to correct\n", c.design.label);
    }
    if (!a.no_plots) {
      std::fflush(stdout);
      if (study.all && !run_script("plot-structure", a.out))
        fmt::print("note: no pareto.png (scripts/plot-structure needs /usr/bin/python3 with matplotlib); pareto.csv is complete\n");
      draw_plots(a.out);
    }
  }
  const optim::LayoutResult& best = o.results[o.best.index];
  if (study.method == optim::Study::Method::Time && study.objective == optim::Study::Objective::SigmaOverMean)
    fmt::print("best: {}{} ({}) — sigma/F_m = {:.4f} (σ {:.3f} N, F_m {:.2f} N) at {:.0f} km/h (time domain){}\n",
               o.stock_best ? "the stock suspension " : "", best.layout, best.expression, best.cost.J, best.cost.sigma,
               best.cost.mean, best.cost.speed * 3.6, best.cost.feasible ? "" : "; no design keeps the limits: " + best.cost.violation);
  else if (study.method == optim::Study::Method::Time)
    fmt::print("best: {}{} ({}) — J2 = {:.3f} N at {:.0f} km/h (time domain){}\n", o.stock_best ? "the stock suspension " : "",
               best.layout, best.expression, best.cost.J, best.cost.speed * 3.6,
               best.cost.feasible ? "" : "; no design keeps the limits: " + best.cost.violation);
  else
    fmt::print("best: {} ({}) — time-domain re-check J2 = {:.3f} N at {:.0f} km/h (periodic {:.3f} N, {:+.2f} %)\n",
               best.layout, best.expression, o.time_check.J, o.time_check.speed * 3.6, best.cost.J,
               100 * (best.cost.J - o.time_check.J) / o.time_check.J);
  return 0;
}

}  // namespace
}  // namespace optimise_command

Command add_optimise_command(CLI::App& app) {
  using namespace optimise_command;
  auto* opt = app.add_subcommand("optimise", "Optimise the suspension layouts of a study file (spec/07)");
  opt->add_option("study", oa.study, "Study file (YAML)")->required();
  opt->add_option("--out", oa.out,
                  "Directory for results.csv/json, the figures' data (CSV) and their PNGs (scripts/plot-study)");
  opt->add_option("--map", oa.map, "J2 map over (b, k): N×N points (0: none)")->capture_default_str()->check(count_in(0, 200));
  opt->add_flag("--no-plots", oa.no_plots, "Write the figures' CSV files but do not draw the PNGs");
  auto* workers = opt->add_option("--workers", oa.workers, "Run the layouts on a local Dask cluster of N processes (docs/distributed.md)")
                      ->check(count_in(1, 1024));
  opt->add_option("--scheduler", oa.scheduler, "Run the layouts on the Dask cluster of this scheduler, tcp://HOST:PORT")
      ->excludes(workers)
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {  // '' would run serially without a word
            return v.find_first_not_of(" \t") == std::string::npos
                       ? "empty; expected the address of a running scheduler, tcp://HOST:PORT"
                       : "";
          },
          "ADDRESS"));
  opt->add_option("--max-seconds", oa.max_seconds,
                  "Refuse (exit 2) a study whose estimate — every stage: the search or coarse search, the refinements at "
                  "their limit — is above S seconds (default: no limit; the estimate is printed beyond 10 s)")
      ->check(number_rule(analysis::max_seconds_rule));
  opt->add_flag("--no-early-stops", oa.no_early_stops,
                "Evaluate every time-domain re-check and screened design in full (the early stops are exact: the same "
                "winner and networks refined; a stopped design's J is a lower bound)");
  opt->add_flag("--force", oa.force,
                "Use an --out folder that is not empty: the files a study writes there are removed first");
  return {opt, [] { return cmd_optimise(oa); }};
}

}  // namespace inerta::cli
