// inerta — command-line interface (docs/cli.md).
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

#include "acceptance.hpp"
#include "checks.hpp"
#include "identify.hpp"
#include "linear.hpp"
#include "networks.hpp"
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

using namespace inerta;

namespace {

const char* joint_type_name(mbs::JointType t) {
  switch (t) {
    case mbs::JointType::Revolute:
      return "revolute";
    case mbs::JointType::Spherical:
      return "spherical";
    case mbs::JointType::Prismatic:
      return "prismatic";
    case mbs::JointType::Fixed:
      return "fixed";
    case mbs::JointType::Driving:
      return "driving";
    case mbs::JointType::Distance:
      return "distance";
    case mbs::JointType::Coupling:
      return "coupling";
  }
  return "?";
}

std::string body_name(const mbs::Model& m, int b) {
  return b < 0 ? "ground" : m.bodies[static_cast<std::size_t>(b)].name;
}

void print_assembly(std::FILE* to, const mbs::Model& model, const mbs::AssemblyReport& a) {
  fmt::print(to, "assembly: max |C| {:.3g} -> {:.3g} in {} Newton iteration(s)", a.initial_residual, a.residual,
             a.iterations);
  if (a.dq.size() > 0 && a.dq.cwiseAbs().maxCoeff() > 0)
    fmt::print(to, "; largest correction {:+.4g} {} on {}", a.dq[a.largest],
               model.spatial() ? (a.largest % 7 >= 3 ? "" : "m") : (a.largest % 3 == 2 ? "rad" : "m"),
               model.coord_name(a.largest));
  fmt::print(to, "\n");
}

int check_model_file(const std::string& path, const std::vector<std::string>& sets) {
  mbs::Model model = io::load_model(path, sets);
  for (const auto& note : model.notes) fmt::print("note: {}\n", note);
  fmt::print("model: {} ({})\n", model.name, path);
  fmt::print("bodies ({}){}:\n", model.bodies.size(), model.spatial() ? ", spatial (Euler parameters)" : "");
  for (const auto& b : model.bodies)
    if (model.spatial())
      fmt::print(
          "  {:<16} m = {:<10.6g} kg  I = [{:.6g} {:.6g} {:.6g}] kg·m²  R = [{:.6g} {:.6g} {:.6g}] m  p = [{:.6g} "
          "{:.6g} {:.6g} {:.6g}]\n",
          b.name, b.mass, b.inertia3(0, 0), b.inertia3(1, 1), b.inertia3(2, 2), b.q0s[0], b.q0s[1], b.q0s[2], b.q0s[3],
          b.q0s[4], b.q0s[5], b.q0s[6]);
    else
      fmt::print("  {:<16} m = {:<10.6g} kg  I = {:<10.6g} kg·m²  x = {:<10.6g} y = {:<10.6g} θ = {:.6g} rad\n", b.name,
                 b.mass, b.inertia, b.q0.x(), b.q0.y(), b.q0.z());
  fmt::print("coordinates: {}\n", model.n_coords());
  if (model.spatial()) fmt::print("Euler-parameter normalisation equations: {}\n", model.bodies.size());
  if (model.n_states() > 0) fmt::print("internal states of network struts: {}\n", model.n_states());
  fmt::print("joints ({}), constraint equations: {}\n", model.joints.size(), model.n_constraints());
  for (const auto& j : model.joints)
    fmt::print("  {:<16} {:<10} {} - {}  ({} equation{})\n", j.name, joint_type_name(j.type),
               body_name(model, j.body_i), body_name(model, j.body_j), j.rows(), j.rows() > 1 ? "s" : "");
  fmt::print("force elements ({}):", model.forces.size());
  for (const auto& f : model.forces) fmt::print(" {}", f->name());
  fmt::print("\noutputs ({}):", model.outputs.size());
  for (const auto& o : model.outputs) fmt::print(" {}", o.name);
  fmt::print("\n");

  mbs::AssemblyReport rep;
  mbs::State x = mbs::assemble(model, 0.0, &rep);
  print_assembly(stdout, model, rep);
  mbs::Workspace ws(model);
  mbs::evaluate_constraints(model, 0.0, x, ws);
  Eigen::Index rank = 0;
  if (model.n_constraints() > 0) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(ws.Cq);
    lu.setThreshold(1e-10);
    rank = lu.rank();
  }
  fmt::print("degrees of freedom: {}", model.n_coords() - rank);
  if (rank < model.n_constraints()) fmt::print(" ({} redundant constraint equation(s)!)", model.n_constraints() - rank);
  fmt::print("\n");
  mbs::accelerations(model, 0.0, x, ws);  // throws if the system matrix is singular
  fmt::print("ok\n");
  return 0;
}

