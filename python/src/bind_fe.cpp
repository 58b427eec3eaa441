// The finite-element catenary (catenary/fe_catenary.hpp): its data, the assembled line for
// inspection (mesh, droppers, static state, elasticity), the catenary type, the lumped fit and its
// writers. Runs go through the generic Catenary (simulate_coupled, run_speed, sweep).
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/fe_schema.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/lumped_fit_file.hpp"

namespace inerta::python {

namespace {

using catenary::FeCatenaryData;
using catenary::FeLine;

template <class F>
py::object per_x(const py::object& x, F&& f) {
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) return py::float_(f(x.cast<double>()));
  const std::vector<double> v = doubles(x);
  py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
  {
    py::gil_scoped_release nogil;
    for (std::size_t i = 0; i < v.size(); ++i) out.mutable_data()[i] = f(v[i]);
  }
  return out;
}

/// A sparse matrix as COO triplets (data, (row, col)) and its shape: scipy.sparse.coo_matrix(*t).
py::tuple triplets(const Eigen::SparseMatrix<double>& A) {
  std::vector<double> v;
  std::vector<int> r, c;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
      v.push_back(it.value()), r.push_back(static_cast<int>(it.row())), c.push_back(static_cast<int>(it.col()));
  return py::make_tuple(py::make_tuple(copy(v), py::make_tuple(copy(r), copy(c))),
                        py::make_tuple(A.rows(), A.cols()));
}

}  // namespace

