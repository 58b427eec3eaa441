// Numerics: the log-scaled multi-start pattern search (with a Python cost), its variables and
// options, and the cubic spline.
#include <fmt/format.h>

#include <pybind11/functional.h>

#include "common.hpp"
#include "inerta/numerics/cubic_spline.hpp"
#include "inerta/numerics/floquet.hpp"
#include "inerta/numerics/model_search.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::python {

namespace {

template <class F>
py::object map_scalar(const py::object& x, F&& f) {
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) return py::float_(f(x.cast<double>()));
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!a) throw py::type_error("expected a number or an array of numbers");
  py::array_t<double> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  for (py::ssize_t i = 0; i < a.size(); ++i) out.mutable_data()[i] = f(a.data()[i]);
  return out;
}

}  // namespace

void bind_numerics(py::module_& m) {
  py::class_<numerics::Variable>(m, "Variable",
                                 "A searched value: range [lo, hi] (SI, > 0), searched in decades; can_open / can_rigid "
                                 "let it reach 0 / inf (the half decade beyond each bound).")
      .def(py::init([](std::string name, double lo, double hi, bool can_open, bool can_rigid) {
             return numerics::Variable{std::move(name), lo, hi, can_open, can_rigid};
           }),
           py::arg("name"), py::arg("lo") = 1e-3, py::arg("hi") = 1e9, py::arg("can_open") = true,
           py::arg("can_rigid") = true)
      .def_readwrite("name", &numerics::Variable::name)
      .def_readwrite("lo", &numerics::Variable::lo)
      .def_readwrite("hi", &numerics::Variable::hi)
      .def_readwrite("can_open", &numerics::Variable::can_open)
      .def_readwrite("can_rigid", &numerics::Variable::can_rigid)
      .def("__repr__", [](const numerics::Variable& v) {
        return fmt::format("Variable('{}', {:g} … {:g})", v.name, v.lo, v.hi);
      });
  py::class_<numerics::Options>(m, "SearchOptions", "Options of the pattern search.")
      .def(py::init([](int starts, unsigned seed, double initial_step, double min_step, int max_evaluations) {
             return numerics::Options{starts, seed, initial_step, min_step, max_evaluations, {}};
           }),
           py::arg("starts") = 4, py::arg("seed") = 1u, py::arg("initial_step") = 1.0, py::arg("min_step") = 1e-3,
           py::arg("max_evaluations") = 5000)
      .def_readwrite("starts", &numerics::Options::starts, "random starts (the first at the box centre)")
      .def_readwrite("seed", &numerics::Options::seed)
      .def_readwrite("initial_step", &numerics::Options::initial_step, "decades")
      .def_readwrite("initial_values", &numerics::Options::initial_values,
                     "warm starts after the random ones: one value per variable (0 open, inf rigid)")
      .def_readwrite("min_step", &numerics::Options::min_step, "decades")
      .def_readwrite("max_evaluations", &numerics::Options::max_evaluations, "per start")
      .def("__repr__", [](const numerics::Options& o) {
        return fmt::format("SearchOptions(starts={}, seed={}, min_step={:g})", o.starts, o.seed, o.min_step);
      });
  py::class_<numerics::Result>(m, "SearchResult", "Result of pattern_search.")
      .def_readonly("values", &numerics::Result::values, "decoded values (0 and inf possible)")
      .def_readonly("u", &numerics::Result::u, "search coordinates, decades")
      .def_readonly("cost", &numerics::Result::cost)
      .def_readonly("evaluations", &numerics::Result::evaluations)
      .def_readonly("best_start", &numerics::Result::best_start)
      .def_readonly("exhausted", &numerics::Result::exhausted,
                    "a start stopped at max_evaluations before its mesh reached min_step");
  py::class_<numerics::FloquetResult>(m, "FloquetResult", "Floquet multipliers of a linear time-periodic system.")
      .def_readonly("multipliers", &numerics::FloquetResult::multipliers, "eigenvalues of the monodromy matrix, largest first")
      .def_readonly("largest", &numerics::FloquetResult::largest, "max |μ|")
      .def_property_readonly("stable", &numerics::FloquetResult::stable, "largest < 1");
  using RowFn = std::function<Eigen::RowVectorXd(double)>;
  m.def("monodromy", static_cast<Eigen::MatrixXd (*)(const Eigen::MatrixXd&, const Eigen::VectorXd&, const RowFn&, double, int)>(&numerics::monodromy), py::arg("A"), py::arg("b"), py::arg("r"), py::arg("T"), py::arg("steps") = 256,
        "Φ(T) of dX/dt = (A + b r(t)) X over one period T (r(t): a row of A's size; Strang splitting, second order).");
  m.def("floquet", static_cast<numerics::FloquetResult (*)(const Eigen::MatrixXd&, const Eigen::VectorXd&, const RowFn&, double, int)>(&numerics::floquet), py::arg("A"), py::arg("b"), py::arg("r"), py::arg("T"), py::arg("steps") = 256,
        "Floquet multipliers of dX/dt = (A + b r(t)) X: the eigenvalues of monodromy(A, b, r, T, steps).");
  m.def("decode", &numerics::decode, py::arg("variable"), py::arg("u"), "The value of a variable at coordinate u (decades).");
  m.def("describe", &numerics::describe, py::arg("value"), "'open', 'rigid' or the number.");
  m.def("pattern_search", [](const std::vector<numerics::Variable>& vars, const py::object& cost,
                             const py::object& options, const py::object& progress) {
    const numerics::Options o = options.is_none() ? numerics::Options{} : options.cast<numerics::Options>();
    return run(progress, [&](Call& call) {
      auto J = [&](const std::vector<double>& values) {
        call.poll();
        py::gil_scoped_acquire gil;
        return cost(values).cast<double>();
      };
      return numerics::pattern_search(vars, J, o, [&](int start, int evals, double best) {
        call.post([start, evals, best](const py::object& cb) { cb(start, evals, best); });
      });
    });
  }, py::arg("variables"), py::arg("cost"), py::arg("options") = py::none(), py::kw_only(),
        py::arg("progress") = py::none(),
        "Minimises cost(values) (a Python callable taking a list of floats, returning a float; inf for a point it "
        "cannot evaluate) by the log-scaled multi-start pattern search. The cost is called under the GIL from the "
        "library's worker threads (one at a time); an exception it raises propagates.");
  m.def("model_search", [](const std::vector<numerics::Variable>& vars, const py::object& cost,
                           const py::object& options, const std::string& optimiser, const py::object& progress) {
    const numerics::Options o = options.is_none() ? numerics::Options{} : options.cast<numerics::Options>();
    const auto which = numerics::parse_optimiser(optimiser);
    if (!which) throw py::value_error("optimiser: 'bobyqa', 'cobyla' or 'pattern'");
    return run(progress, [&](Call& call) {
      auto fg = [&](const std::vector<double>& values) {
        call.poll();
        py::gil_scoped_acquire gil;
        const py::object r = cost(values);
        if (py::isinstance<py::tuple>(r)) {
          const auto t = r.cast<py::tuple>();
          if (t.size() != 2) throw py::value_error("model_search: the cost returns f or (f, g)");
          return numerics::Evaluation{t[0].cast<double>(), t[1].cast<double>()};
        }
        return numerics::Evaluation{r.cast<double>(), 0.0};
      };
      return numerics::model_search(vars, fg, o, *which, [&](int start, int evals, double best) {
        call.post([start, evals, best](const py::object& cb) { cb(start, evals, best); });
      });
    });
  }, py::arg("variables"), py::arg("cost"), py::arg("options"), py::kw_only(), py::arg("optimiser") = "bobyqa",
        py::arg("progress") = py::none(),
        "Minimises cost(values) -> f or (f, g) (g <= 0: feasible) from each of options.initial_values by NLopt's "
        "BOBYQA (g as an exact penalty) or COBYLA (g as a constraint) on the log-scaled values, 0 and inf by a final "
        "limit check ('pattern': pattern_search on the ranks). SearchResult.cost: f, or 1e100 (1 + g) if g > 0.");

  py::class_<numerics::CubicSpline> spline(m, "CubicSpline",
                                           "C² cubic spline through (x, y), x increasing; natural or periodic ends.");
  spline
      .def(py::init([](std::vector<double> x, std::vector<double> y, const std::string& ends) {
             if (ends != "natural" && ends != "periodic")
               throw py::value_error("ends: 'natural' or 'periodic'");
             return numerics::CubicSpline(std::move(x), std::move(y),
                                          ends == "periodic" ? numerics::CubicSpline::Ends::Periodic
                                                             : numerics::CubicSpline::Ends::Natural);
           }),
           py::arg("x"), py::arg("y"), py::arg("ends") = "natural")
      .def("__call__", [](const numerics::CubicSpline& s, const py::object& x) {
        return map_scalar(x, [&](double v) { return s.value(v); });
      }, py::arg("x"))
      .def("value", [](const numerics::CubicSpline& s, const py::object& x) {
        return map_scalar(x, [&](double v) { return s.value(v); });
      }, py::arg("x"))
      .def("slope", [](const numerics::CubicSpline& s, const py::object& x) {
        return map_scalar(x, [&](double v) { return s.slope(v); });
      }, py::arg("x"))
      .def("curvature", [](const numerics::CubicSpline& s, const py::object& x) {
        return map_scalar(x, [&](double v) { return s.curvature(v); });
      }, py::arg("x"))
      .def("mean", &numerics::CubicSpline::mean)
      .def_property_readonly("x_min", &numerics::CubicSpline::x_min)
      .def_property_readonly("x_max", &numerics::CubicSpline::x_max);
}

}  // namespace inerta::python