// A catenary file: its key numbers (a finite-element line from its data, without the form-finding).
int check_catenary(const std::string& path, const std::vector<std::string>& sets) {
  const io::CatenaryFile f = io::read_catenary_file(path, sets);
  fmt::print("catenary: {} ({})\n", f.name, path);
  if (f.fe) {
    const catenary::FeCatenaryData& d = *f.fe;
    const std::size_t n = d.dropper_x.size();
    fmt::print("type: finite_element (messenger and contact wire as tensioned beams, droppers slack in compression)\n");
    fmt::print("line: {} spans of {:g} m, length {:g} m, encumbrance {:g} m\n", d.spans, d.span, d.span * d.spans,
               d.encumbrance);
    for (const auto& [which, w] : {std::pair{"messenger", d.messenger}, std::pair{"contact wire", d.contact_wire}})
      fmt::print("{:<13} T = {:g} N, rho A = {:g} kg/m, EI = {:g} N·m², wave speed sqrt(T/rho A) = {:.2f} m/s ({:.1f} km/h)\n",
                 std::string(which) + ":", w.tension, w.mass_per_length, w.EI, w.wave_speed(), 3.6 * w.wave_speed());
    fmt::print("droppers: {} a span, {} in all; EA = {:g} N, {:g} kg/m, clamps {:g} kg (messenger), {:g} kg (contact wire)\n",
               n, n * static_cast<std::size_t>(d.spans), d.dropper_EA, d.dropper_mass_per_length, d.clamp_mass_messenger,
               d.clamp_mass_contact);
    fmt::print("supports: {:g} N/m, {:g} kg; registration: {:g} N/m, {:g} kg{}\n", d.support_stiffness, d.support_mass,
               d.registration_stiffness, d.registration_mass,
               std::isnan(d.registration_uplift_limit)
                   ? ""
                   : fmt::format("; uplift limit {:g} m (acceptance criterion support_uplift)", d.registration_uplift_limit));
    fmt::print("mesh: element length <= {:g} m (nodes at every dropper and mast)\n", d.element_length);
    fmt::print("damping: Rayleigh a = {:g} 1/s, b = {:g} s; integration: HHT-alpha, alpha = {:g}, time step {:g} s\n",
               d.rayleigh_mass, d.rayleigh_stiffness, d.hht_alpha, d.time_step);
    if (d.solver == catenary::FeCatenaryData::Solver::Direct)
      fmt::print("solver: direct (HHT-alpha on the whole line)\n");
    else if (d.window_behind < 0 || d.window_ahead < 0)
      fmt::print("solver: modal, modes below {:g} Hz, the whole line\n", d.modal_cutoff);
    else
      fmt::print("solver: modal, modes below {:g} Hz, a window of {} span(s) behind and {} ahead\n", d.modal_cutoff,
                 d.window_behind, d.window_ahead);
    if (d.section_first > 0)
      fmt::print("analysis section: spans {} to {}\n", d.section_first, d.section_last);
    else
      fmt::print("analysis section: the default (the middle spans, away from the ends)\n");
  } else {
    fmt::print("{}\n", f.catenary->describe());
  }
  if (f.contact.kind == catenary::Contact::Kind::Penalty)
    fmt::print("contact: penalty, k_s = {:g} N/m, c_s = {:g} N·s/m\n", f.contact.stiffness, f.contact.damping);
  else
    fmt::print("contact: bilateral\n");
  fmt::print("ok\n");
  return 0;
}

// `inerta check FILE`: a model, a lumped pantograph or a catenary file (io::file_kind).
int cmd_check(const std::string& path, const std::vector<std::string>& sets) {
  const io::FileKind kind = io::file_kind(path);
  if (kind == io::FileKind::Catenary) return check_catenary(path, sets);
  if (kind == io::FileKind::LumpedPantograph) {
    const pantograph::LumpedPantographData d = io::load_lumped_pantograph_data(path, sets);
    fmt::print("lumped pantograph: {} masses, head first: m = [{}] kg, k = [{}] N/m, c = [{}] N·s/m\n", d.mass.size(),
               fmt::join(d.mass, ", "), fmt::join(d.stiffness, ", "), fmt::join(d.damping, ", "));
    fmt::print("static uplift {:g} N on the lowest mass; aerodynamic uplift on the head {:g} v² + {:g} v + {:g} N (v in m/s)\n",
               d.static_uplift, d.aero_a, d.aero_b, d.aero_c);
  }
  return check_model_file(path, sets);
}

// A CSV destination: the file given with --out (written safely, io/files.hpp), or standard output.
using io::OutputFile;

// CSV numbers: 10 significant digits, shortest general form.
void append_number(std::string& s, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 10);
  s.append(buf, r.ptr);
}

// Options shared by simulate and sweep for a pantograph running under a catenary (issue 4).
struct CatenaryArgs {
  std::string catenary, unit = "ms", suspension, contact;
  std::vector<std::string> sets, params;
  bool relaxed = false;  ///< relax --suspension at the operating point under the catenary (as a study)
  bool allow_supercritical = false;  ///< run above the contact wire's wave speed (analysis::check_run_speed)
};

network::Params parse_params(const std::vector<std::string>& list) {
  network::Params params;
  for (const auto& p : list) {
    auto eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CLI::ValidationError("--param", "expected NAME=VALUE, got '" + p + "'");
    std::string name = p.substr(0, eq), v = p.substr(eq + 1);
    double value = 0;
    if (params.count(name)) throw CLI::ValidationError("--param", "'" + name + "' is given twice");
    std::string lower = v;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower == "inf" || lower == ".inf")
      value = INFINITY;
    else if (!CLI::detail::lexical_cast(v, value))
      throw CLI::ValidationError("--param", "not a number in '" + p + "'");
    params[name] = value;
  }
  return params;
}

