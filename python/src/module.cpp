// The extension module inerta._inerta (docs/python.md); python/inerta/__init__.py re-exports it.
#include <cstring>

#include "inerta/io/data_dir.hpp"
#include "common.hpp"
#include "inerta/error.hpp"
#include "inerta/network/network.hpp"

namespace inerta::python {

namespace {

PyObject* new_exception(py::module_& m, const char* name, std::initializer_list<PyObject*> bases, const char* doc) {
  py::tuple b(bases.size());
  std::size_t i = 0;
  for (PyObject* base : bases) b[i++] = py::reinterpret_borrow<py::object>(base);
  PyObject* e = PyErr_NewExceptionWithDoc((std::string("inerta.") + name).c_str(), doc, b.ptr(), nullptr);
  if (!e) throw py::error_already_set();
  m.add_object(name, py::handle(e));
  return e;
}

void raise(PyObject* type, const char* what, const char* attr = nullptr, py::object value = py::none()) {
  // A message quoting a file's bytes may not be UTF-8: escaped, never a UnicodeDecodeError instead of it.
  py::object text = py::reinterpret_steal<py::object>(
      PyUnicode_DecodeUTF8(what, static_cast<Py_ssize_t>(std::strlen(what)), "backslashreplace"));
  if (!text) return;
  py::object inst = py::reinterpret_steal<py::object>(PyObject_CallFunctionObjArgs(type, text.ptr(), nullptr));
  if (!inst) return;  // the call set an error
  if (attr) inst.attr(attr) = value;
  PyErr_SetObject(type, inst.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  static PyObject* base = new_exception(m, "Error", {PyExc_Exception}, "Base class of the errors of the inerta library.");
  static PyObject* model_error = new_exception(
      m, "ModelError", {base, PyExc_ValueError},
      "Bad input in a model, catenary or study file (or an override): 'file:line: key: what is wrong; expected "
      "...', the same text as the CLI prints after 'error: '.");
  static PyObject* invalid = new_exception(
      m, "InvalidArgument", {base, PyExc_ValueError},
      "A non-physical or inconsistent argument given to a library function or constructor (negative stiffness, zero "
      "mass, NaN, an unknown handle). Attribute `parameter`: the offending parameter ('' if none).");
  static PyObject* numerical = new_exception(
      m, "NumericalError", {base, PyExc_RuntimeError},
      "Numerical failure (assembly not converging, singular constraints, integrator failure, a bilateral contact "
      "force becoming negative); the message carries the simulated time and the quantities involved.");
  static PyObject* network_error =
      new_exception(m, "NetworkError", {base, PyExc_ValueError},
                    "Malformed network expression or parameter set. Attribute `column`: 1-based position of the "
                    "problem in the expression (0 if none).");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const network::NetworkError& e) {
      raise(network_error, e.what(), "column", py::int_(e.column));
    } catch (const ModelError& e) {
      raise(model_error, e.what());
    } catch (const InvalidArgument& e) {
      raise(invalid, e.what(), "parameter", py::str(e.parameter()));
    } catch (const NumericalError& e) {
      raise(numerical, e.what());
    } catch (const Cancelled& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
}

}  // namespace inerta::python

PYBIND11_MODULE(_inerta, m) {
  using namespace inerta::python;
  m.doc() =
      "Inerta: inerter-based vibration suppression in multibody systems (C++ library bindings; docs/python.md). "
      "SI units throughout: m, s, kg, N, rad; speeds in m/s (inerta.kmh converts), frequencies in Hz.";
  bind_errors(m);
  bind_numerics(m);
  bind_network(m);
  bind_model(m);
  bind_catenary(m);
  bind_fe(m);
  bind_signal(m);
  bind_linear(m);
  bind_analysis(m);
  bind_commission(m);
  bind_optim(m);
  bind_structure(m);
  bind_study_run(m);
  bind_identification(m);
  bind_report(m);
  // Where the criteria presets, default models and plotting scripts are read (io/data_dir.hpp, docs/install.md).
  m.def("data_dir", [] { return inerta::io::data_dir().string(); },
        "The folder the criteria presets (criteria/), default models (models/) and plotting scripts are read from: "
        "$INERTA_DATA_DIR, else an installed copy's share/inerta, else the source tree the module was built from.");
  m.def("_set_data_dir", [](const std::string& d) { return inerta::io::set_data_dir(d); });
  m.attr("_PYTHON_SITE") = INERTA_PYTHON_REL_DIR;
  m.attr("_DATA_DIR") = INERTA_DATA_REL_DIR;
}
