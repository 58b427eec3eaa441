#include "linear.hpp"

#include "checks.hpp"
#include "networks.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <sstream>

#include "inerta/analysis/state_space.hpp"
#include "inerta/error.hpp"
#include "inerta/io/files.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/io/model_study_results.hpp"
#include "inerta/optim/model_study_run.hpp"
#include "inerta/optim/study_run.hpp"
#include "inerta/io/study_outcome.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/road.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/report/study_report.hpp"
#include "report.hpp"

namespace inerta::cli {

namespace {

using File = io::OutputFile;  // written safely (io/files.hpp)

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string x; std::getline(ss, x, ',');)
    if (!x.empty()) out.push_back(x);
  return out;
}

mbs::Model load(const std::string& path, const std::vector<std::string>& sets) { return io::load_model_file(path, sets).model; }

}  // namespace

int run_frf_any(const std::string& model_path, const std::vector<std::string>& sets, const std::string& input,
                const std::vector<std::string>& outputs, const std::vector<double>& f, const std::string& out) {
  File file(out, {model_path});  // checked before the computation
  const mbs::Model model = load(model_path, sets);
  const auto wall0 = std::chrono::steady_clock::now();
  const analysis::StateSpace ss = analysis::state_space(model, {input}, outputs);
  const auto H = analysis::frequency_response(ss, f);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  fmt::print(file.get(), "f_hz");
  for (const auto& o : outputs) fmt::print(file.get(), ",{0}_mag,{0}_phase_deg,{0}_re,{0}_im", o);
  fmt::print(file.get(), "\n");
  for (std::size_t k = 0; k < f.size(); ++k) {
    fmt::print(file.get(), "{:.10g}", f[k]);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      const auto h = H[k](static_cast<Eigen::Index>(i), 0);
      fmt::print(file.get(), ",{:.10g},{:.10g},{:.10g},{:.10g}", std::abs(h), std::arg(h) * 180 / std::numbers::pi, h.real(), h.imag());
    }
    fmt::print(file.get(), "\n");
  }
  file.commit();
  std::FILE* info = out.empty() ? stderr : stdout;
  fmt::print(info, "FRF (linear, about the static equilibrium) of {}: input '{}' ({}), {} frequencies, {} state(s), wall {:.3f} s\n",
             model.name, input, ss.input_units[0], f.size(), ss.A.rows(), wall);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    std::size_t kmax = 0;
    for (std::size_t k = 0; k < f.size(); ++k)
      if (std::abs(H[k](static_cast<Eigen::Index>(i), 0)) > std::abs(H[kmax](static_cast<Eigen::Index>(i), 0))) kmax = k;
    fmt::print(info, "  {}: peak |H| = {:.6g} per {} at {:.6g} Hz\n", outputs[i], std::abs(H[kmax](static_cast<Eigen::Index>(i), 0)),
               ss.input_units[0], f[kmax]);
  }
  if (ss.has_rate_feedthrough())
    fmt::print(info, "  note: an output responds directly to the input's rate or acceleration (D1, D2 terms)\n");
  if (!out.empty()) fmt::print(info, "wrote {}\n", out);
  return 0;
}

std::string export_state_space(const std::string& model_path, const std::vector<std::string>& sets, const std::string& path,
                               const std::vector<std::string>& inputs_in, const std::vector<std::string>& outputs_in) {
  const mbs::Model model = load(model_path, sets);
  std::vector<std::string> inputs = inputs_in, outputs = outputs_in;
  if (inputs.empty()) {
    for (const auto& f : model.forces)
      if (f->with_value(mbs::TimeFunction::constant(0))) inputs.push_back(f->name());
    for (const auto& j : model.joints)
      if (j.type == mbs::JointType::Driving) inputs.push_back(j.name);
  }
  if (outputs.empty())
    for (const auto& o : model.outputs) outputs.push_back(o.name);
  const analysis::StateSpace ss = analysis::state_space(model, inputs, outputs);
  const mbs::LinearModel& lin = ss.system.lin;
  io::Json j;
  j["model"] = model.name;
  j["form"] = "dY/dt = A Y + B u, y = C Y + D u + D1 du/dt + D2 d2u/dt2; Y = X - T0 u - T1 du/dt, X = [xi; xi_dot; z], "
              "q = q_e + N xi (xi: the independent coordinates named in 'states'); deviations from the static equilibrium, SI";
  j["dof"] = lin.dof;
  j["internal_states"] = lin.nz;
  j["states"] = ss.states;
  j["inputs"] = ss.inputs;
  j["input_units"] = ss.input_units;
  j["outputs"] = ss.outputs;
  std::vector<std::string> coords;
  for (int k = 0; k < model.n_coords(); ++k) coords.push_back(model.coord_name(k));
  j["coordinates"] = coords;
  j["q_e"] = io::json_rows(lin.equilibrium.q.transpose());
  j["N"] = io::json_rows(lin.N);
  for (const auto& [name, M] : std::vector<std::pair<std::string, const Eigen::MatrixXd*>>{
           {"A", &ss.A}, {"B", &ss.B}, {"C", &ss.C}, {"D", &ss.D}, {"D1", &ss.D1}, {"D2", &ss.D2}, {"T0", &ss.T0}, {"T1", &ss.T1},
           {"M", &lin.M}, {"C_damping", &lin.C}, {"K", &lin.K}})
    j[name] = io::json_rows(*M);
  io::write_json(path, j);
  // The same matrices as CSV (numpy.loadtxt(…, delimiter=',', skiprows=1)): PATH-without-.json_A.csv, …
  std::string stem = path;
  if (stem.size() > 5 && stem.substr(stem.size() - 5) == ".json") stem.resize(stem.size() - 5);
  auto csv = [&](const std::string& name, const Eigen::MatrixXd& M, const std::vector<std::string>& cols) {
    File f(stem + "_" + name + ".csv");
    for (std::size_t c = 0; c < cols.size(); ++c) fmt::print(f.get(), "{}{}", c ? "," : "", cols[c]);
    fmt::print(f.get(), "\n");
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      for (Eigen::Index c = 0; c < M.cols(); ++c) fmt::print(f.get(), "{}{:.17g}", c ? "," : "", M(r, c));
      fmt::print(f.get(), "\n");
    }
    f.commit();
  };
  csv("A", ss.A, ss.states);
  csv("B", ss.B, ss.inputs);
  csv("C", ss.C, ss.states);
  csv("D", ss.D, ss.inputs);
  return fmt::format("{} states, {} input(s), {} output(s): wrote {} and {}_{{A,B,C,D}}.csv", ss.states.size(), inputs.size(),
                     outputs.size(), path, stem);
}