double to_ms(double v, const std::string& unit) { return unit == "kmh" ? v / 3.6 : v; }

// The pantograph with the requested suspension, and the catenary file with its overrides.
// `before_work`: called once both are read and before anything is computed on the catenary (the
// cost guard: a finite-element line is built when first used, catenary/fe_catenary.hpp).
using BeforeWork = std::function<void(const pantograph::Pantograph&, const io::CatenaryFile&)>;
std::pair<pantograph::Pantograph, io::CatenaryFile> pantograph_setup(const std::string& path, const CatenaryArgs& c,
                                                                     bool no_centripetal = false,
                                                                     const BeforeWork& before_work = {}) {
  // --set NAME.KEY: to the model if NAME is one of its elements, bodies or joints (or lumped_pantograph),
  // else to the catenary file.
  const auto [panto_sets, cat_sets] = io::split_overrides(path, c.sets);
  pantograph::Pantograph p = io::load_pantograph(path, panto_sets);
  if (no_centripetal) p.model.options.centripetal = false;
  io::CatenaryFile cat = io::load_catenary(c.catenary, cat_sets);
  if (!c.contact.empty())
    cat.contact.kind = c.contact == "penalty" ? catenary::Contact::Kind::Penalty : catenary::Contact::Kind::Bilateral;
  if (before_work) before_work(p, cat);
  if (!c.suspension.empty()) {
    network::Network net;
    try {
      net = network::resolve(c.suspension, parse_params(c.params));
    } catch (const network::NetworkError& e) {
      throw ModelError(fmt::format("--suspension '{}': {}", c.suspension, e.what()));
    }
    // --relaxed: at the actuator's length of the static equilibrium with the model's own suspension
    // under this catenary, as a study's candidates (optim::operating_length); else the old network's.
    p.model = pantograph::with_suspension(p.model, net, c.relaxed ? optim::operating_length(p, *cat.catenary, cat.contact) : -1);
  } else if (!c.params.empty()) {
    throw CLI::ValidationError("--param", "needs --suspension LAYOUT");
  } else if (c.relaxed) {
    throw CLI::ValidationError("--relaxed", "needs --suspension LAYOUT");
  }
  return {p, cat};
}

void add_catenary_options(CLI::App* app, CatenaryArgs& c, bool required) {
  auto* o = app->add_option("--catenary", c.catenary, "Catenary file (models/catenary.yaml)");
  if (required) o->required();
  app->add_option("--unit", c.unit, "Speed unit: ms (m/s) or kmh")
      ->check(CLI::IsMember({"ms", "kmh"}))
      ->capture_default_str();
  app->add_option("--set", c.sets,
                  "Override a value NAME.KEY=VALUE of the model (a force element, body or joint: k_s.k=12000, "
                  "drive.speed=20, lumped_pantograph.static_uplift=90) or of the catenary (catenary.kc0=5000); "
                  "repeatable");
  app->add_option("--contact", c.contact, "bilateral (thesis) or penalty; default: the catenary file's")
      ->check(CLI::IsMember({"bilateral", "penalty"}));
  app->add_option("--suspension", c.suspension, "Replace the actuator's dynamic network by this layout or expression");
  app->add_option("--param", c.params, "Suspension element value NAME=VALUE (repeatable)");
  app->add_flag("--allow-supercritical", c.allow_supercritical,
                "Run above the contact wire's wave speed (refused otherwise; a warning from 70 % of it)");
  app->add_flag("--relaxed", c.relaxed,
                "Relax the --suspension network at the static equilibrium with the model's own suspension under this "
                "catenary, as a study's candidates (default: at the replaced network's reference length)");
}

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
};

// "0,200.5" → {0, 200.5}: positions along the line, m.
std::vector<double> parse_positions(const std::string& list) {
  std::vector<double> x;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    double v = 0;
    if (!CLI::detail::lexical_cast(item, v) || !std::isfinite(v))
      throw CLI::ValidationError("--positions", "expected comma-separated positions in m, got '" + list + "'");
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

// Beside OUT.csv: OUT.supports.csv (uplift of every support over time) and OUT.psd.csv (PSD of each
// pantograph's contact force in the section).
void write_line_files(std::FILE* info, const std::string& out, const analysis::CoupledSimulation& r) {
  const std::string stem = out.size() > 4 && out.ends_with(".csv") ? out.substr(0, out.size() - 4) : out;
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

// The cost guard (analysis/cost_guard.hpp): an estimate beyond 10 s is printed on standard error
// before the work starts; beyond max_seconds (--max-seconds; ≤ 0: no limit) the command is refused
// (exit 2) with how to proceed.
void cost_guard(double seconds, double bytes, double max_seconds, const std::string& what, const std::string& cheaper) {
  analysis::check_memory(bytes, what, cheaper);
  if (max_seconds > 0) analysis::check_cost(seconds, max_seconds, what, "give --max-seconds", cheaper);
  if (const std::string note = analysis::cost_note(seconds, what); !note.empty()) fmt::print(stderr, "{}\n", note);
}
// What makes work on a finite-element line cheaper (the keys of --set).
constexpr const char* kFeCheaper =
    "fewer spans with --set line.spans=N, a coarser mesh with mesh.element_length, the modal solve with solver.type=modal";

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
                                           cost_guard(c.catenary->estimated_seconds(tr, v, a.t_end),
                                                      c.catenary->estimated_bytes(tr, v, a.t_end), a.max_seconds,
                                                      "this run", std::string(kFeCheaper) + ", or a shorter --t-end");
                                         });
    for (const auto& note : panto.model.notes) fmt::print(info, "note: {}\n", note);
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
    if (criteria)
      return cli::report_acceptance(info, *criteria, analysis::verdict(*criteria, r), a.out, a.acceptance.strict,
                                    a.cat.unit == "kmh");
    return 0;
  }
  if (!a.acceptance.criteria.empty()) throw CLI::ValidationError("--acceptance", "needs --catenary FILE");
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

}  // namespace

