// Linear analysis of any model and model design studies (docs/linear-analysis.md, docs/studies.md).
#include "common.hpp"
#include "inerta/analysis/state_space.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/numerics/lyapunov.hpp"
#include "inerta/optim/model_study.hpp"

namespace inerta::python {

void bind_linear(py::module_& m) {
  using analysis::StateSpace;
  py::class_<mbs::LinearSystem>(m, "LinearSystem",
                                "Descriptor form Ẋ = A X + B0 u + B1 u̇ + B2 ü, y = Cy X + D0 u + D1 u̇ + D2 ü (mbs::linearise "
                                "with inputs and outputs).")
      .def_readonly("lin", &mbs::LinearSystem::lin)
      .def_readonly("inputs", &mbs::LinearSystem::inputs)
      .def_readonly("outputs", &mbs::LinearSystem::outputs)
      .def_readonly("motion", &mbs::LinearSystem::motion, "per input: a driving joint (True) or a load")
      .def_readonly("joint", &mbs::LinearSystem::joint, "per input: its driving joint's index in model.joints, or -1 for a load")
      .def_readonly("B0", &mbs::LinearSystem::B0)
      .def_readonly("B1", &mbs::LinearSystem::B1)
      .def_readonly("B2", &mbs::LinearSystem::B2)
      .def_readonly("Cy", &mbs::LinearSystem::Cy)
      .def_readonly("D0", &mbs::LinearSystem::D0)
      .def_readonly("D1", &mbs::LinearSystem::D1)
      .def_readonly("D2", &mbs::LinearSystem::D2);
  m.def("linear_system", [](const Model& h, const mbs::State& x, const std::vector<std::string>& inputs,
                            const std::vector<std::string>& outputs, double t) { return mbs::linearise(h.model(), x, inputs, outputs, t); },
        py::arg("model"), py::arg("state"), py::arg("inputs"), py::arg("outputs"), py::arg("t") = 0.0,
        "The descriptor linearisation with named inputs (loads, driving joints) and outputs (mbs::linearise).");
  m.def("state_names", [](const Model& h, const mbs::LinearModel& lin) { return mbs::state_names(h.model(), lin); },
        py::arg("model"), py::arg("linear"), "Names of X = [ξ; ξ̇; z]: 'body.y', 'body.y_dot', 'strut.z0'.");
  py::class_<mbs::UndampedMode>(m, "UndampedMode", "An undamped natural mode of (M, K): frequency (Hz), shape.")
      .def_readonly("frequency_hz", &mbs::UndampedMode::frequency_hz)
      .def_readonly("shape", &mbs::UndampedMode::shape)
      .def_readonly("description", &mbs::UndampedMode::description);
  m.def("undamped_modes", [](const Model& h, const mbs::LinearModel& lin) { return mbs::undamped_modes(h.model(), lin); },
        py::arg("model"), py::arg("linear"), "Undamped natural frequencies (Hz) and shapes of (M, K), ascending.");

  py::class_<StateSpace>(m, "StateSpace",
                         "Ẏ = A Y + B u, y = C Y + D u (+ D1 u̇ + D2 ü) with state, input and output names "
                         "(analysis::state_space); SI units, deviations from the static equilibrium.")
      .def_readonly("model", &StateSpace::model)
      .def_readonly("states", &StateSpace::states)
      .def_readonly("inputs", &StateSpace::inputs)
      .def_readonly("outputs", &StateSpace::outputs)
      .def_readonly("input_units", &StateSpace::input_units)
      .def_readonly("A", &StateSpace::A)
      .def_readonly("B", &StateSpace::B)
      .def_readonly("C", &StateSpace::C)
      .def_readonly("D", &StateSpace::D)
      .def_readonly("D1", &StateSpace::D1)
      .def_readonly("D2", &StateSpace::D2)
      .def_readonly("T0", &StateSpace::T0)
      .def_readonly("T1", &StateSpace::T1)
      .def_readonly("system", &StateSpace::system)
      .def("has_rate_feedthrough", &StateSpace::has_rate_feedthrough);
  m.def("state_space", [](const Model& h, const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                          const py::object& state, double t) {
    if (state.is_none()) return analysis::state_space(h.model(), inputs, outputs);
    return analysis::state_space(h.model(), state.cast<mbs::State>(), inputs, outputs, t);
  }, py::arg("model"), py::arg("inputs"), py::arg("outputs"), py::kw_only(), py::arg("state") = py::none(), py::arg("t") = 0.0,
        "State space from named inputs (point_force/point_torque elements, driving joints) to named outputs, about "
        "the static equilibrium (or about `state`). InvalidArgument names unknown inputs or outputs.");
  m.def("frequency_response", [](const StateSpace& ss, const py::object& f) {
    const std::vector<double> fv = doubles(f);
    std::vector<Eigen::MatrixXcd> H;
    {
      py::gil_scoped_release release;
      H = analysis::frequency_response(ss, fv);
    }
    const auto no = static_cast<py::ssize_t>(ss.outputs.size()), ni = static_cast<py::ssize_t>(ss.inputs.size());
    py::array_t<std::complex<double>> out({static_cast<py::ssize_t>(fv.size()), no, ni});
    auto r = out.mutable_unchecked<3>();
    for (std::size_t k = 0; k < fv.size(); ++k)
      for (py::ssize_t i = 0; i < no; ++i)
        for (py::ssize_t j = 0; j < ni; ++j) r(static_cast<py::ssize_t>(k), i, j) = H[k](i, j);
    return out;
  }, py::arg("state_space"), py::arg("f_hz"),
        "H(j 2π f), an array [frequency, output, input] (analysis::frequency_response).");
  py::class_<analysis::RandomResponse>(m, "RandomResponse", "Stationary rms and covariance of outputs.")
      .def_readonly("outputs", &analysis::RandomResponse::outputs)
      .def_readonly("rms", &analysis::RandomResponse::rms)
      .def_readonly("covariance", &analysis::RandomResponse::covariance);
  m.def("white_noise_response", &analysis::white_noise_response, py::arg("state_space"), py::arg("W"),
        "rms under white noise on the inputs, E[u(t)u(s)ᵀ] = W δ(t − s) (W = 2π S0 for a two-sided PSD S0 per rad/s). "
        "With W = I: the H2 norms.");
  py::class_<analysis::Road>(m, "Road", "ISO 8608 road: G_d(n0) (m³, n0 = 0.1 cycles/m), speed (m/s), inputs, delays (s).")
      .def(py::init<>())
      .def_readwrite("gd0", &analysis::Road::gd0)
      .def_readwrite("speed", &analysis::Road::speed)
      .def_readwrite("inputs", &analysis::Road::inputs)
      .def_readwrite("delays", &analysis::Road::delays)
      .def_readwrite("pade_order", &analysis::Road::pade_order);
  m.def("road_response", &analysis::road_response, py::arg("state_space"), py::arg("road"),
        "rms on an ISO 8608 road by the Lyapunov equation (analysis::road_response).");
  m.def("road_velocity_intensity", &analysis::road_velocity_intensity, py::arg("gd0"), py::arg("speed"),
        "White-noise intensity of the road velocity, 2π² n0² G_d(n0) v (m²/s).");
  m.def("lyapunov", &numerics::lyapunov, py::arg("A"), py::arg("Q"), "P with A P + P Aᵀ + Q = 0 (A Hurwitz).");

  // ---- model studies ----
  using optim::ModelStudy;
  py::class_<optim::WeightedOutput>(m, "WeightedOutput").def_readonly("name", &optim::WeightedOutput::name).def_readonly("weight", &optim::WeightedOutput::weight);
  py::class_<optim::RmsLimit>(m, "RmsLimit").def_readonly("output", &optim::RmsLimit::output).def_readonly("limit", &optim::RmsLimit::limit);
  py::class_<optim::Objective>(m, "Objective", "A model study's objective: rms, hinf or peak (optim/model_study.hpp).")
      .def_property_readonly("kind", [](const optim::Objective& o) { return std::string(optim::Objective::name(o.kind)); })
      .def_readonly("outputs", &optim::Objective::outputs)
      .def_readonly("limits", &optim::Objective::limits)
      .def_readonly("input", &optim::Objective::input)
      .def_readonly("frequencies", &optim::Objective::frequencies);
  py::class_<ModelStudy>(m, "ModelStudy", "A design study on any model (io::load_model_study).")
      .def_readonly("name", &ModelStudy::name)
      .def_readonly("source", &ModelStudy::source)
      .def_property_readonly("model", [](const ModelStudy& s) { return make_model(s.model); })
      .def_readonly("strut", &ModelStudy::strut)
      .def_readonly("objective", &ModelStudy::objective)
      .def_readonly("layouts", &ModelStudy::layouts);
  m.def("load_model_study", [](const py::object& path) { return io::load_model_study(path_arg(path)); }, py::arg("path"),
        "Reads a model study file (docs/studies.md).");
  m.def("is_model_study", [](const py::object& path) { return io::is_model_study(path_arg(path)); }, py::arg("path"),
        "True for a study file with objective: rms | hinf | peak (a model study), False for a pantograph J2 study.");
  py::class_<optim::ModelCost>(m, "ModelCost", "The objective J, per-output values, limits' rms, feasibility.")
      .def_readonly("J", &optim::ModelCost::J)
      .def_readonly("penalised", &optim::ModelCost::penalised)
      .def_readonly("values", &optim::ModelCost::values)
      .def_readonly("limit_values", &optim::ModelCost::limit_values)
      .def_readonly("frequency", &optim::ModelCost::frequency)
      .def_readonly("feasible", &optim::ModelCost::feasible)
      .def(py::pickle(  // exact (Dask workers return model studies' results, docs/distributed.md)
          [](const optim::ModelCost& c) { return py::make_tuple(c.J, c.penalised, c.values, c.limit_values, c.frequency, c.feasible); },
          [](const py::tuple& t) {
            optim::ModelCost c;
            c.J = t[0].cast<double>(), c.penalised = t[1].cast<double>();
            c.values = t[2].cast<std::vector<double>>(), c.limit_values = t[3].cast<std::vector<double>>();
            c.frequency = t[4].cast<double>(), c.feasible = t[5].cast<bool>();
            return c;
          }));
  py::class_<optim::ModelLayoutResult>(m, "ModelLayoutResult", "The optimum of one layout of a model study.")
      .def_readonly("layout", &optim::ModelLayoutResult::layout)
      .def_readonly("expression", &optim::ModelLayoutResult::expression)
      .def_readonly("values", &optim::ModelLayoutResult::values)
      .def_readonly("at_bounds", &optim::ModelLayoutResult::at_bounds)
      .def_readonly("cost", &optim::ModelLayoutResult::cost)
      .def_readonly("evaluations", &optim::ModelLayoutResult::evaluations)
      .def_readonly("budget_exhausted", &optim::ModelLayoutResult::budget_exhausted, "the search stopped at max_evaluations")
      .def(py::pickle(
          [](const optim::ModelLayoutResult& r) {
            return py::make_tuple(r.layout, r.expression, r.values, r.at_bounds, r.cost, r.evaluations, r.budget_exhausted);
          },
          [](const py::tuple& t) {
            optim::ModelLayoutResult r;
            r.layout = t[0].cast<std::string>(), r.expression = t[1].cast<std::string>();
            r.values = t[2].cast<network::Params>(), r.at_bounds = t[3].cast<std::vector<std::string>>();
            r.cost = t[4].cast<optim::ModelCost>(), r.evaluations = t[5].cast<int>(), r.budget_exhausted = t[6].cast<bool>();
            return r;
          }));
  m.def("default_network", &optim::default_network, py::arg("study"), "The study strut's own network.");
  m.def("evaluate_model", [](const ModelStudy& s, const std::string& layout, const network::Params& p) {
    py::gil_scoped_release release;
    return optim::evaluate(s, network::resolve(layout, p));
  }, py::arg("study"), py::arg("layout"), py::arg("params") = network::Params{}, "The objective of one design (optim::evaluate).");
  m.def("optimise_model_layout", [](const ModelStudy& s, const std::string& layout, const std::vector<network::Params>& warm) {
    py::gil_scoped_release release;
    return optim::optimise_layout(s, layout, {}, warm);
  }, py::arg("study"), py::arg("layout"), py::arg("warm") = std::vector<network::Params>{},
        "Optimises one layout of a model study (optim::optimise_layout), warm-started from `warm` designs.");
  m.def("with_strut_network", [](const Model& h, int strut, const std::string& layout, const network::Params& p) {
    return make_model(optim::with_strut_network(h.model(), strut, network::resolve(layout, p)));
  }, py::arg("model"), py::arg("strut"), py::arg("layout"), py::arg("params") = network::Params{},
        "The model with force element `strut`'s network replaced.");
  py::class_<optim::ObjectiveMap>(m, "ObjectiveMap")
      .def_readonly("layout", &optim::ObjectiveMap::layout)
      .def_readonly("x_name", &optim::ObjectiveMap::x_name)
      .def_readonly("y_name", &optim::ObjectiveMap::y_name)
      .def_readonly("x", &optim::ObjectiveMap::x)
      .def_readonly("y", &optim::ObjectiveMap::y)
      .def_readonly("J", &optim::ObjectiveMap::J);
  m.def("objective_map", [](const ModelStudy& s, const std::string& layout, const network::Params& values, const std::string& x,
                            const std::string& y, int n, double decades) {
    py::gil_scoped_release release;
    return optim::objective_map(s, layout, values, x, y, n, decades);
  }, py::arg("study"), py::arg("layout"), py::arg("values"), py::arg("x"), py::arg("y"), py::arg("n") = 15, py::arg("decades") = 1.0,
        "The objective over an n × n grid of two elements x, y (±decades around their values), in parallel.");
  py::class_<optim::StudyFrf>(m, "StudyFrf")
      .def_readonly("input", &optim::StudyFrf::input)
      .def_readonly("outputs", &optim::StudyFrf::outputs)
      .def_readonly("f", &optim::StudyFrf::f)
      .def_readonly("magnitude", &optim::StudyFrf::magnitude);
  m.def("study_frf", [](const ModelStudy& s, const std::string& layout, const network::Params& p, const py::object& f) {
    return optim::study_frf(s, network::resolve(layout, p), doubles(f));
  }, py::arg("study"), py::arg("layout"), py::arg("params"), py::arg("f_hz"),
        "|H| from the study's excitation input to its weighted outputs for one design, per frequency (Hz).");
}

}  // namespace inerta::python