// ---- rms --------------------------------------------------------------------------------------

namespace {
struct RmsArgs {
  std::string model, outputs, inputs, road_class, out, delays;
  std::vector<std::string> sets, noise;
  double gd0 = 0, speed = 0;
  int pade = 8;
} rms_args;
CLI::App* rms_cmd = nullptr;
}  // namespace

CLI::App* add_rms_command(CLI::App& app) {
  RmsArgs& a = rms_args;
  rms_cmd = app.add_subcommand("rms", "Random response (rms, H2) of outputs under white noise or an ISO 8608 road, by Lyapunov equations");
  rms_cmd->add_option("model", a.model, "Model file (YAML)")->required();
  rms_cmd->add_option("--outputs", a.outputs, "Outputs, comma-separated")->required();
  rms_cmd->add_option("--road", a.road_class, "ISO 8608 road class A…H (with --speed and --inputs)");
  rms_cmd->add_option("--gd0", a.gd0, "Road: G_d(n0) in m³ instead of a class (n0 = 0.1 cycles/m)")->check(positive("m³"));
  rms_cmd->add_option("--speed", a.speed, "Road: speed, m/s")->check(positive("m/s"));
  rms_cmd->add_option("--inputs", a.inputs, "Road: the driving joints that see the road, comma-separated");
  rms_cmd->add_option("--delays", a.delays, "Road: delay of each input, s, comma-separated (e.g. 0,0.1)");
  rms_cmd->add_option("--pade", a.pade, "Road: Padé order of a delay")->capture_default_str()->check(count_in(1, 20));
  rms_cmd->add_option("--white-noise", a.noise, "INPUT=W: white noise of intensity W (E[u(t)u(s)] = W δ(t−s)); repeatable");
  rms_cmd->add_option("--set", a.sets, "Override a model value NAME.KEY=VALUE (repeatable)");
  rms_cmd->add_option("--out", a.out, "CSV of the rms values");
  return rms_cmd;
}

