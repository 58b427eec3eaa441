// `inerta identify …`: identification from measurements (spec/06 §6.4, spec/03 §3.3;
// docs/cli.md#identify, docs/identification.md). The algorithms are in analysis/identification.
#include "identify.hpp"

#include "checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <tuple>

#include "inerta/analysis/identification.hpp"
#include "inerta/error.hpp"
#include "inerta/io/csv_table.hpp"
#include "inerta/io/files.hpp"
#include "inerta/io/model_file.hpp"

namespace inerta::cli {

namespace {

using cd = std::complex<double>;

struct Args {
  std::string csv, out, band, model, outputs, head = "P_ay", arm = "E_ay", freq_column = "f_hz";
  double head_mass = 0, c1 = 0, piston_mass = 0, friction = 0, freq = 0;
  bool fit_c1 = false;
  std::vector<std::string> fit, sets;
  int starts = 4;
  unsigned seed = 1;
  double min_step = 1e-4;
};
Args args;  // filled by CLI11 while parsing

CLI::App *head_cmd, *fit_cmd, *static_cmd, *dynamic_cmd;

// "LO:HI" in Hz.
std::pair<double, double> band_of(const std::string& s, const char* option) {
  double lo = 0, hi = 0;
  char colon = 0;
  std::istringstream in(s);
  if (!(in >> lo >> colon >> hi) || colon != ':' || !(in >> std::ws).eof() || !(lo >= 0) || !(hi > lo))
    throw CLI::ValidationError(option, "expected LO:HI in Hz with 0 <= LO < HI, got '" + s + "'");
  return {lo, hi};
}

using Output = io::OutputFile;  // written safely (io/files.hpp)

// Frequencies (column f_hz, > 0) of an FRF CSV.
std::vector<double> frequencies(const io::CsvTable& t) {
  std::vector<double> f = t.column("f_hz");
  for (std::size_t r = 0; r < f.size(); ++r)
    if (!(f[r] > 0))
      throw ModelError(
          fmt::format("{}:{}: column 'f_hz': {:g} Hz; expected a frequency > 0", t.source(), t.line(r), f[r]));
  return f;
}

// FRF of output `name` from <name>_re,<name>_im or <name>_mag,<name>_phase_deg (as `inerta frf` writes).
std::vector<cd> frf_column(const io::CsvTable& t, const std::string& name) {
  std::vector<cd> H(t.rows());
  if (t.has(name + "_re") || t.has(name + "_im")) {
    std::vector<double> re = t.column(name + "_re"), im = t.column(name + "_im");
    for (std::size_t r = 0; r < H.size(); ++r) H[r] = {re[r], im[r]};
  } else if (t.has(name + "_mag") || t.has(name + "_phase_deg")) {
    std::vector<double> mag = t.column(name + "_mag"), ph = t.column(name + "_phase_deg");
    for (std::size_t r = 0; r < H.size(); ++r) H[r] = std::polar(mag[r], ph[r] * std::numbers::pi / 180);
  } else {
    std::string list;
    for (const auto& n : t.names()) list += (list.empty() ? "" : ", ") + n;
    throw ModelError(
        fmt::format("{}: missing columns '{}_re' and '{}_im' (or '{}_mag' and '{}_phase_deg') for the FRF "
                    "of '{}'; the header has: {}",
                    t.source(), name, name, name, name, name, list));
  }
  return H;
}

// Output names of an FRF CSV: every NAME with NAME_re or NAME_mag.
std::vector<std::string> frf_outputs(const io::CsvTable& t) {
  std::vector<std::string> out;
  for (const auto& n : t.names())
    for (const char* suffix : {"_re", "_mag"}) {
      const std::string s = suffix;
      if (n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0)
        out.push_back(n.substr(0, n.size() - s.size()));
    }
  if (out.empty())
    throw ModelError(fmt::format("{}: no FRF columns (NAME_re,NAME_im or NAME_mag,NAME_phase_deg)", t.source()));
  return out;
}

int head_suspension() {
  const io::CsvTable t = io::CsvTable::read(args.csv);
  t.require_rows(1, "the head-suspension fit");
  const auto [lo, hi] = band_of(args.band.empty() ? "4:20" : args.band, "--band");
  const std::vector<double> f = frequencies(t);
  const std::vector<cd> H = frf_column(t, args.head), E = frf_column(t, args.arm);
  const analysis::HeadSuspensionFit r = analysis::fit_head_suspension(args.head_mass, f, H, E, lo, hi);
  fmt::print("head suspension from FRF_H = {} and FRF_E = {} ({}), head mass {:g} kg (eqs. 4.19, 4.20)\n", args.head,
             args.arm, args.csv, args.head_mass);
  fmt::print("band {:g}–{:g} Hz ({} frequencies): k2 = {:.6g} N/m, c2 = {:.6g} N·s/m (rms residual {:.3g})\n", lo, hi,
             r.points, r.k2, r.c2, r.rms_residual);
  if (!args.out.empty()) {
    Output o(args.out);
    fmt::print(o.get(), "f_hz,k2,c2,in_band\n");
    for (const auto& p : r.per_frequency)
      fmt::print(o.get(), "{:.10g},{:.10g},{:.10g},{}\n", p.f, p.k2, p.c2, p.f >= lo && p.f <= hi ? 1 : 0);
    o.commit();
    fmt::print("wrote {} (eq. 4.19 per frequency)\n", args.out);
  }
  return 0;
}

int frf_fit() {
  const std::string text = io::read_input_text(args.model, "model file");
  // Parameters "NAME.KEY" (bounds: ÷10 … ×10 the file's value) or "NAME.KEY=LO:HI".
  std::vector<numerics::Variable> vars;
  for (const auto& spec : args.fit) {
    const std::size_t eq = spec.find('=');
    numerics::Variable v;
    v.name = spec.substr(0, eq);
    v.can_open = v.can_rigid = false;
    if (eq != std::string::npos) {
      std::tie(v.lo, v.hi) = band_of(spec.substr(eq + 1), "--fit");
      if (!(v.lo > 0))
        throw CLI::ValidationError("--fit", "bounds must be > 0 (log-scaled search), got '" + spec + "'");
    } else {
      std::optional<double> x = io::model_value(text, args.model, v.name);
      if (!x || !(*x > 0))
        throw CLI::ValidationError(
            "--fit", fmt::format("'{}' has no positive value in {}; give bounds {}=LO:HI", v.name, args.model, v.name));
      v.lo = *x / 10, v.hi = *x * 10;
    }
    vars.push_back(v);
  }
  const io::CsvTable t = io::CsvTable::read(args.csv);
  t.require_rows(1, "the FRF fit");
  analysis::Frf meas;
  meas.f = frequencies(t);
  if (!args.outputs.empty()) {
    std::stringstream os(args.outputs);
    for (std::string o; std::getline(os, o, ',');)
      if (!o.empty()) meas.outputs.push_back(o);
  } else {
    meas.outputs = frf_outputs(t);
  }
  for (const auto& o : meas.outputs) meas.H.push_back(frf_column(t, o));
  const auto [lo, hi] = band_of(args.band.empty() ? "0.5:11" : args.band, "--band");
  meas = analysis::frf_band(meas, lo, hi);
  const std::vector<std::string> sets = args.sets;
  auto model_of = [&](const std::vector<double>& values) {
    std::vector<std::string> o = sets;
    for (std::size_t i = 0; i < vars.size(); ++i) o.push_back(fmt::format("{}={:.17g}", vars[i].name, values[i]));
    return io::parse_model_file(text, args.model, o);
  };
  {  // overrides and parameter names are checked before the search starts
    std::vector<double> centre;
    for (const auto& v : vars) centre.push_back(std::sqrt(v.lo * v.hi));
    (void)model_of(centre);
  }
  numerics::Options opt;
  opt.starts = args.starts;
  opt.seed = args.seed;
  opt.min_step = args.min_step;
  std::string outs;
  for (const auto& o : meas.outputs) outs += (outs.empty() ? "" : ", ") + o;
  fmt::print("FRF fit of {} to {}: outputs {}, band {:g}–{:g} Hz ({} frequencies), {} starts (seed {})\n", args.model,
             args.csv, outs, lo, hi, meas.f.size(), opt.starts, opt.seed);
  const analysis::FrfFit r = analysis::fit_frf(model_of, vars, meas, opt);
  fmt::print("  {:<20} {:>14} {:>14} {:>14}\n", "parameter", "fitted", "lower bound", "upper bound");
  for (std::size_t i = 0; i < vars.size(); ++i)
    fmt::print(
        "  {:<20} {:>14.6g} {:>14.6g} {:>14.6g}{}\n", vars[i].name, r.values[i], vars[i].lo, vars[i].hi,
        r.values[i] <= vars[i].lo * (1 + 1e-9) || r.values[i] >= vars[i].hi * (1 - 1e-9) ? "  (at a bound)" : "");
  fmt::print("cost (eq. 6.47) {:.6g} (m/s²/N)² at the fit, {:.6g} at the start; {} evaluations\n", r.cost,
             r.initial_cost, r.evaluations);
  if (!args.out.empty()) {
    Output o(args.out);
    fmt::print(o.get(), "f_hz");
    for (const auto& n : meas.outputs) fmt::print(o.get(), ",{}_re,{}_im,{}_meas_re,{}_meas_im", n, n, n, n);
    fmt::print(o.get(), "\n");
    for (std::size_t k = 0; k < meas.f.size(); ++k) {
      fmt::print(o.get(), "{:.10g}", meas.f[k]);
      for (std::size_t i = 0; i < meas.outputs.size(); ++i)
        fmt::print(o.get(), ",{:.10g},{:.10g},{:.10g},{:.10g}", r.fitted.H[i][k].real(), r.fitted.H[i][k].imag(),
                   meas.H[i][k].real(), meas.H[i][k].imag());
      fmt::print(o.get(), "\n");
    }
    o.commit();
    fmt::print("wrote {} (fitted and measured FRFs)\n", args.out);
  }
  return 0;
}

int actuator_static() {
  const io::CsvTable t = io::CsvTable::read(args.csv);
  t.require_rows(4, "the constant-velocity fit (two lines of two points)");
  const analysis::ActuatorStaticFit r = analysis::fit_actuator_static(t.column("velocity"), t.column("force"));
  fmt::print("actuator constant-velocity fit ({}; velocity in m/s, force in N):\n", args.csv);
  fmt::print("  forward  (v > 0): F = {:.6g} v + {:.6g}  ({} points, rms {:.3g} N)\n", r.forward.slope,
             r.forward.intercept, r.forward.points, r.forward.rms);
  fmt::print("  backward (v < 0): F = {:.6g} v + {:.6g}  ({} points, rms {:.3g} N)\n", r.backward.slope,
             r.backward.intercept, r.backward.points, r.backward.rms);
  fmt::print("F_c = {:.6g} N, F_r = {:.6g} N, c1 = {:.6g} N·s/m\n", r.F_c, r.F_r, r.c1);
  return 0;
}

int actuator_dynamic() {
  const io::CsvTable t = io::CsvTable::read(args.csv);
  t.require_rows(8, "the correlation method");
  const std::vector<double> time = t.column("t"), x = t.column("displacement"), F = t.column("force");
  std::map<double, analysis::DynamicTest> tests;
  if (t.has(args.freq_column)) {
    if (args.freq > 0) throw CLI::ValidationError("--freq", "the CSV has a column '" + args.freq_column + "' already");
    const std::vector<double> f = t.column(args.freq_column);
    for (std::size_t r = 0; r < f.size(); ++r) {
      if (!(f[r] > 0))
        throw ModelError(fmt::format("{}:{}: column '{}': {:g} Hz; expected a frequency > 0", t.source(), t.line(r),
                                     args.freq_column, f[r]));
      auto& T = tests[f[r]];
      T.f = f[r];
      T.t.push_back(time[r]), T.x.push_back(x[r]), T.F.push_back(F[r]);
    }
  } else {
    if (!(args.freq > 0))
      throw ModelError(fmt::format("{}: no column '{}'; give the excitation frequency with --freq F (Hz)", t.source(),
                                   args.freq_column));
    tests[args.freq] = {args.freq, time, x, F};
  }
  std::vector<analysis::DynamicTest> list;
  for (auto& [f, T] : tests) list.push_back(std::move(T));
  const analysis::ActuatorDynamicFit r =
      analysis::fit_actuator_dynamic(list, args.c1, args.piston_mass, args.friction, args.fit_c1);
  fmt::print("actuator dynamic fit ({}; {} frequencies; m_p = {:g} kg, F_r = {:g} N):\n", args.csv, r.points.size(),
             args.piston_mass, args.friction);
  fmt::print("  {:>8} {:>12} {:>14} {:>14} {:>14}\n", "f [Hz]", "|X| [mm]", "|Y_E| [N·s/m]", "arg Y_E [deg]",
             "|Y| fit");
  for (const auto& p : r.points)
    fmt::print("  {:>8.4g} {:>12.4g} {:>14.6g} {:>14.2f} {:>14.6g}\n", p.f, 1e3 * p.amplitude, std::abs(p.Y_E),
               std::arg(p.Y_E) * 180 / std::numbers::pi, std::abs(analysis::maxwell_admittance(r.k1, r.c1, p.f)));
  fmt::print("k1 = {:.6g} N/m, c1 = {:.6g} N·s/m ({}), cost (eq. 5.25) {:.4g}\n", r.k1, r.c1,
             args.fit_c1 ? "fitted" : "given", r.cost);
  if (!args.out.empty()) {
    Output o(args.out);
    fmt::print(o.get(), "f_hz,amplitude,Y_E_re,Y_E_im,Y_re,Y_im\n");
    for (const auto& p : r.points) {
      const cd y = analysis::maxwell_admittance(r.k1, r.c1, p.f);
      fmt::print(o.get(), "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", p.f, p.amplitude, p.Y_E.real(),
                 p.Y_E.imag(), y.real(), y.imag());
    }
    o.commit();
    fmt::print("wrote {} (estimated and fitted admittance)\n", args.out);
  }
  return 0;
}

}  // namespace

CLI::App* add_identify_commands(CLI::App& app) {
  auto* idn = app.add_subcommand("identify", "Identify parameters from measured CSV data (spec/06 §6.4, spec/03 §3.3)");
  idn->require_subcommand(1);

  head_cmd = idn->add_subcommand("head-suspension", "Head k2, c2 from the head and upper-arm FRFs (eqs. 4.19, 4.20)");
  head_cmd->add_option("csv", args.csv, "FRF CSV: f_hz, <head>_re/_im and <arm>_re/_im (m/s²/N)")->required();
  head_cmd->add_option("--head-mass", args.head_mass, "Head mass m_H, kg")->required()->check(positive("kg"));
  head_cmd->add_option("--head", args.head, "Output name of the head FRF in the CSV")->capture_default_str();
  head_cmd->add_option("--arm", args.arm, "Output name of the upper-arm FRF in the CSV")->capture_default_str();
  head_cmd->add_option("--band", args.band, "Least-squares band LO:HI in Hz (default 4:20)");
  head_cmd->add_option("--out", args.out, "CSV of eq. 4.19 solved per frequency");

  fit_cmd = idn->add_subcommand("frf-fit", "Fit model parameters to measured FRFs (eq. 6.47, pattern search)");
  fit_cmd->add_option("model", args.model, "Pantograph model with a rig joint (YAML)")->required();
  fit_cmd->add_option("--measured", args.csv, "FRF CSV: f_hz and per output NAME_re/_im or NAME_mag/_phase_deg")
      ->required();
  fit_cmd->add_option("--fit", args.fit, "Parameter NAME.KEY or NAME.KEY=LO:HI (e.g. c2.c, kf_cf.k); repeatable")
      ->required();
  fit_cmd->add_option("--outputs", args.outputs, "Outputs to fit, comma-separated (default: all in the CSV)");
  fit_cmd->add_option("--band", args.band, "Band LO:HI in Hz (default 0.5:11)");
  fit_cmd->add_option("--set", args.sets, "Fixed model value NAME.KEY=VALUE (repeatable)");
  fit_cmd->add_option("--starts", args.starts, "Random starts of the pattern search")
      ->capture_default_str()
      ->check(count_in(1, 10000));
  fit_cmd->add_option("--seed", args.seed, "Random seed")->capture_default_str()->check(count_in(0, 4294967295L));
  fit_cmd->add_option("--min-step", args.min_step, "Final mesh size, decades")
      ->capture_default_str()
      ->check(number_in(1e-9, 1, "1e-9 … 1 decades"));
  fit_cmd->add_option("--out", args.out, "CSV of the fitted and measured FRFs");

  static_cmd =
      idn->add_subcommand("actuator-static", "Actuator F_c, F_r, c1 from constant-velocity tests (spec/03 §3.3)");
  static_cmd->add_option("csv", args.csv, "CSV: velocity (m/s), force (N), one row per test")->required();

  dynamic_cmd =
      idn->add_subcommand("actuator-dynamic", "Actuator k1 from sinusoidal tests (correlation method, eq. 5.25)");
  dynamic_cmd->add_option("csv", args.csv, "CSV: t (s), displacement (m), force (N)[, f_hz]")->required();
  dynamic_cmd->add_option("--c1", args.c1, "Damping c1 in series with k1, N·s/m (from actuator-static)")
      ->check(positive("N·s/m"));
  dynamic_cmd->add_flag("--fit-c1", args.fit_c1, "Fit c1 as well");
  dynamic_cmd->add_option("--piston-mass", args.piston_mass, "Piston mass m_p, kg (thesis: 3.45)")
      ->capture_default_str()
      ->check(number_in(0, 1e6, ">= 0 kg"));
  dynamic_cmd->add_option("--friction", args.friction, "Coulomb friction F_r, N (from actuator-static)")
      ->capture_default_str()
      ->check(number_in(0, 1e9, ">= 0 N"));
  dynamic_cmd->add_option("--freq", args.freq, "Excitation frequency, Hz, when the CSV has no f_hz column")
      ->check(positive("Hz"));
  dynamic_cmd->add_option("--out", args.out, "CSV of the estimated and fitted admittance");
  return idn;
}

int run_identify() {
  io::check_output_path(args.out, {args.csv, args.model});  // before any computation
  if (head_cmd->parsed()) return head_suspension();
  if (fit_cmd->parsed()) return frf_fit();
  if (static_cmd->parsed()) return actuator_static();
  if (dynamic_cmd->parsed()) {
    if (!args.fit_c1 && !(args.c1 > 0)) throw CLI::ValidationError("--c1", "give c1 > 0 (N·s/m) or --fit-c1");
    return actuator_dynamic();
  }
  return 0;
}

}  // namespace inerta::cli
