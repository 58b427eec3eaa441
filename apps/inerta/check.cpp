// `inerta check FILE` (docs/cli.md): a model, a lumped pantograph or a catenary file.
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"

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
#include "inerta/catenary/fe_schema.hpp"
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

namespace check_command {
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
    const std::vector<catenary::FeLinkedSection> linked = catenary::link_sections(d);
    for (std::size_t k = 0; k < linked.size(); ++k) {  // a line of tension sections (issue 35)
      const catenary::FeLinkedSection& ls = linked[k];
      const catenary::FeCatenaryData& s = ls.line;
      fmt::print("tension section {}: spans {} to {} ({:g} … {:g} m), contact wire {} (T = {:g} N), messenger T = {:g} N, "
                 "anchors {}\n",
                 k + 1, ls.first_span + 1, ls.first_span + s.spans, ls.line_start, ls.line_start + s.spans * s.span,
                 ls.wire_label, s.contact_wire.tension, s.messenger.tension,
                 s.anchor.pinned ? "pinned" : fmt::format("on a tensioning device ({:g} N/m, {:g} kg)", s.anchor.stiffness, s.anchor.mass));
    }
    if (d.sectioned()) {
      auto heights = [](const std::vector<double>& z, const std::vector<double>& x) {
        if (x.empty()) return fmt::format("[{}] m at its supports", fmt::join(z, ", "));
        std::vector<std::string> p;
        for (std::size_t i = 0; i < x.size() && i < z.size(); ++i) p.push_back(fmt::format("{:g}: {:g}", x[i], z[i]));
        return fmt::format("{{{}}} (m from the overlap's first support: m)", fmt::join(p, ", "));
      };
      fmt::print("overlaps: {} spans each; contact-wire heights: outgoing {}, incoming {}\n", d.overlap_spans,
                 heights(d.overlap_outgoing, d.overlap_outgoing_x), heights(d.overlap_incoming, d.overlap_incoming_x));
    }
    for (const auto& [which, w] : {std::pair{"messenger", d.messenger}, std::pair{"contact wire", d.contact_wire}})
      fmt::print("{:<13} wave speed sqrt(T/rho A) = {:.2f} m/s ({:.1f} km/h){}\n", std::string(which) + ":", w.wave_speed(),
                 3.6 * w.wave_speed(),
                 std::string(which) == "contact wire" && d.wear.any() && d.wear.x.empty()
                     ? fmt::format("; worn: {:.2f} m/s ({:.1f} km/h)", w.wave_speed() / std::sqrt(d.wear.uniform / 100),
                                   3.6 * w.wave_speed() / std::sqrt(d.wear.uniform / 100))
                     : "");
    fmt::print("droppers: {} a span, {} in all{}\n", n, n * static_cast<std::size_t>(d.spans),
               d.stitch.present ? fmt::format("; stitch droppers: {} a span, {} in all ({}; none at the 2 end masts)",
                                              d.stitch.dropper_x.size(), d.stitch.dropper_x.size() * static_cast<std::size_t>(d.spans),
                                              d.stitch.enabled ? "stitch wires at the interior masts, ends clamped to the messenger"
                                                               : "disabled: every stitch dropper hangs from the messenger")
                                : "");
    {
      const catenary::FeIrregularity& irr = d.irregularity;
      if (!irr.any()) {
        fmt::print("irregularity: none (a perfect line)\n");
      } else {
        if (irr.dropper_length_std > 0)
          fmt::print("irregularity: random dropper-length errors, std {:g} m, seed {} (normal, truncated at ±4 std)\n",
                     irr.dropper_length_std, irr.seed);
        if (!irr.dropper_length_errors.empty())
          fmt::print("irregularity: explicit dropper-length errors for {} droppers, largest {:g} m\n",
                     irr.dropper_length_errors.size(),
                     *std::max_element(irr.dropper_length_errors.begin(), irr.dropper_length_errors.end(),
                                       [](double a, double b) { return std::abs(a) < std::abs(b); }));
        if (!irr.height_error_x.empty())
          fmt::print("irregularity: contact-wire height errors from {} ({} points)\n", irr.height_errors_file,
                     irr.height_error_x.size());
        for (const auto& pm : irr.point_masses) fmt::print("irregularity: point mass {:g} kg at x = {:g} m\n", pm.mass, pm.x);
      }
    }
    if (!d.wear.any()) {
      fmt::print("wear: none (a new contact wire)\n");
    } else if (d.wear.x.empty()) {
      const double p = d.wear.uniform / 100;
      fmt::print("wear: {:g} % of the contact wire's section remaining along the line: mass per length {:g} kg/m, EI {:g} N·m² "
                 "(× {:g} and × {:g}), tension unchanged\n",
                 d.wear.uniform, p * d.contact_wire.mass_per_length, p * p * d.contact_wire.EI, p, p * p);
    } else {
      fmt::print("wear: the contact wire's section remaining from {} ({} points, {:g} … {:g} %)\n", d.wear.file, d.wear.x.size(),
                 *std::min_element(d.wear.percent.begin(), d.wear.percent.end()),
                 *std::max_element(d.wear.percent.begin(), d.wear.percent.end()));
    }
    // Every key's value from the schema (catenary/fe_schema.hpp), a section a line.
    fmt::print("keys (docs/model-format.md; the line's values, a tension section's own above):\n");
    std::string section, line;
    for (const catenary::FeKey& k : catenary::fe_keys()) {
      if (k.path.rfind("stitch.", 0) == 0 && !d.stitch.present) continue;
      if (k.path == "line.spans" && d.sectioned()) continue;
      const std::string top = k.path.substr(0, k.path.find('.'));
      if (top != section) {
        if (!line.empty()) fmt::print("  {}\n", line);
        section = top, line = top + ":";
      }
      line += fmt::format("{} {} {}", line.back() == ':' ? "" : ",", k.path.substr(top.size() + 1), k.value_text(d));
    }
    fmt::print("  {}\n", line);
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

std::string check_model;
std::vector<std::string> check_sets;

}  // namespace
}  // namespace check_command

Command add_check_command(CLI::App& app) {
  using namespace check_command;
  auto* check = app.add_subcommand("check", "Validate a model (print bodies, constraints, DOF), a lumped pantograph or a catenary file");
  check->add_option("model", check_model, "Model, lumped pantograph or catenary file (YAML)")->required();
  check->add_option("--set", check_sets, "Override a value NAME.KEY=VALUE of the file (repeatable)");
  return {check, [] { return cmd_check(check_model, check_sets); }};
}

}  // namespace inerta::cli