int run_rms() {
  const RmsArgs& a = rms_args;
  io::check_output_path(a.out, {a.model});
  const bool road = !a.road_class.empty() || a.gd0 > 0;
  if (road == !a.noise.empty())
    throw CLI::ValidationError("rms", "give either a road (--road CLASS or --gd0, --speed, --inputs) or --white-noise INPUT=W");
  const mbs::Model model = load(a.model, a.sets);
  const std::vector<std::string> outputs = split(a.outputs);
  analysis::RandomResponse r;
  std::string what;
  const auto wall0 = std::chrono::steady_clock::now();
  if (road) {
    analysis::Road rd;
    if (!a.road_class.empty()) {
      try {
        if (a.road_class.size() != 1) throw InvalidArgument("--road");
        rd.gd0 = mbs::iso8608_gd0(a.road_class[0]);
      } catch (const InvalidArgument&) {
        throw CLI::ValidationError("--road", "expected an ISO 8608 class A to H, got '" + a.road_class + "'");
      }
    } else {
      rd.gd0 = a.gd0;
    }
    if (!(a.speed > 0)) throw CLI::ValidationError("--speed", "a road needs the speed in m/s (> 0)");
    rd.speed = a.speed;
    rd.inputs = split(a.inputs);
    if (rd.inputs.empty()) throw CLI::ValidationError("--inputs", "name the driving joints that see the road");
    for (const auto& d : split(a.delays)) {
      double v = 0;
      if (!CLI::detail::lexical_cast(d, v)) throw CLI::ValidationError("--delays", "not a number: '" + d + "'");
      rd.delays.push_back(v);
    }
    rd.pade_order = a.pade;
    const analysis::StateSpace ss = analysis::state_space(model, rd.inputs, outputs);
    r = analysis::road_response(ss, rd);
    what = fmt::format("ISO 8608 road G_d(n0) = {:g} m³ at {:g} m/s ({:.4g} km/h)", rd.gd0, rd.speed, rd.speed * 3.6);
  } else {
    std::vector<std::string> inputs;
    std::vector<double> W;
    for (const auto& s : a.noise) {
      const auto eq = s.find('=');
      double v = 0;
      if (eq == std::string::npos || !CLI::detail::lexical_cast(s.substr(eq + 1), v) || !(v > 0))
        throw CLI::ValidationError("--white-noise", "expected INPUT=W with W > 0, got '" + s + "'");
      inputs.push_back(s.substr(0, eq));
      W.push_back(v);
    }
    const analysis::StateSpace ss = analysis::state_space(model, inputs, outputs);
    r = analysis::white_noise_response(ss, Eigen::VectorXd::Map(W.data(), static_cast<Eigen::Index>(W.size())).asDiagonal().toDenseMatrix());
    what = "white noise";
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  fmt::print("random response of {} under {} (Lyapunov, about the static equilibrium; wall {:.4f} s):\n", model.name, what, wall);
  for (std::size_t i = 0; i < outputs.size(); ++i) fmt::print("  {:<16} rms {:.6g}\n", outputs[i], r.rms[static_cast<Eigen::Index>(i)]);
  if (!a.out.empty()) {
    File f(a.out);
    fmt::print(f.get(), "output,rms\n");
    for (std::size_t i = 0; i < outputs.size(); ++i) fmt::print(f.get(), "{},{:.10g}\n", outputs[i], r.rms[static_cast<Eigen::Index>(i)]);
    f.commit();
    fmt::print("wrote {}\n", a.out);
  }
  return 0;
}

// ---- optimise (model study) -------------------------------------------------------------------

namespace {
// The table of a model study after its searches (the default, each layout, the best; the structure
// summary for layouts: all).
void print_model_study(const optim::ModelStudyResult& run) {
  const optim::ModelStudy& study = run.study;
  const optim::Objective& o = study.objective;
  const network::Network& baseline = run.baseline;
  const optim::ModelCost& def = run.baseline_cost;
  const auto& results = run.results;
  fmt::print("\n  {:<14} {:<14} {:>12} {:>10}", "layout", "network", "J", "vs default");
  for (const auto& w : o.outputs) fmt::print(" {:>12}", w.name);
  for (const auto& lim : o.limits) fmt::print(" {:>12}", lim.output + "≤" + fmt::format("{:g}", lim.limit));
  fmt::print("  values (SI)\n");
  auto row = [&](const std::string& layout, const std::string& expr, const optim::ModelCost& c, const std::string& values,
                 const std::string& bounds, bool exhausted) {
    fmt::print("  {:<14} {:<14} {:>12.6g} {:>9.1f}%", layout, expr, c.J, 100 * (c.J - def.J) / def.J);
    for (double v : c.values) fmt::print(" {:>12.5g}", v);
    for (double v : c.limit_values) fmt::print(" {:>12.5g}", v);
    fmt::print("  {}{}{}{}\n", values, bounds.empty() ? "" : "  at limits: " + bounds, c.feasible ? "" : "  INFEASIBLE",
               exhausted ? "  budget exhausted (max_evaluations reached before min_step)" : "");
  };
  row("(default)", network::to_string(baseline), def, network::to_string(baseline, true), "", false);
  const std::size_t shown = study.all ? 25 : results.size();
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (i == shown) fmt::print("  … {} more in results.csv (with --out)\n", results.size() - shown);
    std::string values, bounds;
    for (const auto& [k, v] : r.values) values += fmt::format("{}{}={}", values.empty() ? "" : " ", k, numerics::describe(v));
    for (const auto& b : r.at_bounds) bounds += (bounds.empty() ? "" : ",") + b;
    if (i < shown) row(r.layout, r.expression, r.cost, values, bounds, r.budget_exhausted);
  }
  const auto& best = results[run.best];
  fmt::print("default ({}) J = {:.6g}; best {} ({}) J = {:.6g} ({:+.1f} %); wall {:.2f} s\n", network::to_string(baseline, true),
             def.J, best.layout, best.expression, best.cost.J, 100 * (best.cost.J - def.J) / def.J, run.seconds);
  if (study.all) {
    print_structure(run.entries, def.J, "", 0);
    int evaluations = 0;
    for (const auto& e : run.entries) evaluations += e.evaluations;
    fmt::print("{} networks, {} evaluations in {:.1f} s ({:.0f} evaluations/s)\n", run.entries.size(), evaluations,
               run.seconds, evaluations / run.seconds);
  }
}
}  // namespace

int run_model_study(const std::string& path, const std::string& out, bool plots) {
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

}  // namespace inerta::cli
