#pragma once
// Shared pieces of the bindings (docs/python.md): the model handle the module passes around, the
// runner of long library calls (GIL released, progress and Ctrl-C on the calling thread), NumPy
// views of result vectors, and argument conversions.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/pantograph/pantograph.hpp"
#include "inerta/solve/integrator.hpp"

namespace py = pybind11;

namespace inerta::python {

// ---- Long calls ---------------------------------------------------------------------------------
//
// run(callback, work) runs work(call) on the calling thread with the GIL released, so that the
// library's own threads (oneTBB) run freely and other Python threads too. The library's progress
// callbacks call call.post(event) (events are closures of C++ values only):
//   - on the calling thread (simulate's integrator, and the calling thread's share of a parallel
//     loop) the GIL is taken, the queued events and this one are delivered to the Python callback,
//     and PyErr_CheckSignals runs (Ctrl-C);
//   - on the library's worker threads the event is queued for the calling thread.
// A KeyboardInterrupt or an exception raised by the Python callback cancels the call: from then on
// every progress callback of the library throws Cancelled, which stops a sweep (oneTBB cancels
// the remaining speeds; the running ones finish), and run re-raises the Python exception. Events
// still queued at the end are delivered before run returns. A call without progress hooks in the
// library cannot be stopped early; Ctrl-C then takes effect when it returns.

struct Cancelled : std::exception {
  const char* what() const noexcept override { return "cancelled from Python"; }
};

class Call {
 public:
  using Event = std::function<void(const py::object& callback)>;
  explicit Call(const py::object& callback) : callback_(callback), owner_(std::this_thread::get_id()) {}

  /// From any thread, GIL not held: a progress event. Throws Cancelled once the call is cancelled.
  void post(Event e) {
    check();
    if (std::this_thread::get_id() == owner_) {
      {
        py::gil_scoped_acquire gil;
        if (!callback_.is_none()) {
          deliver_queued();
          deliver(e);
        }
        check_signals();
      }
      check();
    } else if (!callback_.is_none()) {
      std::lock_guard<std::mutex> lock(m_);
      if (queue_.size() >= 100000) queue_.pop_front();
      queue_.push_back(std::move(e));
    }
  }
  /// For hooks that report nothing (a cost or model function): Ctrl-C on the calling thread, and
  /// Cancelled once the call is cancelled.
  void poll() {
    check();
    if (std::this_thread::get_id() == owner_) {
      {
        py::gil_scoped_acquire gil;
        check_signals();
      }
      check();
    }
  }
  void check() const {
    if (cancelled_.load(std::memory_order_relaxed)) throw Cancelled();
  }
  /// On the calling thread with the GIL held, after the work: the remaining events, then the error.
  void finish() {
    if (!callback_.is_none()) deliver_queued();
    if (python_error_) std::rethrow_exception(python_error_);
  }

 private:
  void deliver(const Event& e) {
    if (python_error_) return;
    try {
      e(callback_);
    } catch (...) {
      python_error_ = std::current_exception();
      cancelled_.store(true);
    }
  }
  void deliver_queued() {
    std::deque<Event> q;
    {
      std::lock_guard<std::mutex> lock(m_);
      q.swap(queue_);
    }
    for (const auto& e : q) deliver(e);
  }
  void check_signals() {
    if (!python_error_ && PyErr_CheckSignals() != 0) {
      python_error_ = std::make_exception_ptr(py::error_already_set());
      cancelled_.store(true);
    }
  }