void bind_fe(py::module_& m) {
  py::class_<catenary::FeWire>(m, "FeWire", "A tensioned wire: tension T (N), ρA (kg/m), EI (N·m²).")
      .def(py::init([](double T, double rhoA, double EI) { return catenary::FeWire{T, rhoA, EI}; }),
           py::arg("tension") = 0.0, py::arg("mass_per_length") = 0.0, py::arg("EI") = 0.0)
      .def_readwrite("tension", &catenary::FeWire::tension, "N")
      .def_readwrite("mass_per_length", &catenary::FeWire::mass_per_length, "kg/m")
      .def_readwrite("EI", &catenary::FeWire::EI, "N·m²")
      .def("wave_speed", &catenary::FeWire::wave_speed, "sqrt(T/ρA), m/s");

  py::class_<FeCatenaryData> d(m, "FeCatenaryData",
                               "Everything a finite-element catenary file gives (docs/model-format.md): geometry "
                               "(m), wires, droppers, supports, mesh, Rayleigh damping, HHT-α time step (s).");
  d.def(py::init<>())
      .def_readwrite("span", &FeCatenaryData::span, "m")
      .def_readwrite("spans", &FeCatenaryData::spans)
      .def_readwrite("encumbrance", &FeCatenaryData::encumbrance, "m")
      .def_readwrite("dropper_x", &FeCatenaryData::dropper_x, "m from the span's first mast")
      .def_readwrite("presag", &FeCatenaryData::presag, "m, positive down")
      .def_readwrite("nominal_dropper_length", &FeCatenaryData::nominal_dropper_length, "m")
      .def_readwrite("messenger", &FeCatenaryData::messenger)
      .def_readwrite("contact_wire", &FeCatenaryData::contact_wire)
      .def_readwrite("dropper_EA", &FeCatenaryData::dropper_EA, "N")
      .def_readwrite("dropper_mass_per_length", &FeCatenaryData::dropper_mass_per_length, "kg/m")
      .def_readwrite("clamp_mass_messenger", &FeCatenaryData::clamp_mass_messenger, "kg")
      .def_readwrite("clamp_mass_contact", &FeCatenaryData::clamp_mass_contact, "kg")
      .def_readwrite("support_stiffness", &FeCatenaryData::support_stiffness, "N/m")
      .def_readwrite("support_mass", &FeCatenaryData::support_mass, "kg")
      .def_readwrite("registration_stiffness", &FeCatenaryData::registration_stiffness, "N/m")
      .def_readwrite("registration_mass", &FeCatenaryData::registration_mass, "kg")
      .def_readwrite("element_length", &FeCatenaryData::element_length, "m")
      .def_readwrite("rayleigh_mass", &FeCatenaryData::rayleigh_mass, "1/s")
      .def_readwrite("rayleigh_stiffness", &FeCatenaryData::rayleigh_stiffness, "s")
      .def_readwrite("gravity", &FeCatenaryData::gravity, "m/s²")
      .def_readwrite("time_step", &FeCatenaryData::time_step, "s")
      .def_readwrite("hht_alpha", &FeCatenaryData::hht_alpha)
      .def_readwrite("section_first", &FeCatenaryData::section_first, "analysis section, first span (1-based; −1 default)")
      .def_readwrite("section_last", &FeCatenaryData::section_last)
      .def_property(
          "solver", [](const FeCatenaryData& d) { return d.solver == FeCatenaryData::Solver::Modal ? "modal" : "direct"; },
          [](FeCatenaryData& d, const std::string& s) {
            if (s != "modal" && s != "direct") throw InvalidArgument("FeCatenaryData.solver", "solver", "expected 'modal' or 'direct'");
            d.solver = s == "modal" ? FeCatenaryData::Solver::Modal : FeCatenaryData::Solver::Direct;
          },
          "'modal' (a window of spans, modes below modal_cutoff; docs/catenary-fe.md) or 'direct' (the whole line)")
      .def_readwrite("modal_cutoff", &FeCatenaryData::modal_cutoff, "Hz, highest natural frequency kept")
      .def_readwrite("window_behind", &FeCatenaryData::window_behind, "spans behind the rear pantograph's span (−1: whole line)")
      .def_readwrite("window_ahead", &FeCatenaryData::window_ahead, "spans ahead of the leading pantograph's span (−1: whole line)")
      .def_readwrite("tension_sections", &FeCatenaryData::tension_sections,
                     "a line of tension sections as written: each section whole (empty: one section); then call join_sections()")
      .def_readwrite("overlap_spans", &FeCatenaryData::overlap_spans, "spans consecutive sections share")
      .def_readwrite("overlap_outgoing", &FeCatenaryData::overlap_outgoing, "m, the ending section's contact wire at the overlap's supports")
      .def_readwrite("overlap_incoming", &FeCatenaryData::overlap_incoming, "m, the starting section's")
      .def_readwrite("overlap_outgoing_x", &FeCatenaryData::overlap_outgoing_x,
                     "m from the overlap's first support: the outgoing profile's points (empty: the supports)")
      .def_readwrite("overlap_incoming_x", &FeCatenaryData::overlap_incoming_x, "m, the incoming profile's points")
      .def_readwrite("mast_height", &FeCatenaryData::mast_height, "m, a section's contact wire at each of its masts (empty: 0)")
      .def_readwrite("height_x", &FeCatenaryData::height_x, "m from a section's first mast: its height profile's points (empty: mast_height)")
      .def_readwrite("height_z", &FeCatenaryData::height_z, "m, up: the profile's heights")
      .def("height_at", &FeCatenaryData::height_at, py::arg("x"), "m: a section's contact-wire height at x (its profile, linear)")
      .def("join_sections", &FeCatenaryData::join_sections,
           "checks that the tension sections form a line and sets the line's spans and span from them")
      .def("linked_sections", [](const FeCatenaryData& d) { return catenary::link_sections(d); },
           "the tension sections placed along the line (link_sections): FeLinkedSection each")
      .def("validate", &FeCatenaryData::validate, "InvalidArgument naming the offending value");

  py::class_<catenary::FeLinkedSection>(m, "FeLinkedSection", "A tension section placed along its line (link_sections).")
      .def_readonly("line", &catenary::FeLinkedSection::line, "the section as a line, its heights set from the overlaps")
      .def_readonly("line_start", &catenary::FeLinkedSection::line_start, "m, its first mast along the line")
      .def_readonly("first_span", &catenary::FeLinkedSection::first_span, "its first span along the line (0-based)")
      .def_readonly("wire_label", &catenary::FeLinkedSection::wire_label, "its contact wire: 1 or 2");

  py::class_<FeLine::Dropper>(m, "FeDropper", "One dropper of the assembled line.")
      .def_readonly("x", &FeLine::Dropper::x, "m along the line")
      .def_readonly("node", &FeLine::Dropper::node)
      .def_readonly("dof_m", &FeLine::Dropper::dof_m)
      .def_readonly("dof_c", &FeLine::Dropper::dof_c)
      .def_readonly("length", &FeLine::Dropper::length, "unstretched, from the form-finding, m")
      .def_readonly("stiffness", &FeLine::Dropper::stiffness, "N/m")
      .def_readonly("tension", &FeLine::Dropper::tension, "static, N");

  py::class_<FeLine, std::shared_ptr<FeLine>>(m, "FeLine",
                                              "The assembled finite-element line (mesh, matrices, form-found static "
                                              "state), for inspection. Immutable.")
      .def(py::init([](const FeCatenaryData& data) {
             py::gil_scoped_release nogil;
             return std::make_shared<FeLine>(data);
           }),
           py::arg("data"))
      .def_property_readonly("data", &FeLine::data)
      .def_property_readonly("n_nodes", &FeLine::n_nodes)
      .def_property_readonly("n_dofs", &FeLine::n_dofs)
      .def_property_readonly("length", &FeLine::length, "m")
      .def_property_readonly("node_x", [](const FeLine& l) { return copy(l.node_x()); }, "m")
      .def("dof", &FeLine::dof, py::arg("wire"), py::arg("node"), py::arg("component"),
           "free DOF of wire 0 (messenger) / 1 (contact wire) at a node, component 0 (w) / 1 (θ); −1 if fixed")
      .def("matrices", [](const FeLine& l) {
        py::dict d;
        d["M"] = triplets(l.M());
        d["K"] = triplets(l.K());
        d["C"] = triplets(l.C());
        return d;
      }, "{'M', 'K', 'C'}: each ((data, (row, col)), shape), for scipy.sparse.coo_matrix; kg, N/m, N·s/m")
      .def_property_readonly("droppers", &FeLine::droppers)
      .def_property_readonly("support_x", [](const FeLine& l) { return copy(l.support_x()); }, "m")
      .def_property_readonly("support_dofs", &FeLine::support_dofs)
      .def("static_height", [](const FeLine& l, const py::object& x) {
        return per_x(x, [&](double v) { return l.static_height(v); });
      }, py::arg("x"), "contact-wire height in the static state at x (m), m")
      .def("static_slope", [](const FeLine& l, const py::object& x) {
        return per_x(x, [&](double v) { return l.static_slope(v); });
      }, py::arg("x"))
      .def("elasticity", [](const FeLine& l, const py::object& x) {
        return per_x(x, [&](double v) { return l.elasticity(v); });
      }, py::arg("x"), "static uplift per newton at x, m/N (all droppers taut)")
      .def("messenger_height", &FeLine::messenger_height, py::arg("node"), "m")
      .def("dropper_length_error_max", &FeLine::dropper_length_error_max, "m")
      .def("contact_shape", [](const FeLine& l, double x) {
        const auto s = l.contact_shape(x);
        return py::make_tuple(s.node, s.dofs, s.N, s.dN);
      }, py::arg("x"), "(node, 4 DOFs, Hermite values N, dN/dx) of the contact wire at x")
      .def("contact_displacement", &FeLine::contact_displacement, py::arg("u"), py::arg("x"), "N(x)ᵀ u, m")
      .def("load_vector", &FeLine::load_vector, py::arg("x"), py::arg("F"), "F N(x), N")
      .def("static_displacement", [](const FeLine& l, const py::object& x, const py::object& F) {
        std::vector<char> slack;
        const std::vector<double> xv = doubles(x), Fv = doubles(F);
        Eigen::VectorXd u;
        {
          py::gil_scoped_release nogil;
          u = l.static_displacement(xv, Fv, &slack);
        }
        std::vector<bool> s(slack.begin(), slack.end());
        return py::make_tuple(u, s);
      }, py::arg("x"), py::arg("F"), "(u, slack per dropper) under upward forces F (N) at x (m)")
      .def("describe", &FeLine::describe);

  py::class_<catenary::FeCatenary, catenary::Catenary, std::shared_ptr<catenary::FeCatenary>>(
      m, "FeCatenary", "The finite-element catenary as a catenary type (co-simulated, several pantographs, penalty contact).")
      .def(py::init([](const FeCatenaryData& data) {
             py::gil_scoped_release nogil;
             return std::make_shared<catenary::FeCatenary>(data);
           }),
           py::arg("data"), "Form-finding and factorisation of the line (seconds for a long line).")
      .def_property_readonly("line", &catenary::FeCatenary::line, py::return_value_policy::reference_internal);

  py::class_<catenary::LumpedFit>(m, "LumpedFit", "The lumped catenary of eq. 7.1 fitted to a finite-element line.")
      .def_readonly("lumped", &catenary::LumpedFit::lumped)
      .def_readonly("span", &catenary::LumpedFit::span, "the span fitted (1-based)")
      .def_property_readonly("x", [](const catenary::LumpedFit& f) { return copy(f.x); }, "m from the span's first mast")
      .def_property_readonly("elasticity", [](const catenary::LumpedFit& f) { return copy(f.elasticity); }, "m/N")
      .def_property_readonly("mass", [](const catenary::LumpedFit& f) { return copy(f.mass); }, "kg")
      .def_property_readonly("damping", [](const catenary::LumpedFit& f) { return copy(f.damping); }, "N·s/m")
      .def_property_readonly("fitted_elasticity", [](const catenary::LumpedFit& f) { return copy(f.fitted_elasticity); })
      .def_readonly("max_elasticity_error", &catenary::LumpedFit::max_elasticity_error)
      .def_readonly("max_smoothed_error", &catenary::LumpedFit::max_smoothed_error)
      .def_readonly("rms_error", &catenary::LumpedFit::rms_error)
      .def_readonly("rms_smoothed_error", &catenary::LumpedFit::rms_smoothed_error);
  m.def("fit_lumped", [](const py::object& line, int span, int points) {
    const FeLine* l = py::isinstance<catenary::FeCatenary>(line) ? &line.cast<const catenary::FeCatenary&>().line()
                                                                   : &line.cast<const FeLine&>();
    py::gil_scoped_release nogil;
    return catenary::fit_lumped(*l, span, points);
  }, py::arg("line"), py::arg("span") = 0, py::arg("points") = 220,
        "The lumped catenary fitted to an FeLine or FeCatenary along one span (1-based; 0 the middle one), as "
        "`inerta catenary fit`.");
  m.def("beam_stiffness", &catenary::beam_stiffness, py::arg("EI"), py::arg("tension"), py::arg("length"),
        "4×4 stiffness of a tensioned Euler–Bernoulli beam element on [w_i, θ_i, w_j, θ_j] (N/m, N, m)");
  m.def("beam_mass", &catenary::beam_mass, py::arg("mass_per_length"), py::arg("length"),
        "4×4 consistent mass of a beam element (kg/m, m)");

  m.def("read_catenary_file", [](const py::object& path, const py::object& overrides) {
    return io::read_catenary_file(path_arg(path), override_strings(overrides));
  }, py::arg("path"), py::arg("overrides") = py::none(),
        "A catenary file checked but, for type finite_element, without making the catenary (CatenaryFile.catenary "
        "None, .fe the data), as `inerta check`.");
  m.def("fe_keys", []() {
    py::list out;
    for (const catenary::FeKey& k : catenary::fe_keys()) {
      static const char* types[] = {"number", "whole", "bool", "choice", "numbers", "csv", "span_range", "point_masses"};
      py::dict e;
      e["path"] = k.path, e["type"] = types[static_cast<int>(k.type)], e["unit"] = k.unit, e["range"] = k.range_text();
      e["required"] = k.required, e["default"] = k.default_text, e["doc"] = k.doc, e["in_sections"] = k.in_sections;
      out.append(e);
    }
    return out;
  }, "Every key of a finite-element catenary file (catenary/fe_schema.hpp): dicts of path, type, unit, range, "
     "required, default, doc, in_sections — the keys of read_fe_catenary_data's overrides and of --set.");
  m.def("read_fe_catenary_data", [](const py::object& path, const py::object& overrides) {
    return io::read_fe_catenary_data(path_arg(path), override_strings(overrides));
  }, py::arg("path"), py::arg("overrides") = py::none(),
        "The data of a finite-element catenary file (overrides applied, validated); ModelError for another type.");
  m.def("write_lumped_catenary", [](const py::object& path, const catenary::LumpedFit& fit,
                                    const catenary::Contact& contact, const std::string& source) {
    io::write_lumped_catenary(path_arg(path), fit, contact, source);
  }, py::arg("path"), py::arg("fit"), py::arg("contact"), py::arg("source"),
        "Writes the fitted lumped catenary as a catenary file.");
  m.def("write_fit_table", [](const py::object& path, const catenary::LumpedFit& fit) {
    io::write_fit_table(path_arg(path), fit);
  }, py::arg("path"), py::arg("fit"), "Writes the fit along the span as CSV.");
}

}  // namespace inerta::python
