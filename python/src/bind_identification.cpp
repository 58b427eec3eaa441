// Identification from measurements (analysis/identification.hpp, docs/identification.md) and the
// CSV reader for measured data (io::CsvTable, with file:line errors).
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/analysis/identification.hpp"
#include "inerta/error.hpp"
#include "inerta/io/csv_table.hpp"
#include "inerta/io/model_file.hpp"

namespace inerta::python {

namespace {

using cd = std::complex<double>;

std::vector<cd> complexes(const py::object& o) {
  auto a = py::array_t<cd, py::array::c_style | py::array::forcecast>::ensure(o);
  if (!a || a.ndim() != 1) throw py::type_error("expected a one-dimensional sequence of complex numbers");
  return std::vector<cd>(a.data(), a.data() + a.size());
}

// fit_frf's variables: Variable objects, {key: (lo, hi)}, or keys (÷10 … ×10 the model's value, as the CLI).
std::vector<numerics::Variable> fit_variables(const Model* model, const py::object& vars) {
  std::vector<numerics::Variable> out;
  auto key_var = [&](const std::string& key) {
    if (!model) throw py::value_error("variables: give bounds (Variable or {key: (lo, hi)}) with a model function");
    numerics::Variable v;
    v.name = key;
    v.can_open = v.can_rigid = false;
    std::optional<double> x;
    for (const auto& [k, val] : model->overrides)
      if (k == key) x = std::stod(val);
    if (!x) {
      if (model->text.empty()) throw ModelError(fmt::format("model '{}' was not read from a file", model->model().name));
      x = io::model_value(model->text, model->source, key);
    }
    if (!x || !(*x > 0))
      throw ModelError(fmt::format("'{}' has no positive value in {}; give bounds {{'{}': (lo, hi)}}", key,
                                   model->source, key));
    v.lo = *x / 10, v.hi = *x * 10;
    return v;
  };
  if (py::isinstance<py::dict>(vars)) {
    for (auto [k, b] : vars.cast<py::dict>()) {
      numerics::Variable v;
      v.name = k.cast<std::string>();
      v.can_open = v.can_rigid = false;
      if (b.is_none()) {
        out.push_back(key_var(v.name));
        continue;
      }
      auto lohi = b.cast<std::pair<double, double>>();
      v.lo = lohi.first, v.hi = lohi.second;
      out.push_back(v);
    }
    return out;
  }
  for (auto item : vars) {
    if (py::isinstance<numerics::Variable>(item))
      out.push_back(item.cast<numerics::Variable>());
    else
      out.push_back(key_var(item.cast<std::string>()));
  }
  return out;
}

}  // namespace

void bind_identification(py::module_& m) {
  py::class_<io::CsvTable>(m, "CsvTable",
                           "Numeric CSV (a header row, then numbers); every error names the file, the line and the "
                           "column (ModelError).")
      .def_static("read", [](const py::object& p) { return io::CsvTable::read(path_arg(p)); }, py::arg("path"))
      .def_static("parse", &io::CsvTable::parse, py::arg("text"), py::arg("source"))
      .def_property_readonly("source", &io::CsvTable::source)
      .def_property_readonly("names", &io::CsvTable::names)
      .def_property_readonly("rows", &io::CsvTable::rows)
      .def("line", &io::CsvTable::line, py::arg("row"), "file line (1-based) of data row r")
      .def("has", &io::CsvTable::has, py::arg("column"))
      .def("column", [](const io::CsvTable& t, const std::string& n) { return copy(t.column(n)); }, py::arg("name"))
      .def("__getitem__", [](const io::CsvTable& t, const std::string& n) { return copy(t.column(n)); })
      .def("require_rows", &io::CsvTable::require_rows, py::arg("n"), py::arg("what"));

  py::class_<analysis::HeadSuspensionPoint>(m, "HeadSuspensionPoint", "Eq. 4.19 solved at one frequency.")
      .def_readonly("f", &analysis::HeadSuspensionPoint::f, "Hz")
      .def_readonly("k2", &analysis::HeadSuspensionPoint::k2, "N/m")
      .def_readonly("c2", &analysis::HeadSuspensionPoint::c2, "N·s/m");
  py::class_<analysis::HeadSuspensionFit>(m, "HeadSuspensionFit", "Head suspension k2 ‖ c2 by least squares (eq. 4.20).")
      .def_readonly("k2", &analysis::HeadSuspensionFit::k2, "N/m")
      .def_readonly("c2", &analysis::HeadSuspensionFit::c2, "N·s/m")
      .def_readonly("points", &analysis::HeadSuspensionFit::points)
      .def_readonly("f_lo", &analysis::HeadSuspensionFit::f_lo, "Hz")
      .def_readonly("f_hi", &analysis::HeadSuspensionFit::f_hi, "Hz")
      .def_readonly("rms_residual", &analysis::HeadSuspensionFit::rms_residual)
      .def_readonly("per_frequency", &analysis::HeadSuspensionFit::per_frequency);
  m.def("head_suspension_at", &analysis::head_suspension_at, py::arg("m_H"), py::arg("f"), py::arg("H"), py::arg("E"),
        "Eq. 4.19 at one frequency f (Hz) from the head and upper-arm FRFs H, E ((m/s²)/N) and the head mass m_H (kg).");
  m.def("fit_head_suspension", [](double m_H, const py::object& f, const py::object& H, const py::object& E,
                                  double f_lo, double f_hi) {
    return analysis::fit_head_suspension(m_H, doubles(f), complexes(H), complexes(E), f_lo, f_hi);
  }, py::arg("m_H"), py::arg("f"), py::arg("H"), py::arg("E"), py::arg("f_lo") = 4.0, py::arg("f_hi") = 20.0,
        "k2, c2 of the head suspension from the FRFs over [f_lo, f_hi] Hz (eqs. 4.19–4.20, `inerta identify "
        "head-suspension`). ModelError if the band holds no frequency.");

  m.def("frf_misfit", &analysis::frf_misfit, py::arg("model"), py::arg("measured"),
        "Eq. 6.47: Σ |H_model − H_meas|² ((m/s²/N)²); ModelError for different outputs or frequencies.");
  m.def("frf_band", &analysis::frf_band, py::arg("frf"), py::arg("f_lo"), py::arg("f_hi"),
        "The frequencies of an Frf within [f_lo, f_hi] Hz; ModelError if none.");
  py::class_<analysis::FrfFit>(m, "FrfFit", "Result of fit_frf.")
      .def_readonly("values", &analysis::FrfFit::values)
      .def_readonly("cost", &analysis::FrfFit::cost, "eq. 6.47 at the fit, (m/s²/N)²")
      .def_readonly("initial_cost", &analysis::FrfFit::initial_cost)
      .def_readonly("evaluations", &analysis::FrfFit::evaluations)
      .def_readonly("fitted", &analysis::FrfFit::fitted, "model FRF at the fit");
  m.def("fit_frf", [](const py::object& model, const py::object& variables, const analysis::Frf& measured,
                      const py::object& options, const py::object& sets) {
    const numerics::Options o = options.is_none() ? numerics::Options{} : options.cast<numerics::Options>();
    const bool callable = !py::isinstance<Model>(model);
    const Model* handle = callable ? nullptr : &model.cast<const Model&>();
    const std::vector<numerics::Variable> vars = fit_variables(handle, variables);
    const std::vector<std::string> fixed = override_strings(sets);
    auto overrides = [&](const std::vector<double>& values) {
      std::vector<std::string> ov = fixed;
      for (std::size_t i = 0; i < vars.size(); ++i) ov.push_back(fmt::format("{}={:.17g}", vars[i].name, values[i]));
      return ov;
    };
    if (handle) {  // overrides and names checked before the search starts, as the CLI does
      std::vector<double> centre;
      for (const auto& v : vars) centre.push_back(std::sqrt(v.lo * v.hi));
      (void)handle->with_overrides(overrides(centre));
    }
    return run(py::none(), [&](Call& call) {
      analysis::ModelOf model_of = [&](const std::vector<double>& values) {
        call.poll();
        if (handle) return handle->with_overrides(overrides(values)).p;
        py::gil_scoped_acquire gil;
        return model(values).cast<const Model&>().p;
      };
      return analysis::fit_frf(model_of, vars, measured, o);
    });
  }, py::arg("model"), py::arg("variables"), py::arg("measured"), py::arg("options") = py::none(),
        py::arg("sets") = py::none(),
        "Fits model parameters to measured FRFs (eq. 6.47, pattern search; `inerta identify frf-fit`). model: a "
        "Model read from a file — variables are override keys ('c2.c'), as a list (bounds ÷10 … ×10 the file's "
        "value) or {key: (lo, hi)} or Variable objects, and `sets` fixed overrides — or a callable values → Model "
        "(called under the GIL). measured: Frf with the rig outputs.");

  py::class_<analysis::LineFit>(m, "LineFit", "y = slope·x + intercept by least squares.")
      .def_readonly("slope", &analysis::LineFit::slope)
      .def_readonly("intercept", &analysis::LineFit::intercept)
      .def_readonly("points", &analysis::LineFit::points)
      .def_readonly("rms", &analysis::LineFit::rms);
  m.def("fit_line", [](const py::object& x, const py::object& y) { return analysis::fit_line(doubles(x), doubles(y)); },
        py::arg("x"), py::arg("y"), "Least-squares line; ModelError for < 2 points or all x equal.");
  py::class_<analysis::ActuatorStaticFit>(m, "ActuatorStaticFit", "Actuator constant-velocity fit (spec/03 §3.3).")
      .def_readonly("forward", &analysis::ActuatorStaticFit::forward, "F(v) for v > 0 (m/s, N)")
      .def_readonly("backward", &analysis::ActuatorStaticFit::backward, "F(v) for v < 0")
      .def_readonly("F_c", &analysis::ActuatorStaticFit::F_c, "constant force, N")
      .def_readonly("F_r", &analysis::ActuatorStaticFit::F_r, "Coulomb friction, N")
      .def_readonly("c1", &analysis::ActuatorStaticFit::c1, "viscous damping, N·s/m");
  m.def("fit_actuator_static", [](const py::object& v, const py::object& F) {
    return analysis::fit_actuator_static(doubles(v), doubles(F));
  }, py::arg("v"), py::arg("F"),
        "F_c, F_r, c1 from constant-velocity tests (mean force F in N at velocity v in m/s), `inerta identify "
        "actuator-static`.");
  m.def("maxwell_admittance", &analysis::maxwell_admittance, py::arg("k1"), py::arg("c1"), py::arg("f"),
        "Eq. 5.16: Y = 1 / (1/c1 + s/k1) at s = i 2πf (N·s/m).");
  m.def("harmonic_amplitude", [](const py::object& t, const py::object& y, double f) {
    return analysis::harmonic_amplitude(doubles(t), doubles(y), f);
  }, py::arg("t"), py::arg("y"), py::arg("f"), "Complex amplitude Y of y(t) ≈ y0 + Re(Y e^{iωt}) at f (Hz).");
  py::class_<analysis::DynamicTest>(m, "DynamicTest", "One sinusoidal actuator test: f (Hz), t (s), x (m), F (N).")
      .def(py::init([](double f, const py::object& t, const py::object& x, const py::object& F) {
             return analysis::DynamicTest{f, doubles(t), doubles(x), doubles(F)};
           }),
           py::arg("f"), py::arg("t"), py::arg("x"), py::arg("F"))
      .def_readonly("f", &analysis::DynamicTest::f)
      .def_property_readonly("t", [](const analysis::DynamicTest& d) { return copy(d.t); })
      .def_property_readonly("x", [](const analysis::DynamicTest& d) { return copy(d.x); })
      .def_property_readonly("F", [](const analysis::DynamicTest& d) { return copy(d.F); });
  py::class_<analysis::AdmittancePoint>(m, "AdmittancePoint", "Estimated admittance at one frequency.")
      .def(py::init([](double f, cd Y, double amplitude) { return analysis::AdmittancePoint{f, Y, amplitude}; }),
           py::arg("f"), py::arg("Y_E"), py::arg("amplitude") = 0.0)
      .def_readonly("f", &analysis::AdmittancePoint::f, "Hz")
      .def_readonly("Y_E", &analysis::AdmittancePoint::Y_E, "N·s/m")
      .def_readonly("amplitude", &analysis::AdmittancePoint::amplitude, "m");
  py::class_<analysis::ActuatorDynamicFit>(m, "ActuatorDynamicFit", "Maxwell k1, c1 from the dynamic tests (eq. 5.25).")
      .def_readonly("k1", &analysis::ActuatorDynamicFit::k1, "N/m")
      .def_readonly("c1", &analysis::ActuatorDynamicFit::c1, "N·s/m")
      .def_readonly("cost", &analysis::ActuatorDynamicFit::cost)
      .def_readonly("points", &analysis::ActuatorDynamicFit::points);
  m.def("admittance_cost", &analysis::admittance_cost, py::arg("k1"), py::arg("c1"), py::arg("points"),
        "Eq. 5.25: Σ |Y − Y_E| / |Y_E| with Y the Maxwell admittance.");
  m.def("fit_actuator_dynamic", [](const std::vector<analysis::DynamicTest>& tests, double c1, double piston_mass,
                                   double friction, bool fit_c1) {
    py::gil_scoped_release nogil;
    return analysis::fit_actuator_dynamic(tests, c1, piston_mass, friction, fit_c1);
  }, py::arg("tests"), py::arg("c1"), py::arg("piston_mass"), py::arg("friction"), py::arg("fit_c1") = false,
        "k1 (and c1 with fit_c1) from sinusoidal tests by the correlation method (`inerta identify actuator-dynamic`).");
}

}  // namespace inerta::python