  const py::object& callback_;
  std::thread::id owner_;
  std::atomic<bool> cancelled_{false};
  std::exception_ptr python_error_;
  std::mutex m_;
  std::deque<Event> queue_;
};

template <class F>
auto run(const py::object& callback, F&& work) -> decltype(work(std::declval<Call&>())) {
  using R = decltype(work(std::declval<Call&>()));
  Call call(callback);
  std::optional<R> result;
  std::exception_ptr error;
  {
    py::gil_scoped_release nogil;
    try {
      result.emplace(work(call));
    } catch (...) {
      error = std::current_exception();
    }
  }
  call.finish();  // a Python exception (KeyboardInterrupt, the callback's) comes first
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

// ---- The model handle -----------------------------------------------------------------------------

/// What `inerta.Model` holds: the library's pantograph::Pantograph (an mbs::Model and, when the
/// file has a `pantograph:` section, its contact marker and rig joint; −1 otherwise), and where it
/// came from, so that parameters can be changed by reloading with overrides: the file's text and
/// name, the overrides applied, and the transformations applied after loading (suspension
/// replacement, options, ...), replayed after a reload.
struct Model {
  pantograph::Pantograph p;
  std::string text, source;  ///< text empty: not from a file (e.g. the model of a modal analysis)
  std::vector<std::pair<std::string, std::string>> overrides;  ///< key, value, in order
  std::vector<std::function<void(pantograph::Pantograph&)>> transforms;
  std::vector<std::string> history;  ///< the transformations in words

  const mbs::Model& model() const { return p.model; }
  /// The same file read again with these overrides added (a key given again replaces its value),
  /// then the transformations replayed. ModelError if the model did not come from a file.
  Model with_overrides(const std::vector<std::string>& more) const;
  /// A copy with one more transformation.
  Model transformed(std::function<void(pantograph::Pantograph&)> f, std::string what) const;
  std::vector<std::string> override_list() const;
};

Model make_model(pantograph::Pantograph p);  ///< not from a file
Model make_model(mbs::Model m);              ///< not from a file, no pantograph data
Model load_model_handle(const std::string& path, const std::vector<std::string>& overrides);
Model parse_model_handle(const std::string& text, const std::string& source, const std::vector<std::string>& overrides);

/// Overrides given as a dict {"c2.c": 70}, a list ["c2.c=70"], a single string or None.
std::vector<std::string> override_strings(const py::object& o);

/// A catenary argument: a Catenary, or a CatenaryFile (its catenary; its contact law is the default).
struct CatenaryArg {
  std::shared_ptr<const catenary::Catenary> catenary;
  std::optional<catenary::Contact> contact;
};
CatenaryArg catenary_arg(const py::object& o);
/// The contact law: `contact` if given (a Contact or "bilateral"/"penalty"), else the catenary file's,
/// else the default bilateral contact.
catenary::Contact contact_arg(const py::object& contact, const CatenaryArg& cat);

/// Integrator options: a base (IntegratorOptions or None) and the keyword overrides that are not None.
solve::IntegratorOptions integrator_arg(const py::object& base, const py::object& method, const py::object& rtol,
                                        const py::object& atol, const py::object& max_step);

// ---- Arrays -------------------------------------------------------------------------------------

/// A read-only NumPy view of v's memory (no copy), which keeps `owner` alive.
inline py::array_t<double> view(const std::vector<double>& v, py::handle owner) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size())}, {static_cast<py::ssize_t>(sizeof(double))}, v.data(),
                        owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}
/// A new NumPy array with v's values.
template <class T>
py::array_t<T> copy(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}
/// One field of every element of a vector of structs, as a new array.
template <class T, class F>
auto column(const std::vector<T>& v, F&& f) {
  using V = std::decay_t<decltype(f(v.front()))>;
  py::array_t<V> a(static_cast<py::ssize_t>(v.size()));
  auto m = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < v.size(); ++i) m(static_cast<py::ssize_t>(i)) = f(v[i]);
  return a;
}
/// A file name given as str or os.PathLike.
inline std::string path_arg(const py::object& o) {
  return py::str(py::module_::import("os").attr("fspath")(o)).cast<std::string>();
}
/// A sequence of numbers (list, tuple, NumPy array, scalar) as a vector.
std::vector<double> doubles(const py::object& o);

/// A number argument checked by the rule of the CLI option it mirrors: the same message, after the
/// argument's name ("t_end: 0 is out of range; expected > 0 s, at most 1e7 s"); `text` of the
/// value as Python writes it. A count (CountRule) must be a whole number in its range.
template <class Rule>
double rule_arg(const py::object& v, const char* name, const Rule& rule) {
  // A number, not a bool (True would be 1) nor a string: a TypeError naming the argument, not
  // pybind's "Unable to cast Python instance" (issue 38).
  if (py::isinstance<py::bool_>(v) || !PyNumber_Check(v.ptr()) || py::isinstance<py::str>(v))
    throw py::type_error(std::string(name) + ": expected a number, got " +
                         py::str(py::type::of(v).attr("__name__")).cast<std::string>() + " " +
                         py::repr(v).cast<std::string>());
  const double x = v.cast<double>();
  if (const std::string e = rule.check(x, py::str(v).cast<std::string>()); !e.empty())
    throw InvalidArgument(std::string(name) + ": " + e);
  return x;
}
/// The same for an optional argument: None keeps `fallback` (which is checked as well: it may come
/// from an options object the user filled).
template <class Rule>
double rule_arg(const py::object& v, const char* name, const Rule& rule, double fallback) {
  if (!v.is_none()) return rule_arg(v, name, rule);
  require(rule, fallback, name);
  return fallback;
}

/// A Network, or a layout/expression with `params` (NAME → value).
network::Network network_arg(const py::object& net, const py::object& params);

// ---- Registration of the parts of the module (one file each) -------------------------------------
void bind_commission(py::module_& m);
void bind_errors(py::module_& m);
void bind_model(py::module_& m);
void bind_network(py::module_& m);
void bind_catenary(py::module_& m);
void bind_analysis(py::module_& m);
void bind_optim(py::module_& m);
void bind_identification(py::module_& m);
void bind_numerics(py::module_& m);
void bind_signal(py::module_& m);
void bind_fe(py::module_& m);
void bind_linear(py::module_& m);
void bind_structure(py::module_& m);
void bind_study_run(py::module_& m);
void bind_report(py::module_& m);

}  // namespace inerta::python
