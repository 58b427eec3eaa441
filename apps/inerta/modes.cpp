// `inerta modes` and `inerta frf` (docs/cli.md): the linearised model about its static equilibrium.
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "linear.hpp"

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
#include "inerta/solve/integrator.hpp"

namespace inerta::cli {

namespace modes_command {
namespace {

struct ModesArgs {
  std::string model, out, export_json, inputs, outputs;
  CatenaryArgs cat;
};

// Modes of the linearised model about its static equilibrium (spec/02 §2.5, spec/06 §6.3).
int cmd_modes(const ModesArgs& a) {
  if (!a.out.empty() && !a.export_json.empty() && a.out == a.export_json)
    throw InvalidArgument(fmt::format("--out and --export are both '{}'; give two file names", a.out));
  io::check_output_path(a.export_json, {a.model, a.cat.catenary});
  OutputFile file(a.out, {a.model, a.cat.catenary});
  analysis::ModalAnalysis ma;
  const bool plain = a.cat.catenary.empty() && !io::load_model_file(a.model, a.cat.sets).has_rig();
  if (!a.cat.catenary.empty()) {
    // A finite-element line is built for its mean (fitted lumped) catenary: its estimate first.
    auto [panto, cat] = pantograph_setup(a.model, a.cat, false, [&](const pantograph::Pantograph& p, const io::CatenaryFile& c) {
      const std::vector<catenary::PantographOnLine> tr{{p, 0.0, c.contact}};
      cost_guard(c.catenary->estimated_setup_seconds(tr), c.catenary->estimated_bytes(tr, 0, 0), 0,
                 "building this catenary", kFeCheaper);
    });
    ma = analysis::modal_analysis(panto, *cat.catenary, cat.contact);
  } else if (const pantograph::Pantograph p = io::load_model_file(a.model, a.cat.sets); p.has_rig()) {
    ma = analysis::modal_analysis_free_head(p);
  } else {
    ma = analysis::modal_analysis(p.model);
  }
  const mbs::Model& model = ma.model;
  const mbs::LinearModel& lin = ma.linear;
  const std::vector<mbs::Mode>& ms = ma.modes;
  const std::string& setting = ma.setting;
  if (!a.export_json.empty()) {
    if (plain) {
      auto list = [](const std::string& s) {
        std::vector<std::string> v;
        std::stringstream ss(s);
        for (std::string x; std::getline(ss, x, ',');)
          if (!x.empty()) v.push_back(x);
        return v;
      };
      fmt::print("state space: {}\n",
                 inerta::cli::export_state_space(a.model, a.cat.sets, a.export_json, list(a.inputs), list(a.outputs)));
    } else {
      io::write_linear_model(a.export_json, model, lin);  // for MATLAB/Python
      fmt::print("wrote {} (linear model: A, N, M, C, K)\n", a.export_json);
    }
  }
  fmt::print("modes of {} about its static equilibrium{}{}: {} independent coordinates, {} internal states\n",
             model.name, setting.empty() ? "" : ", ", setting, lin.dof, lin.nz);
  fmt::print("  {:>3} {:>12} {:>12} {:>10}  {}\n", "#", "f_d [Hz]", "|λ|/2π [Hz]", "zeta",
             "dominant coordinates (mode shape, body coordinates; largest +100 %)");
  for (std::size_t i = 0; i < ms.size(); ++i)
    fmt::print("  {:>3} {:>12.6g} {:>12.6g} {:>10.6f}  {}{}\n", i + 1, ms[i].damped_frequency_hz, ms[i].frequency_hz,
               std::abs(ms[i].damping_ratio) < 5e-7 ? 0.0 : ms[i].damping_ratio, ms[i].eigenvalue.imag() == 0 ? "(real, non-oscillatory) " : "", ms[i].description);
  const auto und = mbs::undamped_modes(model, lin);
  if (!und.empty()) {
    fmt::print("undamped natural frequencies of (M, K) (damping removed, network states held):\n");
    for (std::size_t i = 0; i < und.size(); ++i)
      fmt::print("  {:>3} {:>12.6g} Hz  {}\n", i + 1, und[i].frequency_hz, und[i].description);
  }
  if (!a.out.empty()) {
    fmt::print(file.get(), "mode,f_hz,f_damped_hz,zeta,re_lambda,im_lambda");
    for (int k = 0; k < model.n_coords(); ++k) fmt::print(file.get(), ",{}", model.coord_name(k));
    fmt::print(file.get(), "\n");
    for (std::size_t i = 0; i < ms.size(); ++i) {
      fmt::print(file.get(), "{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", i + 1, ms[i].frequency_hz, ms[i].damped_frequency_hz,
                 ms[i].damping_ratio, ms[i].eigenvalue.real(), ms[i].eigenvalue.imag());
      for (int k = 0; k < ms[i].shape.size(); ++k) fmt::print(file.get(), ",{:.6g}", ms[i].shape[k]);
      fmt::print(file.get(), "\n");
    }
    file.commit();
    fmt::print("wrote {}\n", a.out);
  }
  return 0;
}

struct FrfArgs {
  std::string model, outputs, freq, method = "linear", out, input;
  std::vector<std::string> sets;
  double vc = 0.06;
  int cycles = 100, analysed = 50;
};

// FRF from any input to any outputs of the linearised model (--input), or the test-rig FRF
// (spec/04 §4.2, eq. 6.25): acceleration over contact force.
int cmd_frf(const FrfArgs& a) {
  io::check_output_path(a.out, {a.model});
  if (!a.input.empty()) {
    if (a.method != "linear") throw CLI::ValidationError("--method", "with --input the FRF is the linear one");
    std::vector<std::string> outputs;
    std::stringstream ss(a.outputs);
    for (std::string o; std::getline(ss, o, ',');)
      if (!o.empty()) outputs.push_back(o);
    if (outputs.empty()) throw CLI::ValidationError("--outputs", "expected a comma-separated list of output names");
    return inerta::cli::run_frf_any(a.model, a.sets, a.input, outputs, frequency_range(a.freq), a.out);
  }
  const pantograph::Pantograph rig = io::load_model_file(a.model, a.sets);
  const mbs::Model& model = rig.model;
  std::vector<std::string> outputs;
  std::stringstream ss(a.outputs);
  for (std::string o; std::getline(ss, o, ',');)
    if (!o.empty()) outputs.push_back(o);
  if (outputs.empty()) throw CLI::ValidationError("--outputs", "expected a comma-separated list, e.g. P_ay,E_ay,B_ay");
  const std::vector<double> f = frequency_range(a.freq);
  for (double fk : f)
    if (!(fk > 0)) throw CLI::ValidationError("--freq", "frequencies must be > 0");
  const auto wall0 = std::chrono::steady_clock::now();
  analysis::Frf r;
  if (a.method == "linear") {
    r = analysis::frf_linear(rig, outputs, f);
  } else {
    analysis::SteppedSine o;
    o.vc = a.vc;
    o.cycles = a.cycles;
    o.analysed = a.analysed;
    try {
      analysis::check(o);  // the rules Python's frf_stepped_sine applies too
    } catch (const InvalidArgument& e) {
      const std::string m = e.what();
      const auto colon = m.find(": ");
      throw CLI::ValidationError("--" + m.substr(0, colon), m.substr(colon + 2));
    }
    r = analysis::frf_stepped_sine(rig, outputs, f, o);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  OutputFile file(a.out, {a.model});
  fmt::print(file.get(), "f_hz");
  for (const auto& o : outputs) fmt::print(file.get(), ",{}_mag,{}_phase_deg", o, o);
  fmt::print(file.get(), "\n");
  for (std::size_t k = 0; k < f.size(); ++k) {
    fmt::print(file.get(), "{:.10g}", f[k]);
    for (std::size_t i = 0; i < outputs.size(); ++i)
      fmt::print(file.get(), ",{:.10g},{:.10g}", std::abs(r.H[i][k]), std::arg(r.H[i][k]) * 180 / std::numbers::pi);
    fmt::print(file.get(), "\n");
  }
  file.commit();
  std::FILE* info = a.out.empty() ? stderr : stdout;
  fmt::print(info, "FRF ({}) of {}: {} frequencies, {} output(s) per N of contact force (m/s²/N), wall {:.2f} s\n",
             a.method, model.name, f.size(), outputs.size(), wall);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    std::size_t kmax = 0;
    for (std::size_t k = 0; k < f.size(); ++k)
      if (std::abs(r.H[i][k]) > std::abs(r.H[i][kmax])) kmax = k;
    fmt::print(info, "  {}: peak |FRF| = {:.4g} at {:.4g} Hz\n", outputs[i], std::abs(r.H[i][kmax]), f[kmax]);
  }
  if (!a.out.empty()) fmt::print(info, "wrote {}\n", a.out);
  return 0;
}

ModesArgs ma;
FrfArgs fa;

}  // namespace
}  // namespace modes_command

Command add_modes_command(CLI::App& app) {
  using namespace modes_command;
  auto* mds =
      app.add_subcommand("modes", "Natural frequencies, damping ratios and mode shapes about the static equilibrium");
  mds->add_option("model", ma.model, "Model file (YAML)")->required();
  mds->add_option("--out", ma.out, "CSV of the modes and their shapes");
  mds->add_option("--export", ma.export_json,
                  "JSON file with the state space (A, B, C, D, names; also PATH_{A,B,C,D}.csv) for MATLAB/Python; "
                  "a pantograph: the linear model (A, N, M, C, K)");
  mds->add_option("--inputs", ma.inputs, "State space: inputs, comma-separated (default: every load and driving joint)");
  mds->add_option("--outputs", ma.outputs, "State space: outputs, comma-separated (default: every output)");
  mds->add_option("--catenary", ma.cat.catenary, "Couple to this catenary (its mean, time-invariant part)");
  mds->add_option("--set", ma.cat.sets,
                  "Override a value NAME.KEY=VALUE of the model (k_s.k=12000) or, with --catenary, of the catenary "
                  "(repeatable)");
  return {mds, [] { return cmd_modes(ma); }};
}

Command add_frf_command(CLI::App& app) {
  using namespace modes_command;
  auto* frf = app.add_subcommand("frf", "FRF from an input to outputs of any model (--input), or the test-rig FRF (spec/04 §4.2)");
  frf->add_option("model", fa.model, "Model (YAML); without --input a pantograph with a rig joint")->required();
  frf->add_option("--input", fa.input, "A load (point_force/point_torque) or driving joint of the model: linear FRF about the static equilibrium");
  frf->add_option("--outputs", fa.outputs, "Outputs, comma-separated (rig FRF: accelerations, e.g. P_ay,E_ay,B_ay)")->required();
  frf->add_option("--set", fa.sets, "Override a model value NAME.KEY=VALUE (repeatable)");
  frf->add_option("--freq", fa.freq, "Frequencies F0:DF:F1 in Hz")->required();
  frf->add_option("--method", fa.method, "linear or stepped-sine")
      ->check(CLI::IsMember({"linear", "stepped-sine"}))
      ->capture_default_str();
  frf->add_option("--vc", fa.vc, "Stepped sine: mean velocity amplitude V_c, m/s")->capture_default_str()->check(number_rule(analysis::vc_rule));
  frf->add_option("--cycles", fa.cycles, "Stepped sine: cycles per frequency")->capture_default_str()->check(count_rule(analysis::cycles_rule));
  frf->add_option("--analysed", fa.analysed, "Stepped sine: last cycles analysed")->capture_default_str()->check(count_rule(analysis::analysed_rule));
  frf->add_option("--out", fa.out, "CSV file (default: standard output)");
  return {frf, [] { return cmd_frf(fa); }};
}

}  // namespace inerta::cli