// Largest number of points of a range option (--freq, --speeds, --fp).
constexpr double max_range_points = 1e6;
// Exit code of a sweep with an unstable periodic solution at some speed (docs/cli.md).
constexpr int exit_unstable = 4;

// "F0:DF:F1" → F0, F0 + DF, ..., F1 (inclusive within 1e-9 DF).
std::vector<double> frequency_range(const std::string& spec, const char* option = "--freq") {
  double f0 = 0, df = 0, f1 = 0;
  char c1 = 0, c2 = 0;
  std::istringstream in(spec);
  if (!(in >> f0 >> c1 >> df >> c2 >> f1) || c1 != ':' || c2 != ':' || !(in >> std::ws).eof() || !(f0 >= 0) ||
      !(df > 0) || !(f1 >= f0))
    throw CLI::ValidationError(option, "expected A:STEP:B with 0 <= A <= B and STEP > 0, got '" + spec + "'");
  // At most max_range_points points (docs/cli.md), counted in floating point before any cast (issue 15).
  const double n = std::floor((f1 - f0) / df + 1e-9);
  if (!std::isfinite(f1) || !(n < max_range_points))
    throw CLI::ValidationError(option, fmt::format("'{}' has {:.3g} points; at most {} are accepted (a larger STEP "
                                                   "or a shorter range)",
                                                   spec, n + 1, max_range_points));
  std::vector<double> f;
  for (long k = 0; k <= static_cast<long>(n); ++k) f.push_back(f0 + static_cast<double>(k) * df);
  for (std::size_t k = 1; k < f.size(); ++k)
    if (!(f[k] > f[k - 1]))
      throw CLI::ValidationError(option, fmt::format("'{}': STEP {:g} is below the resolution of the values", spec, df));
  return f;
}

struct AdmittanceArgs {
  std::string layout, freq, out;
  std::vector<std::string> params;
};

int cmd_admittance(const AdmittanceArgs& a) {
  io::check_output_path(a.out);
  network::Params params = parse_params(a.params);
  network::Network net;
  try {
    net = network::resolve(a.layout, params);
  } catch (const network::NetworkError& e) {
    std::string where = e.column > 0 ? fmt::format("\n  {}\n  {:>{}}", a.layout, "^", e.column) : "";
    throw ModelError(fmt::format("network '{}': {}{}", a.layout, e.what(), where));
  }
  const std::vector<double> f = frequency_range(a.freq);
  network::Network s = network::simplify(net);
  std::FILE* info = a.out.empty() ? stderr : stdout;
  fmt::print(info, "network: {}  →  {}\n", network::to_string(net, true), network::to_string(s, true));
  if (s.kind == network::Network::Kind::Rigid)
    throw ModelError(fmt::format("network '{}' is rigid with these values: its admittance is infinite", a.layout));
  if (s.kind != network::Network::Kind::Open) {
    network::Rational y = network::rational_admittance(s);
    auto poly = [](const network::Poly& p) {
      std::string t;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i] != 0)
          t += fmt::format("{}{:g}{}", t.empty() ? "" : " + ", p[i],
                           i == 0   ? ""
                           : i == 1 ? " s"
                                    : fmt::format(" s^{}", i));
      return t.empty() ? std::string("0") : t;
    };
    fmt::print(info, "Y(s) = F/v = ({}) / ({})\n", poly(y.num), poly(y.den));
  } else {
    fmt::print(info, "the network is open with these values: Y = 0\n");
  }
  for (double fk : f)
    if (!std::isfinite(std::abs(network::admittance(s, {0.0, 2 * std::numbers::pi * fk}))))
      throw ModelError(
          fmt::format("network '{}': Y is infinite at f = {:g} Hz (a spring path gives a static "
                      "stiffness); start --freq above 0",
                      a.layout, fk));
  OutputFile file(a.out);
  std::FILE* out = file.get();
  fmt::print(out, "f_hz,mag,phase_deg,re,im\n");
  for (double fk : f) {
    std::complex<double> y = network::admittance(s, {0.0, 2 * std::numbers::pi * fk});
    fmt::print(out, "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", fk, std::abs(y), std::arg(y) * 180 / std::numbers::pi,
               y.real(), y.imag());
  }
  file.commit();
  if (!a.out.empty()) fmt::print(info, "wrote {} ({} frequencies)\n", a.out, f.size());
  return 0;
}

struct SweepArgs {
  std::string model, out, speeds, integrator = "rk", method = "time";
  int harmonics = 8;
  CatenaryArgs cat;
  double rtol = 1e-6, atol = 1e-8;
  bool no_centripetal = false;
  cli::AcceptanceArgs acceptance;
  double max_seconds = analysis::default_max_seconds;
};

