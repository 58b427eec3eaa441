// Commissioning a design (analysis/commission.hpp, issue 49): inerta.commission, Commissioning, Trim,
// WorkingRange.
#include "common.hpp"
#include "inerta/analysis/commission.hpp"
#include "inerta/io/acceptance_file.hpp"

namespace inerta::python {

void bind_commission(py::module_& m) {
  using analysis::Commissioning;
  py::class_<analysis::Trim>(m, "Trim", "The aerodynamic trim of commissioning: a v² so that the mean force meets a target.")
      .def(py::init<>())
      .def_readwrite("speed", &analysis::Trim::speed, "m/s (0: no trim)")
      .def_readwrite("target", &analysis::Trim::target, "N")
      .def_readwrite("periodic", &analysis::Trim::periodic, "by the periodic fast path (a lumped line)")
      .def_readwrite("harmonics", &analysis::Trim::harmonics)
      .def_readwrite("tolerance", &analysis::Trim::tolerance, "N");
  py::class_<analysis::WorkingRange>(m, "WorkingRange", "Contact-wire heights around the reference line's, m.")
      .def(py::init([](double below, double above, int points) { return analysis::WorkingRange{below, above, points}; }),
           py::arg("below") = 0.1, py::arg("above") = 0.1, py::arg("points") = 5)
      .def_readonly("below", &analysis::WorkingRange::below, "m")
      .def_readonly("above", &analysis::WorkingRange::above, "m")
      .def_readonly("points", &analysis::WorkingRange::points);
  py::class_<Commissioning>(m, "Commissioning",
                            "What commissioning set and measured (docs/contact-quality.md \"Commissioning\"); SI units.")
      .def_readonly("operating_length", &Commissioning::operating_length, "m: the actuator's length at standstill on the reference line (NaN: own suspension)")
      .def_readonly("static_stiffness", &Commissioning::static_stiffness, "N/m: G(0) = lim s→0 s·Y(s) of the suspension")
      .def_readonly("static_force", &Commissioning::static_force, "N: static contact force at standstill on the reference line")
      .def_readonly("head_offset", &Commissioning::head_offset, "m: the head there above its rig position")
      .def_readonly("a", &Commissioning::a, "N·s²/m²: the aerodynamic uplift a v²")
      .def_readonly("mean", &Commissioning::mean, "N: mean contact force at the trim speed")
      .def_readonly("mean_without", &Commissioning::mean_without, "N: the same without aerodynamic uplift")
      .def_readonly("target", &Commissioning::target, "N")
      .def_readonly("trimmed", &Commissioning::trimmed)
      .def_readonly("reached", &Commissioning::reached)
      .def_readonly("runs", &Commissioning::runs)
      .def_readonly("range_height", &Commissioning::range_height, "m: the working range's heights")
      .def_readonly("range_force", &Commissioning::range_force, "N: the static force there (stock characteristic + the suspension's)")
      .def_readonly("range_model", &Commissioning::range_model, "N: the model's own static force there")
      .def("range_min", &Commissioning::range_min)
      .def("range_max", &Commissioning::range_max)
      .def("__repr__", [](const Commissioning& c) {
        return fmt::format("Commissioning(static force {:.2f} N, G(0) {:.6g} N/m, a {:.6g} N·s²/m², mean {:.2f} N)", c.static_force,
                           c.static_stiffness, c.a, c.mean);
      })
      .def(py::pickle(  // exact (Dask workers return StudyCosts that carry one)
          [](const Commissioning& c) {
            return py::make_tuple(c.operating_length, c.static_stiffness, c.static_force, c.head_offset, c.a, c.mean,
                                  c.mean_without, c.target, c.trimmed, c.reached, c.runs, c.range_height, c.range_force,
                                  c.range_model);
          },
          [](const py::tuple& t) {
            Commissioning c;
            c.operating_length = t[0].cast<double>(), c.static_stiffness = t[1].cast<double>(), c.static_force = t[2].cast<double>();
            c.head_offset = t[3].cast<double>(), c.a = t[4].cast<double>(), c.mean = t[5].cast<double>();
            c.mean_without = t[6].cast<double>(), c.target = t[7].cast<double>(), c.trimmed = t[8].cast<bool>();
            c.reached = t[9].cast<bool>(), c.runs = t[10].cast<int>();
            c.range_height = t[11].cast<std::vector<double>>(), c.range_force = t[12].cast<std::vector<double>>();
            c.range_model = t[13].cast<std::vector<double>>();
            return c;
          }));

  m.def("commission", [](const Model& model, const py::object& catenary, const py::object& speed, const py::object& criteria,
                         const py::object& suspension, const py::object& params, const py::object& contact,
                         const analysis::WorkingRange& range) {
    const CatenaryArg cat = catenary_arg(catenary);
    const catenary::Contact k = contact_arg(contact, cat);
    analysis::Trim trim;
    if (!speed.is_none()) {
      if (criteria.is_none()) throw py::value_error("commission: a trim speed needs criteria (its target curve)");
      const analysis::AcceptanceCriteria c = py::isinstance<analysis::AcceptanceCriteria>(criteria)
                                                 ? criteria.cast<analysis::AcceptanceCriteria>()
                                                 : io::load_acceptance(path_arg(criteria));
      if (!c.has_target) throw py::value_error(fmt::format("the criteria set '{}' has no mean-force target curve", c.name));
      trim.speed = speed.cast<double>();
      trim.target = c.target.at(trim.speed * 3.6);
      trim.options.filter_cutoff = c.filter_cutoff, trim.options.filter_order = c.filter_order;
      trim.statistics = c.mean.empty() ? analysis::Statistics::Raw : c.mean.front().statistics;
    }
    std::optional<network::Network> net;
    if (!suspension.is_none()) net = network_arg(suspension, params);
    const analysis::Commissioned c = run(py::none(), [&](Call&) {  // the GIL released: no Python objects inside
      return analysis::commission(model.p, net ? &*net : nullptr, *cat.catenary, k, trim, model.p.rig_joint >= 0 ? &range : nullptr);
    });
    const pantograph::Pantograph p = c.pantograph;
    return py::make_tuple(model.transformed([p](pantograph::Pantograph& q) { q = p; }, "commissioned"), c.record);
  }, py::arg("model"), py::arg("catenary"), py::arg("speed") = py::none(), py::arg("criteria") = py::none(), py::kw_only(),
        py::arg("suspension") = py::none(), py::arg("params") = py::none(), py::arg("contact") = py::none(),
        py::arg("working_range") = analysis::WorkingRange{},
        "Commissions `model` on `catenary` (the reference line): `suspension` (a Network or layout with `params`; None: "
        "its own) relaxed at standstill there, the aerodynamic uplift fitted so that the mean force at `speed` (m/s) meets "
        "the criteria set's target, the static force over the working range. Returns (the commissioned Model, "
        "Commissioning); as `inerta pantograph aero-fit --suspension`.");
  m.def("static_force_at", [](const Model& model, double offset) { return analysis::static_force_at(model.p, offset); },
        py::arg("model"), py::arg("offset"),
        "N: the static contact force with the head held `offset` m above its rig position (EN 50206-1's test).");
}

}  // namespace inerta::python
