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
#include "inerta/optim/study_run.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/road.hpp"
#include "inerta/network/layouts.hpp"

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


}  // namespace inerta::cli