int cmd_sweep(const SweepArgs& a) {
  OutputFile file(a.out, {a.model, a.cat.catenary});  // checked before the sweep
  std::optional<analysis::AcceptanceCriteria> criteria;
  if (!a.acceptance.criteria.empty()) {
    criteria = io::load_acceptance(a.acceptance.criteria);
    io::check_output_path(cli::acceptance_path(a.out), {a.model, a.cat.catenary, a.out});
  }
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
                                                    std::string(kFeCheaper) + ", or fewer --speeds");
                                       });
  for (const auto& note : panto.model.notes) fmt::print("note: {}\n", note);
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
  fmt::print(out, "v_kmh,v_ms,mean,std,max,min,stat_max,stat_min,loss_pct{}{}{}\n",
             line ? ",f_mean,f_std,f_max,f_min,f_stat_max,f_stat_min,uplift_max_m" : "",
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
  if (!unstable.empty()) {
    fmt::print(stderr,
               "unstable: the periodic solution is unstable at {} {} (largest Floquet multiplier ≥ 1: parametric "
               "resonance, the response grows; stable = 0, statistics NaN); run those speeds with --method time\n",
               fmt::join(unstable, ", "), unit);
    return exit_unstable;
  }
  return verdict_code;
}

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
    const auto j = static_cast<std::size_t>(&dr - line.droppers().data()) % d.dropper_x.size();
    fmt::print("  {:7.2f}  {:.4f}{}  {:7.2f}\n", dr.x, dr.length,
               d.nominal_dropper_length.empty() ? "" : fmt::format(" [{:.3f}]", d.nominal_dropper_length[j]), dr.tension);
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
  std::string model = INERTA_SOURCE_DIR "/models/pantograph-3mass.yaml", speeds;
  CatenaryArgs cat;
  double tolerance = 1.0;
  std::string acceptance;
  double max_seconds = analysis::default_max_seconds;
};

// The finite-element line's modal solve against its direct solve (docs/catenary-fe.md "Modal solver"):
// the same runs on both, the EN 50317 statistics side by side; exit 1 if σ (raw or 20 Hz) differs by
// more than --tolerance %.
int cmd_check_reduction(CheckReductionArgs a) {
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
      fmt::print("  acceptance {}: direct {}, modal {}{}\n", criteria->name, analysis::passed(vd) ? "PASS" : "FAIL",
                 analysis::passed(vm) ? "PASS" : "FAIL",
                 differ.empty() ? "; every criterion the same" : fmt::format("; criteria that differ: {}", fmt::join(differ, "; ")));
    }
  }
  fmt::print("\nlargest difference of sigma (raw or 20 Hz): {:.3f} % (tolerance {:g} %)\n", worst, a.tolerance);
  if (worst > a.tolerance) {
    fmt::print(stderr, "check-reduction: the modal solve differs from the direct one by {:.3f} % in sigma, more than "
                       "--tolerance {:g} %: raise solver.cutoff or the window (solver.window_behind / window_ahead)\n",
               worst, a.tolerance);
    return 1;
  }
  return 0;
}

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

struct OptimiseArgs {
  std::string study, out;
  int map = 15;
  bool no_plots = false, force = false;
  int workers = 0;        ///< > 0: a local Dask cluster of this many processes
  std::string scheduler;  ///< a Dask scheduler's address
  double max_seconds = 0;  ///< > 0: refuse a study whose estimate (at its limit of evaluations) is above
};

