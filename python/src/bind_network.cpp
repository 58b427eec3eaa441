// Series–parallel spring/damper/inerter networks: expressions, named layouts, admittance,
// rational form and state-space realisation (network layer).
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/network/network.hpp"
#include "inerta/network/realisation.hpp"
#include "inerta/network/schematic.hpp"

namespace inerta::python {

namespace {

using cd = std::complex<double>;

// f(s) for a scalar s (→ complex) or an array of s (→ complex array of the same shape).
template <class F>
py::object vectorised(const py::object& s, F&& f) {
  if (py::isinstance<py::float_>(s) || py::isinstance<py::int_>(s) || PyComplex_Check(s.ptr()))
    return py::cast(f(s.cast<cd>()));
  auto a = py::array_t<cd, py::array::c_style | py::array::forcecast>::ensure(s);
  if (!a) throw py::type_error("expected a complex number or an array of them");
  py::array_t<cd> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const cd* in = a.data();
  cd* o = out.mutable_data();
  {
    py::gil_scoped_release nogil;
    for (py::ssize_t i = 0; i < a.size(); ++i) o[i] = f(in[i]);
  }
  return out;
}

const char* kind_name(network::Network::Kind k) {
  switch (k) {
    case network::Network::Kind::Spring: return "spring";
    case network::Network::Kind::Damper: return "damper";
    case network::Network::Kind::Inerter: return "inerter";
    case network::Network::Kind::Series: return "series";
    case network::Network::Kind::Parallel: return "parallel";
    case network::Network::Kind::Open: return "open";
    case network::Network::Kind::Rigid: return "rigid";
    case network::Network::Kind::Admittance: return "admittance";
  }
  return "?";
}

}  // namespace

void bind_network(py::module_& m) {
  using network::Network;
  py::class_<Network> net(m, "Network",
                          "A series–parallel network of springs k (N/m), dampers c (N·s/m) and inerters b (kg), as "
                          "parsed from an expression: '|' parallel, '-' series, parentheses ('b-(k|c)'). Element "
                          "values are bound by name; 0 is open, inf rigid. str(net) is its expression.");
  py::enum_<Network::Kind>(net, "Kind")
      .value("spring", Network::Kind::Spring)
      .value("damper", Network::Kind::Damper)
      .value("inerter", Network::Kind::Inerter)
      .value("series", Network::Kind::Series)
      .value("parallel", Network::Kind::Parallel)
      .value("open", Network::Kind::Open)
      .value("rigid", Network::Kind::Rigid)
      .value("admittance", Network::Kind::Admittance);
  net.def(py::init([](const std::string& text) { return network::parse(text); }), py::arg("expression"),
          "Parses an expression (same as inerta.parse).")
      .def_readonly("kind", &Network::kind)
      .def_readonly("name", &Network::name, "element name (leaves)")
      .def_readonly("value", &Network::value, "element value, SI (N/m, N·s/m, kg)")
      .def_readonly("children", &Network::children)
      .def_readonly("column", &Network::column, "position in the expression, 1-based")
      .def_readonly("num", &Network::num, "admittance leaf: numerator coefficients of Y(s), ascending powers of s")
      .def_readonly("den", &Network::den, "admittance leaf: denominator coefficients of Y(s), ascending powers of s")
      .def("is_element", &Network::is_element)
      .def("parameter_names", [](const Network& n) { return network::parameter_names(n); })
      .def("assign", [](const Network& n, const network::Params& p) { return network::assign(n, p); }, py::arg("params"))
      .def("simplify", [](const Network& n) { return network::simplify(n); })
      .def("to_string", [](const Network& n, bool v) { return network::to_string(n, v); },
           py::arg("with_values") = false)
      .def("admittance", [](const Network& n, const py::object& s) {
        return vectorised(s, [&](cd x) { return network::admittance(n, x); });
      }, py::arg("s"), "Y(s) = force / relative velocity (N·s/m) at the Laplace variable s (rad/s; s = 2j·π·f)")
      .def("__str__", [](const Network& n) { return network::to_string(n); })
      .def("__repr__", [](const Network& n) {
        return fmt::format("Network('{}', {})", network::to_string(n, true), kind_name(n.kind));
      });

  m.def("parse", &network::parse, py::arg("expression"),
        "Parses a network expression such as 'b-(k|c)'. NetworkError with the column of the error.");
  m.def("parameter_names", &network::parameter_names, py::arg("network"),
        "Element names in order of appearance (each once).");
  m.def("assign", &network::assign, py::arg("network"), py::arg("params"),
        "Sets every element's value from `params` {'k': 1e5, 'c': 100} (SI; 0 open, inf rigid). NetworkError for "
        "missing, unknown or negative values.");
  m.def("simplify", &network::simplify, py::arg("network"),
        "Removes open (0) and rigid (inf) elements algebraically; the result has no 0/inf values, or is Open or Rigid.");
  m.def("to_string", &network::to_string, py::arg("network"), py::arg("with_values") = false,
        "Readable form of a network, e.g. 'b-(k|c)', with the values (SI) when with_values.");
  m.def("admittance", [](const Network& n, const py::object& s) {
    return vectorised(s, [&](cd x) { return network::admittance(n, x); });
  }, py::arg("network"), py::arg("s"),
        "Y(s) = F / relative velocity (N·s/m), evaluated on the tree, at s (rad/s; a scalar or an array; "
        "s = 2j·π·f for a frequency f in Hz).");

  py::class_<network::Layout>(m, "Layout", "A named candidate layout of the thesis (spec/03 §3.2).")
      .def_readonly("name", &network::Layout::name)
      .def_readonly("expression", &network::Layout::expression)
      .def_readonly("fixed", &network::Layout::fixed, "values the layout fixes, SI")
      .def_readonly("note", &network::Layout::note)
      .def("__repr__", [](const network::Layout& l) { return fmt::format("Layout('{}', '{}')", l.name, l.expression); });
  m.def("layouts", &network::layouts, "The named layouts (S1-*, S2-*).");
  m.def("find_layout", &network::find_layout, py::arg("name"), "The named layout, or None.");
  m.def("resolve", [](const std::string& layout, const py::object& params) {
    return network::resolve(layout, params.is_none() ? network::Params{} : params.cast<network::Params>());
  }, py::arg("layout"), py::arg("params") = py::none(),
        "A layout name or an expression with values: the layout's fixed values, then `params` (a fixed value cannot "
        "be overridden). The bound, unsimplified network.");

  m.def("draw_network", [](const py::object& net, const py::object& params, const std::string& title) {
    Network n;
    if (py::isinstance<Network>(net)) {
      n = net.cast<Network>();
      if (!params.is_none()) n = network::assign(n, params.cast<network::Params>());
    } else if (py::isinstance<py::str>(net)) {
      const std::string text = net.cast<std::string>();
      if (params.is_none()) {
        const auto named = network::find_layout(text);
        n = network::parse(named ? named->expression : text);
      } else {
        n = network::resolve(text, params.cast<network::Params>());
      }
    } else {
      throw py::type_error(fmt::format("draw_network: network: expected a Network, a layout name or an expression, got {}",
                                       py::str(py::type::of(net).attr("__name__")).cast<std::string>()));
    }
    return network::schematic_svg(n, {.values = true, .title = title});
  }, py::arg("network"), py::arg("params") = py::none(), py::arg("title") = "",
        "The network as a mechanical schematic: an SVG document (str) — springs, dampers and inerters between two "
        "terminals, series left to right, parallel branches stacked, each element with its name and value (SI, in "
        "kN/m, kN·s/m, kg). network: a Network, a layout name or an expression; params: element values.");

  py::class_<network::Rational>(m, "Rational", "Y(s) = P(s)/Q(s); coefficients in ascending powers of s.")
      .def_readonly("num", &network::Rational::num)
      .def_readonly("den", &network::Rational::den)
      .def("__call__", [](const network::Rational& r, const py::object& s) {
        return vectorised(s, [&](cd x) { return r(x); });
      }, py::arg("s"));
  m.def("rational_admittance", &network::rational_admittance, py::arg("simplified"),
        "Y(s) as a ratio of polynomials, of a simplified network (not Open/Rigid).");

  py::class_<network::Realisation>(m, "Realisation",
                                   "State-space form of a strut's force–length law: F = d2·l̈ + d1·l̇ + d0·u + C x, "
                                   "ẋ = A x + B u, u = l − l_ref (N, m).")
      .def_readonly("d0", &network::Realisation::d0, "direct spring, N/m")
      .def_readonly("d1", &network::Realisation::d1, "direct damper, N·s/m")
      .def_readonly("d2", &network::Realisation::d2, "inerter across the terminals, kg")
      .def_readonly("A", &network::Realisation::A)
      .def_readonly("B", &network::Realisation::B)
      .def_readonly("C", &network::Realisation::C)
      .def_property_readonly("n_states", &network::Realisation::n_states)
      .def("dynamic_stiffness", [](const network::Realisation& r, const py::object& s) {
        return vectorised(s, [&](cd x) { return r.dynamic_stiffness(x); });
      }, py::arg("s"), "G(s) = s·Y(s), N/m")
      .def("static_stiffness", &network::Realisation::static_stiffness, "G(0), N/m")
      .def("steady_state", &network::Realisation::steady_state, py::arg("u"), "x = −A⁻¹B u for a constant u (m)");
  m.def("realise", &network::realise, py::arg("simplified"),
        "State-space realisation of a simplified network (NetworkError for Open or Rigid).");
}

}  // namespace inerta::python