// `optimise --workers N | --scheduler ADDRESS`: the study on Dask, by the Python module's driver
// (python/inerta/distributed.py), which this process becomes (exit code and Ctrl-C are its).
int run_distributed(const OptimiseArgs& a) {
  if (io::is_model_study(a.study))
    throw InvalidArgument(fmt::format("--workers/--scheduler: {} is a model study; only J2 studies (catenary:) are "
                                      "distributed so far — run it without", a.study));
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
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = std::string(INERTA_PYTHON_DIR) + (old && *old ? std::string(":") + old : std::string());
  ::setenv("PYTHONPATH", path.c_str(), 1);
  ::setenv("INERTA_SOURCE_DIR", INERTA_SOURCE_DIR, 0);
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

// Structure-based design (spec/07): optimise every layout of the study, print and write the table.
int cmd_optimise(const OptimiseArgs& a) {
  if (a.workers > 0 || !a.scheduler.empty()) return run_distributed(a);
  if (!a.out.empty()) io::prepare_output_folder(a.out, io::study_output_names(), a.force);  // before any computation
  if (io::is_model_study(a.study)) return inerta::cli::run_model_study(a.study, a.out, !a.no_plots);
  optim::Study study = io::load_study(a.study);
  const bool tty = isatty(STDOUT_FILENO);
  if (study.all)
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
  const auto wall0 = std::chrono::steady_clock::now();
  if (const double e = optim::estimated_evaluation_seconds(study); e > 0) {
    // The time domain: its searches are bounded by their evaluations (refine.max_evaluations for
    // a multi-fidelity study, search.max_evaluations per start otherwise).
    const long evals = study.coarse ? static_cast<long>(study.refine.max_evaluations) * study.refine_candidates *
                                          static_cast<long>(study.layouts.size())
                                    : static_cast<long>(study.search.max_evaluations) * study.search.starts *
                                          static_cast<long>(study.layouts.size());
    if (e > 1) fmt::print("one evaluation ≈ {:.1f} s (estimated: {} catenaries × {} speeds in the time domain)\n", e,
                          study.catenaries.size(), study.speeds.size());
    cost_guard(e * static_cast<double>(evals), 0, a.max_seconds, fmt::format("this study, at its limit of {} evaluations,", evals),
               "fewer layouts, starts or search.max_evaluations, fewer speeds, or a coarse: stage");
  }
  const network::Network baseline = optim::default_suspension(study);
  const optim::StudyCost def = optim::evaluate(study, baseline);
  if (def.unstable_speed > 0)
    throw NumericalError(fmt::format("{}: the default suspension's periodic solution is unstable at {:.4g} km/h "
                                     "(Floquet multiplier ≥ 1): the study has no baseline",
                                     study.source, def.unstable_speed * 3.6));
  std::vector<optim::LayoutResult> results;
  std::vector<optim::StructureEntry> entries;
  std::vector<std::size_t> order;  // layouts: all — results[k] is entries[order[k]]
  int verified_best = -1;          // the index in results of the best time-domain re-check
  if (study.all) {
    std::vector<optim::LayoutResult> all;
    entries = optim::optimise_all(study, all, inerta::cli::structure_progress("N"));
    order = optim::ranking(entries);
    for (std::size_t i : order) results.push_back(all[i]);  // ranked: results.csv best first
  } else {
    for (const auto& layout : study.layouts) {
      results.push_back(optim::optimise_layout(study, layout, [&](int start, int evals, double best) {
        if (tty)
          fmt::print("\r  {:<12} start {}/{}  evaluations {:>5}  best J {:.4f} N   ", layout, start + 1,
                     study.search.starts, evals, best);
        std::fflush(stdout);
      }));
      if (tty) fmt::print("\r{:80}\r", "");
      const auto& r = results.back();
      if (study.coarse)
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
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (study.all) {
    inerta::cli::print_structure(entries, def.J, "N");
    int evaluations = 0;
    for (const auto& e : entries) evaluations += e.evaluations;
    fmt::print("{} networks, {} evaluations in {:.1f} s ({:.0f} evaluations/s)\n", entries.size(), evaluations, wall,
               evaluations / wall);
    // The fast path linearises about the static state: the best few distinct designs are re-checked
    // by the time-domain reference, which is what a user should trust when they differ.
    // Ranked by the verified (time-domain) J2: where the fast path is off by a few per cent (issue 24:
    // notch networks near the pantograph's resonance) its order can be wrong.
    fmt::print("\ntime-domain re-check of the best {} distinct designs (analysis::sweep, all catenaries and speeds), "
               "ranked by the time-domain J2:\n",
               std::min<std::size_t>(5, entries.size()));
    fmt::print("  {:<44} {:>13} {:>13} {:>9} {:>6} {:>9}\n", "reduced network", "periodic [N]", "time [N]", "periodic", "rank",
               "settles");
    std::vector<std::string> seen;
    struct Checked {
      std::size_t entry = 0;
      int periodic_rank = 0;
      optim::StudyCost t{};
      std::string failure{};
    };
    std::vector<Checked> checked;
    for (std::size_t i : optim::ranking(entries)) {
      const auto& e = entries[i];
      if (seen.size() == 5) break;
      if (!e.feasible || std::find(seen.begin(), seen.end(), e.reduced_structure) != seen.end()) continue;
      seen.push_back(e.reduced_structure);
      Checked c;
      c.entry = i, c.periodic_rank = static_cast<int>(seen.size());
      try {
        c.t = optim::evaluate_time(study, network::resolve(e.expression, e.values));
      } catch (const NumericalError& err) {
        c.failure = err.what(), c.t.J = INFINITY;
      }
      checked.push_back(std::move(c));
    }
    std::stable_sort(checked.begin(), checked.end(), [](const Checked& x, const Checked& y) { return x.t.J < y.t.J; });
    std::string csv = "network,reduced,J2_periodic,J2_time,v_kmh_time,periodic_rank,settling_spans\n";
    for (const Checked& c : checked) {
      const auto& e = entries[c.entry];
      if (!c.failure.empty()) {
        fmt::print("  {:<44} {:>13.4f} {:>13}  ({})\n", e.reduced, e.J, "failed", c.failure);
        continue;
      }
      const optim::StudyCost& t = c.t;
      // The slowest free vibration (Floquet multiplier of the periodic path): a time-domain run shorter
      // than its decay measures the transient's beating, not the steady state (issue 24 item 4).
      double settle = 0;
      try {
        settle = optim::evaluate(study, network::resolve(e.expression, e.values)).settling_spans();
      } catch (const NumericalError&) {
      }
      const analysis::RunOptions run;
      const bool slow = settle > run.max_spans;
      fmt::print("  {:<44} {:>13.4f} {:>13.4f} {:>+8.2f}% {:>6} {:>9}{}\n", e.reduced, e.J, t.J, 100 * (e.J - t.J) / t.J,
                 c.periodic_rank, settle > 0 ? fmt::format("{:.0f} sp", std::ceil(settle)) : "-",
                 slow && std::abs(e.J - t.J) > 0.01 * t.J
                     ? "  a free vibration outlasts the time-domain run: neither J2 is settled"
                     : std::abs(e.J - t.J) > 0.01 * t.J ? "  the fast path is off by more than 1 %" : "");
      csv += fmt::format("\"{}\",\"{}\",{:.10g},{:.10g},{:.6g},{},{:.6g}\n", e.expression, e.reduced, e.J, t.J,
                         t.speed * 3.6, c.periodic_rank, settle);
    }
    if (!checked.empty() && checked.front().failure.empty()) {
      verified_best = static_cast<int>(std::find(order.begin(), order.end(), checked.front().entry) - order.begin());
      if (checked.front().periodic_rank != 1)
        fmt::print("  the time domain ranks them differently: the best verified design is {} (fast path's #{}); "
                   "the figures and the summary below are of it\n",
                   entries[checked.front().entry].reduced, checked.front().periodic_rank);
    }
    if (!a.out.empty()) {
      std::filesystem::create_directories(a.out);
      io::write_text_file(a.out + "/recheck.csv", csv);
    }
  } else {
    fmt::print("{}", io::study_table(study, def, results));
  }
  fmt::print("default suspension ({}) J2 = {:.3f} N at {:.0f} km/h; wall {:.1f} s\n",
             network::to_string(baseline, true), def.J, def.speed * 3.6, wall);
  if (!study.admittance_degrees.empty()) {
    std::vector<optim::BoundCandidate> cands{{"default " + network::to_string(baseline, true), baseline, def.J, def.J}};
    for (const auto& r : results) try {  // a layout without a design (values missing) is skipped
        cands.push_back({r.layout + " " + network::to_string(optim::design_network(r.layout, r.values), true),
                         optim::design_network(r.layout, r.values), r.cost.J, r.cost.J});
      } catch (const network::NetworkError&) {
      }
    const auto bounds = optim::admittance_bounds(
        study.admittance_degrees, cands, [&](int d, const network::Network& w) { return optim::admittance_bound(study, d, w); },
        inerta::cli::print_admittance_bound(def.J, "N"));
    if (!a.out.empty()) {
      io::write_admittance_results(a.out, bounds, def.J);
      fmt::print("wrote admittance.csv admittance.json in {}\n", a.out);
    }
  }
  // after the bounds: pareto.png draws them (admittance.csv)
  if (study.all && !a.out.empty()) inerta::cli::write_structure(a.out, study.name, "J2", "N", def.J, entries, !a.no_plots);
  std::size_t best = 0;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].cost.penalised() < results[best].cost.penalised()) best = i;  // within the limits first
  if (verified_best >= 0) best = static_cast<std::size_t>(verified_best);  // the time domain has the last word
  if (!a.out.empty()) {
    io::write_study_results(a.out, study.name, def, results);
    fmt::print("wrote {}/results.csv and {}/results.json\n", a.out, a.out);
  }
  // The winner re-checked in the time domain (the reference method): with --out, as part of the
  // figures' post-processing (its σ(v) with the centripetal correction on).
  optim::StudyCost check;
  if (!a.out.empty()) {
    fmt::print("post-processing for the figures:\n");
    auto t0 = std::chrono::steady_clock::now();
    std::string current;
    optim::ReportOptions ro;
    ro.map_size = a.map;
    ro.best = verified_best;
    const optim::Report report =
        optim::make_report(study, results, ro, [&](int step, int steps, const std::string& what, int done, int total) {
          if (!what.empty()) {
            current = fmt::format("  [{}/{}] {}", step, steps, what);
            t0 = std::chrono::steady_clock::now();
            fmt::print("{}{}", current, tty ? "" : " ...");
          }
          if (tty && done < total && total > 1) fmt::print("\r{}: {}/{}", current, done, total);
          if (done == total) {
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (tty)
              fmt::print("\r{}: {:.1f} s{:12}\n", current, s, "");
            else
              fmt::print(" {:.1f} s\n", s);
          }
          std::fflush(stdout);
        });
    check = report.time_check;
    const auto files = io::write_study_report(report, a.out);
    fmt::print("wrote");
    for (const auto& f : files) fmt::print(" {}", std::filesystem::path(f).filename().string());
    fmt::print(" in {}\n", a.out);
    for (const auto& c : report.centripetal) {
      const optim::StudyCost on = optim::worst_of(c.on), off = optim::worst_of(c.off);
      if (c.off_simulated)
        fmt::print("centripetal correction, {}: J2 = {:.4f} N on, {:.4f} N off ({:+.3f} %)\n", c.design.label, on.J,
                   off.J, 100 * (off.J - on.J) / on.J);
      else
        fmt::print("centripetal correction, {}: no inerter, nothing to correct\n", c.design.label);
    }
    if (!a.no_plots) draw_plots(a.out);
  } else if (study.method == optim::Study::Method::Periodic) {
    check = optim::evaluate_time(study, network::resolve(results[best].layout, results[best].values));
  }
  if (study.method == optim::Study::Method::Time)
    fmt::print("best: {} ({}) — J2 = {:.3f} N at {:.0f} km/h (time domain){}\n", results[best].layout,
               results[best].expression, results[best].cost.J, results[best].cost.speed * 3.6,
               results[best].cost.feasible ? "" : "; no design keeps the limits: " + results[best].cost.violation);
  else
    fmt::print("best: {} ({}) — time-domain re-check J2 = {:.3f} N at {:.0f} km/h (periodic {:.3f} N, {:+.2f} %)\n",
               results[best].layout, results[best].expression, check.J, check.speed * 3.6, results[best].cost.J,
               100 * (results[best].cost.J - check.J) / check.J);
  return 0;
}

int main(int argc, char** argv) {
  io::remove_partial_outputs_on_signal();  // Ctrl-C leaves no half-written file (io/files.hpp)
  CLI::App app{"Inerta — inerter-based vibration suppression for multibody systems (docs/cli.md)"};
  app.require_subcommand(1);

  std::string check_model;
  auto* check = app.add_subcommand("check", "Validate a model (print bodies, constraints, DOF), a lumped pantograph or a catenary file");
  check->add_option("model", check_model, "Model, lumped pantograph or catenary file (YAML)")->required();
  std::vector<std::string> check_sets;
  check->add_option("--set", check_sets, "Override a value NAME.KEY=VALUE of the file (repeatable)");

  using inerta::cli::count_in, inerta::cli::count_rule, inerta::cli::number_in, inerta::cli::number_rule, inerta::cli::positive;

  SimulateArgs sa;
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
                  "Several pantographs (copies of the model) at these positions along the line, m, e.g. 0,200");
  cli::add_acceptance_options(sim, sa.acceptance);
  sim->add_option("--max-seconds", sa.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));

  AdmittanceArgs aa;
  auto* adm = app.add_subcommand("admittance", "Admittance Y = force / relative velocity of a network (CSV)");
  adm->add_option("layout", aa.layout, "Named layout (S2-default, S1-3, ...) or expression such as \"b-(k|c)\"")
      ->required();
  adm->add_option("--param", aa.params, "Element value NAME=VALUE (SI; 0 = open, inf = rigid); repeatable");
  adm->add_option("--freq", aa.freq, "Frequencies F0:DF:F1 in Hz")->required();
  adm->add_option("--out", aa.out, "CSV file (default: standard output)");

  SweepArgs wa;
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
  swp->add_option("--max-seconds", wa.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));

  ModesArgs ma;
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

  FrfArgs fa;
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

  CatenaryResponseArgs ca;
  auto* crs = app.add_subcommand("catenary-response",
                                 "Lumped catenary alone under a constant upward force: acceleration amplitude vs f_p");
  crs->add_option("catenary", ca.catenary, "Catenary file (YAML)")->required();
  crs->add_option("--force", ca.force, "Constant upward force, N")->capture_default_str()->check(number_rule(analysis::force_rule));
  crs->add_option("--fp", ca.fp, "Pumping frequencies F0:DF:F1 in Hz (f_p = v / L)")->required();
  crs->add_option("--set", ca.sets, "Override a catenary value (repeatable)");
  crs->add_option("--out", ca.out, "CSV file (default: standard output)");

  FitArgs fit_args;
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
  CheckReductionArgs cra;
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
  crd->add_option("--max-seconds", cra.max_seconds, "Refuse (exit 2) a run whose estimated wall time on a 2-core machine is above S seconds (default 600; docs/cli.md \"Long runs\")")
      ->check(number_rule(analysis::max_seconds_rule));
  cat_cmd->require_subcommand(1);

  CLI::App* idn = inerta::cli::add_identify_commands(app);  // apps/inerta/identify.cpp
  CLI::App* rms = inerta::cli::add_rms_command(app);         // apps/inerta/linear.cpp
  CLI::App* nets = inerta::cli::add_networks_command(app);   // apps/inerta/networks.cpp
  CLI::App* pan = inerta::cli::add_pantograph_command(app);  // apps/inerta/acceptance.cpp

  OptimiseArgs oa;
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
                  "Refuse (exit 2) a study whose estimate at its limit of evaluations is above S seconds (default: no "
                  "limit; the estimate is printed beyond 10 s)")
      ->check(number_rule(analysis::max_seconds_rule));
  opt->add_flag("--force", oa.force,
                "Use an --out folder that is not empty: the files a study writes there are removed first");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (check->parsed()) return cmd_check(check_model, check_sets);
    if (sim->parsed()) return cmd_simulate(sa);
    if (adm->parsed()) return cmd_admittance(aa);
    if (swp->parsed()) return cmd_sweep(wa);
    if (mds->parsed()) return cmd_modes(ma);
    if (frf->parsed()) return cmd_frf(fa);
    if (crs->parsed()) return cmd_catenary_response(ca);
    if (fit->parsed()) return cmd_catenary_fit(fit_args);
    if (crd->parsed()) return cmd_check_reduction(cra);
    if (idn->parsed()) return inerta::cli::run_identify();
    if (rms->parsed()) return inerta::cli::run_rms();
    if (nets->parsed()) return inerta::cli::run_networks();
    if (pan->parsed()) return inerta::cli::run_pantograph();
    if (opt->parsed()) return cmd_optimise(oa);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ModelError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const NumericalError& e) {
    fmt::print(stderr, "numerical failure: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
