// Analyses: simulation (alone and under a catenary), speed sweeps (time domain and periodic fast
// path), contact statistics, modes and linear models, test-rig FRFs, catenary response. Results
// keep the library's vectors; time histories are NumPy views of them (no copy, no per-sample
// Python objects).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "common.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/aero_fit.hpp"
#include "inerta/analysis/catenary_response.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/analysis/frf.hpp"
#include "inerta/analysis/modal.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/report/run_reports.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/linear_model_file.hpp"
#include "inerta/mbs/linearisation.hpp"

namespace inerta::python {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Python `Result`: one time history, owned by `owner` (a Simulation or a CoupledSimulation).
struct History {
  std::shared_ptr<const void> owner;
  const analysis::TimeHistory* h = nullptr;
  std::shared_ptr<const analysis::Simulation> sim;  ///< simulate() only
  double wall_s = 0;                                ///< wall time of the library call, s

  std::size_t index(const std::string& name) const {
    for (std::size_t k = 0; k < h->names.size(); ++k)
      if (h->names[k] == name) return k;
    std::string names;
    for (const auto& n : h->names) names += (names.empty() ? "" : ", ") + n;
    throw py::key_error(fmt::format("no output '{}'; outputs: t, {}", name, names));
  }
};

py::object item(const py::object& self, const std::string& name) {
  const History& r = self.cast<const History&>();
  if (name == "t") return view(r.h->t, self);
  return view(r.h->columns[r.index(name)], self);
}

struct CoupledResult {
  std::shared_ptr<const analysis::CoupledSimulation> sim;
  double wall_s = 0;
  History history(std::size_t k) const {
    if (k >= sim->histories.size()) throw py::index_error("no such pantograph");
    return {sim, &sim->histories[k], nullptr, wall_s};
  }
};

struct SweepResult {
  std::vector<analysis::SpeedResult> r;
  double wall_s = 0;
  std::string method;
  std::size_t worst() const {  // over the stable speeds (an unstable one has NaN statistics)
    std::size_t w = r.size();
    for (std::size_t i = 0; i < r.size(); ++i)
      if (r[i].stable() && (w == r.size() || r[i].stats.std > r[w].stats.std)) w = i;
    return w;
  }
};

struct CatenaryResponses {
  std::vector<analysis::CatenaryResponse> r;
};

std::vector<catenary::PantographOnLine> train(const py::object& model, const py::object& positions,
                                              const catenary::Contact& contact) {
  if (py::isinstance<Model>(model)) {
    const Model& h = model.cast<const Model&>();
    std::vector<double> x = positions.is_none() ? std::vector<double>{0.0} : doubles(positions);
    std::vector<catenary::PantographOnLine> t;
    for (double x0 : x) t.push_back({h.p, x0, contact});
    return t;
  }
  if (!positions.is_none()) throw py::value_error("positions: give a Model (copies at these positions) or a list of PantographOnLine");
  return model.cast<std::vector<catenary::PantographOnLine>>();
}

analysis::RunOptions run_options(const py::object& options, const py::object& method, const py::object& rtol,
                                 const py::object& atol) {
  if (!options.is_none() && !py::isinstance<analysis::RunOptions>(options))  // not pybind's "Unable to cast"
    throw py::type_error("options: expected a RunOptions, got " +
                         py::str(py::type::of(options).attr("__name__")).cast<std::string>());
  analysis::RunOptions o = options.is_none() ? analysis::RunOptions{} : options.cast<analysis::RunOptions>();
  o.integrator = integrator_arg(py::cast(o.integrator), method, rtol, atol, py::none());
  return o;
}

const catenary::LumpedCatenary& lumped_arg(const py::object& o, catenary::LumpedCatenary& store) {
  if (py::isinstance<catenary::LumpedCatenary>(o)) return store = o.cast<catenary::LumpedCatenary>();
  CatenaryArg c = catenary_arg(o);
  const catenary::LumpedCatenary* p = c.catenary->point_model();
  if (!p)
    throw ModelError(fmt::format("catenary-response analyses the lumped catenary (eq. 7.1); this is a {}",
                                 c.catenary->describe()));
  return store = *p;
}

py::array_t<std::complex<double>> frf_matrix(const analysis::Frf& f) {
  const auto n = static_cast<py::ssize_t>(f.H.size()), k = static_cast<py::ssize_t>(f.f.size());
  py::array_t<std::complex<double>> a({n, k});
  auto w = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t j = 0; j < k; ++j) w(i, j) = f.H[static_cast<std::size_t>(i)].at(static_cast<std::size_t>(j));
  return a;
}

void set_frf_matrix(analysis::Frf& f, const py::array_t<std::complex<double>, py::array::forcecast>& a) {
  if (a.ndim() == 1 && f.outputs.size() <= 1) {
    f.H = {std::vector<std::complex<double>>(a.data(), a.data() + a.size())};
    return;
  }
  if (a.ndim() != 2) throw py::value_error("H: expected a 2-D array [output, frequency]");
  auto r = a.unchecked<2>();
  f.H.assign(static_cast<std::size_t>(r.shape(0)), {});
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (py::ssize_t j = 0; j < r.shape(1); ++j) f.H[static_cast<std::size_t>(i)].push_back(r(i, j));
}

const char* method_name_of(const solve::IntegratorOptions& o) { return o.method == solve::Method::Bdf ? "bdf" : "rk"; }

// A warning of the library on sys.stderr (the CLI's standard error); "" prints nothing.
void print_warning(const std::string& w) {
  if (!w.empty()) py::print(w, py::arg("file") = py::module_::import("sys").attr("stderr"));
}

// The cost guard (analysis/cost_guard.hpp) as the CLI's: refused above max_seconds (None: no limit),
// the estimate on sys.stderr beyond 10 s, both before any work on the catenary.
void cost_guard(double seconds, double bytes, const py::object& max_seconds, const std::string& what) {
  analysis::check_memory(bytes, what, "fewer spans ('line.spans'), a coarser mesh ('mesh.element_length')");
  if (!max_seconds.is_none())
    analysis::check_cost(seconds, rule_arg(max_seconds, "max_seconds", analysis::max_seconds_rule), what,
                         "pass max_seconds=",
                         "fewer spans ('line.spans'), a coarser mesh ('mesh.element_length'), the modal solve "
                         "('solver.type': 'modal') or a shorter t_end");
  print_warning(analysis::cost_note(seconds, what));
}

}  // namespace

namespace {

// Options and statistics of a run.
void bind_options_statistics(py::module_& m) {
  // ---- Options and statistics ------------------------------------------------------------------------
  py::class_<solve::IntegratorOptions>(m, "IntegratorOptions",
                                       "Time integration (SUNDIALS): method 'rk' (ARKODE Dormand–Prince 5(4), the "
                                       "default) or 'bdf' (CVODE BDF, stiff); tolerances; max_step (s, 0 unlimited).")
      .def(py::init([](const std::string& method, double rtol, double atol, double max_step, long max_steps) {
             solve::IntegratorOptions o;
             o.method = solve::parse_method(method);
             o.rtol = rtol, o.atol = atol, o.max_step = max_step, o.max_steps = max_steps;
             return o;
           }),
           py::arg("method") = "rk", py::arg("rtol") = 1e-6, py::arg("atol") = 1e-8, py::arg("max_step") = 0.0,
           py::arg("max_steps") = 50'000'000L)
      .def_property("method", [](const solve::IntegratorOptions& o) { return std::string(method_name_of(o)); },
                    [](solve::IntegratorOptions& o, const std::string& s) { o.method = solve::parse_method(s); })
      .def_readwrite("rtol", &solve::IntegratorOptions::rtol)
      .def_readwrite("atol", &solve::IntegratorOptions::atol, "m, rad, m/s, rad/s")
      .def_readwrite("max_step", &solve::IntegratorOptions::max_step, "s; 0 = unlimited")
      .def_readwrite("max_steps", &solve::IntegratorOptions::max_steps)
      .def("__repr__", [](const solve::IntegratorOptions& o) {
        return fmt::format("IntegratorOptions('{}', rtol={:g}, atol={:g}, max_step={:g})", method_name_of(o), o.rtol,
                           o.atol, o.max_step);
      });

  py::class_<solve::RunStats>(m, "RunStats", "Integrator statistics of a run.")
      .def_readonly("steps", &solve::RunStats::steps)
      .def_readonly("rhs_evals", &solve::RunStats::rhs_evals)
      .def_readonly("wall_s", &solve::RunStats::wall_s, "wall time of the integration, s")
      .def_readonly("max_violation", &solve::RunStats::max_violation, "max |C(q)| over the steps (m or rad)")
      .def_readonly("max_velocity_violation", &solve::RunStats::max_velocity_violation)
      .def_readonly("t_max_violation", &solve::RunStats::t_max_violation, "s");

  py::class_<analysis::RunOptions>(m, "RunOptions",
                                   "How one speed of a time-domain sweep is run (spec/06 §6.1): span by span until σ "
                                   "changes by less than `tolerance` for `settled_spans` spans in a row.")
      .def(py::init<>())
      .def(py::init([](py::kwargs kw) {
        analysis::RunOptions o;
        py::object self = py::cast(o);
        for (auto [k, v] : kw) self.attr(k) = v;
        return self.cast<analysis::RunOptions>();
      }))
      .def_readwrite("min_spans", &analysis::RunOptions::min_spans)
      .def_readwrite("max_spans", &analysis::RunOptions::max_spans)
      .def_readwrite("tolerance", &analysis::RunOptions::tolerance, "relative change of σ span to span")
      .def_readwrite("settled_spans", &analysis::RunOptions::settled_spans)
      .def_readwrite("window_spans", &analysis::RunOptions::window_spans, "statistics over the last spans")
      .def_readwrite("samples_per_span", &analysis::RunOptions::samples_per_span)
      .def_readwrite("integrator", &analysis::RunOptions::integrator)
      .def_readwrite("fixed_spans", &analysis::RunOptions::fixed_spans, "run exactly min_spans spans")
      .def_readwrite("filter_cutoff", &analysis::RunOptions::filter_cutoff, "Hz, the 20 Hz statistics' low-pass of a finite line")
      .def_readwrite("filter_order", &analysis::RunOptions::filter_order, "order of each pass of that low-pass")
      .def_readwrite("allow_supercritical", &analysis::RunOptions::allow_supercritical,
                     "run above the catenary's wave speed (else ModelError, as the CLI without --allow-supercritical)");

  py::class_<analysis::ContactStatistics>(m, "ContactStatistics",
                                          "Contact-force statistics over a window (N; compression positive).")
      .def_readonly("mean", &analysis::ContactStatistics::mean, "N")
      .def_readonly("std", &analysis::ContactStatistics::std, "σ, N")
      .def_readonly("max", &analysis::ContactStatistics::max, "N")
      .def_readonly("min", &analysis::ContactStatistics::min, "N")
      .def_readonly("stat_max", &analysis::ContactStatistics::stat_max, "F_m + 3σ, N")
      .def_readonly("stat_min", &analysis::ContactStatistics::stat_min, "F_m − 3σ, N")
      .def_readonly("loss_pct", &analysis::ContactStatistics::loss_pct, "% of samples with F <= 0")
      .def_readonly("samples", &analysis::ContactStatistics::samples)
      .def("__repr__", [](const analysis::ContactStatistics& s) {
        return fmt::format("ContactStatistics(mean={:.4g} N, std={:.4g} N, loss={:.3g} %)", s.mean, s.std, s.loss_pct);
      })
      .def(py::pickle(  // exact: every field, as Python floats (Dask, docs/distributed.md)
          [](const analysis::ContactStatistics& s) {
            return py::make_tuple(s.mean, s.std, s.max, s.min, s.stat_max, s.stat_min, s.loss_pct, s.samples);
          },
          [](const py::tuple& t) {
            analysis::ContactStatistics s;
            s.mean = t[0].cast<double>(), s.std = t[1].cast<double>(), s.max = t[2].cast<double>();
            s.min = t[3].cast<double>(), s.stat_max = t[4].cast<double>(), s.stat_min = t[5].cast<double>();
            s.loss_pct = t[6].cast<double>(), s.samples = t[7].cast<long>();
            return s;
          }));
  m.def("statistics", [](const py::object& F) { return analysis::statistics(doubles(F)); }, py::arg("F"),
        "Contact statistics (spec/06 §6.1) of a contact-force array (N).");

  py::class_<analysis::OutputSummary>(m, "OutputSummary", "min / max / mean of one output over the steady part, SI.")
      .def_readonly("name", &analysis::OutputSummary::name)
      .def_readonly("initial", &analysis::OutputSummary::initial)
      .def_readonly("min", &analysis::OutputSummary::min)
      .def_readonly("max", &analysis::OutputSummary::max)
      .def_readonly("mean", &analysis::OutputSummary::mean)
      .def_readonly("samples", &analysis::OutputSummary::samples)
      .def("__repr__", [](const analysis::OutputSummary& s) {
        return fmt::format("OutputSummary('{}', min={:.6g}, max={:.6g}, mean={:.6g})", s.name, s.min, s.max, s.mean);
      });

}

// Time histories (simulate).
void bind_time_histories(py::module_& m) {
  // ---- Time histories ---------------------------------------------------------------------------------
  py::class_<History>(m, "Result",
                      "Sampled outputs of a run: r['C_y'] (or r['t']) is a read-only NumPy view of the library's "
                      "vector (no copy), r.t the times (s), r.names the outputs in the model's order. SI units. With "
                      "simulate(): also stats, assembly, equilibrium, steady, t_end, sample.")
      .def("__getitem__", &item, py::arg("name"))
      .def("__contains__", [](const History& r, const std::string& n) {
        return n == "t" || std::find(r.h->names.begin(), r.h->names.end(), n) != r.h->names.end();
      })
      .def("__len__", [](const History& r) { return r.h->names.size(); }, "number of outputs")
      .def("__iter__", [](const History& r) { return py::iter(py::cast(r.h->names)); })
      .def("keys", [](const History& r) { return r.h->names; })
      .def_property_readonly("t", [](py::object self) { return view(self.cast<const History&>().h->t, self); },
                             "sample times, s (a view)")
      .def_property_readonly("names", [](const History& r) { return r.h->names; })
      .def_property_readonly("n_samples", [](const History& r) { return r.h->t.size(); })
      .def_property_readonly("data", [](const History& r) {
        const auto n = static_cast<py::ssize_t>(r.h->names.size()), k = static_cast<py::ssize_t>(r.h->t.size());
        py::array_t<double> a({n, k});
        for (py::ssize_t i = 0; i < n; ++i)
          std::copy(r.h->columns[static_cast<std::size_t>(i)].begin(), r.h->columns[static_cast<std::size_t>(i)].end(),
                    a.mutable_data(i, 0));
        return a;
      }, "all outputs as a new 2-D array [output, sample] (a copy)")
      .def("to_dict", [](py::object self) {
        const History& r = self.cast<const History&>();
        py::dict d;
        d["t"] = view(r.h->t, self);
        for (std::size_t k = 0; k < r.h->names.size(); ++k) d[py::str(r.h->names[k])] = view(r.h->columns[k], self);
        return d;
      }, "{'t': ..., name: ...} of views")
      .def("summary", [](const History& r, double from) { return analysis::summarise(*r.h, from); },
           py::arg("from_t") = 0.0, "OutputSummary of every output over t >= from_t (s)")
      .def_property_readonly("wall_s", [](const History& r) { return r.wall_s; },
                             "wall time of the library call, s")
      .def_property_readonly("stats", [](const History& r) -> py::object {
        return r.sim ? py::cast(r.sim->stats) : py::object(py::none());
      })
      .def_property_readonly("assembly", [](const History& r) -> py::object {
        return r.sim ? py::cast(r.sim->assembly) : py::object(py::none());
      })
      .def_property_readonly("equilibrium", [](const History& r) -> py::object {
        return r.sim && r.sim->equilibrium ? py::cast(*r.sim->equilibrium) : py::object(py::none());
      })
      .def_property_readonly("steady", [](const History& r) -> py::object {
        return r.sim ? py::cast(r.sim->steady) : py::object(py::none());
      }, "summaries over t >= steady_from (simulate(..., steady_from=...))")
      .def_property_readonly("t_end", [](const History& r) -> py::object {
        return r.sim ? py::cast(r.sim->t_end) : py::object(py::none());
      })
      .def_property_readonly("sample", [](const History& r) -> py::object {
        return r.sim ? py::cast(r.sim->sample) : py::object(py::none());
      })
      .def("__repr__", [](const History& r) {
        return fmt::format("Result({} outputs × {} samples)", r.h->names.size(), r.h->t.size());
      });
  m.def("summarise", [](const History& r, double from) { return analysis::summarise(*r.h, from); }, py::arg("result"),
        py::arg("from_t"), "Summaries (OutputSummary) of every output over t >= from_t (s).");

  m.def("simulate", [](const Model& model, const py::object& t_end, const py::object& sample, bool from_equilibrium,
                       double steady_from, const py::object& integrator, const py::object& method,
                       const py::object& rtol, const py::object& atol, const py::object& max_step,
                       const py::object& progress) {
    analysis::SimulateOptions o;
    // Given: the CLI's rule and message (--t-end, --sample); None (-1): the model's options.
    o.t_end = t_end.is_none() ? -1.0 : rule_arg(t_end, "t_end", analysis::t_end_rule);
    o.sample = sample.is_none() ? -1.0 : rule_arg(sample, "sample", analysis::sample_rule);
    // The CLI's --steady-from (>= 0 s, at most 1e7 s); a negative value (the default −1): off. NaN is refused.
    if (!(steady_from < 0) && !(steady_from >= 0 && steady_from <= 1e7))
      throw InvalidArgument(fmt::format("steady_from: {} is out of range; expected >= 0 s, at most 1e7 s (or < 0: off)", steady_from));
    o.from_equilibrium = from_equilibrium, o.steady_from = steady_from;
    o.integrator = integrator_arg(integrator, method, rtol, atol, max_step);
    return run(progress, [&](Call& call) {
      const auto t0 = Clock::now();
      auto sim = std::make_shared<analysis::Simulation>(analysis::simulate(model.model(), o, [&](double t, double te) {
        call.post([t, te](const py::object& cb) { cb(t, te); });
      }));
      return History{sim, &sim->history, sim, seconds_since(t0)};
    });
  }, py::arg("model"), py::arg("t_end") = py::none(), py::arg("sample") = py::none(), py::kw_only(),
        py::arg("from_equilibrium") = false, py::arg("steady_from") = -1.0, py::arg("integrator") = py::none(),
        py::arg("method") = py::none(), py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        py::arg("max_step") = py::none(), py::arg("progress") = py::none(),
        "Time simulation (analysis::simulate, as `inerta simulate`): assembles at t = 0 (static equilibrium with "
        "from_equilibrium), integrates to t_end (s; None: the model's options.t_end; given: > 0 s, at most 1e7 s, as "
        "`inerta simulate --t-end`, else InvalidArgument with the CLI's message) and samples every output each "
        "`sample` s. Integrator: `integrator` (IntegratorOptions) and/or method ('rk'|'bdf'), rtol, atol, max_step "
        "(s). steady_from >= 0: Result.steady summarises t >= steady_from. progress(t, t_end) is called on this "
        "thread; Ctrl-C stops the run (KeyboardInterrupt). NumericalError with the time on failure.");

}

// A pantograph under a catenary.
void bind_under_catenary(py::module_& m) {
  // ---- Under a catenary -------------------------------------------------------------------------------
  py::class_<analysis::ContactSummary>(m, "ContactSummary", "Contact force of one pantograph over a coupled run.")
      .def_readonly("stats", &analysis::ContactSummary::stats, "over the window (last window_spans spans)")
      .def_readonly("first_loss_t", &analysis::ContactSummary::first_loss_t, "s, first sample with F <= 0 (−1: none)")
      .def_readonly("first_loss_x", &analysis::ContactSummary::first_loss_x, "m along the line there")
      .def_readonly("lost_samples", &analysis::ContactSummary::lost_samples);

  py::class_<CoupledResult>(m, "CoupledResult",
                            "Pantographs running under a catenary (analysis::simulate_coupled): histories[k] is the "
                            "Result of pantograph k (its model's outputs, F_contact last); r['F_contact'] and r.t "
                            "index the leading pantograph's.")
      .def_property_readonly("histories", [](const CoupledResult& r) {
        std::vector<History> v;
        for (std::size_t k = 0; k < r.sim->histories.size(); ++k) v.push_back(r.history(k));
        return v;
      })
      .def("__getitem__", [](const CoupledResult& r, const std::string& name) {
        return item(py::cast(r.history(0)), name);
      }, py::arg("name"))
      .def_property_readonly("t", [](const CoupledResult& r) { return item(py::cast(r.history(0)), "t"); })
      .def_property_readonly("names", [](const CoupledResult& r) { return r.sim->histories.at(0).names; })
      .def_property_readonly("contacts", [](const CoupledResult& r) { return r.sim->contacts; })
      .def_property_readonly("stats", [](const CoupledResult& r) { return r.sim->stats; })
      .def_property_readonly("speed", [](const CoupledResult& r) { return r.sim->speed; }, "m/s")
      .def_property_readonly("span", [](const CoupledResult& r) { return r.sim->span; }, "m")
      .def_property_readonly("t_end", [](const CoupledResult& r) { return r.sim->t_end; }, "s")
      .def_property_readonly("sample", [](const CoupledResult& r) { return r.sim->sample; }, "s")
      .def_property_readonly("window_from", [](const CoupledResult& r) { return r.sim->window_from; },
                             "s: start of the statistics window")
      .def_property_readonly("section", [](const CoupledResult& r) { return r.sim->section; },
                             "a finite line: the statistics' section (m along the line)")
      .def_property_readonly("support_x", [](const CoupledResult& r) { return copy(r.sim->support_x); },
                             "a finite line: the supports reported, m")
      .def_property_readonly("supports", [](const CoupledResult& r) {
        return History{r.sim, &r.sim->supports, nullptr, r.wall_s};
      }, "a finite line: the supports' uplift over time (m), a Result")
      .def_property_readonly("quality", [](const CoupledResult& r) { return r.sim->quality; },
                             "per pantograph: EN 50317 ContactQuality (raw and filtered statistics, PSD)")
      .def_property_readonly("uplift", [](const CoupledResult& r) { return r.sim->uplift; },
                             "the supports in the section: SupportUplift (max uplift, m, and when)")
      .def_property_readonly("wall_s", [](const CoupledResult& r) { return r.wall_s; })
      .def("__repr__", [](const CoupledResult& r) {
        return fmt::format("CoupledResult({} pantograph(s), v = {:.4g} m/s, t_end = {:.4g} s)", r.sim->histories.size(),
                           r.sim->speed, r.sim->t_end);
      });

  m.def("simulate_coupled", [](const py::object& model, const py::object& catenary, double speed,
                               const py::object& contact, const py::object& positions, const py::object& spans,
                               const py::object& t_end, const py::object& sample, const py::object& window_spans,
                               const py::object& integrator, const py::object& method,
                               const py::object& rtol, const py::object& atol, const py::object& max_step,
                               const py::object& progress, const py::object& max_seconds, bool allow_supercritical) {
    const CatenaryArg cat = catenary_arg(catenary);
    const auto pantographs = train(model, positions, contact_arg(contact, cat));
    analysis::check_run_speed(*cat.catenary, speed,
                              t_end.is_none() ? static_cast<int>(rule_arg(spans, "spans", analysis::spans_rule)) : 0,
                              allow_supercritical);
    print_warning(analysis::speed_warning(*cat.catenary, speed));
    cost_guard(cat.catenary->estimated_seconds(pantographs, speed, t_end.is_none() ? -1.0 : rule_arg(t_end, "t_end", analysis::t_end_rule)),
               cat.catenary->estimated_bytes(pantographs, speed, t_end.is_none() ? -1.0 : rule_arg(t_end, "t_end", analysis::t_end_rule)),
               max_seconds, "this run");
    analysis::CoupledOptions o;
    // The CLI's rules and messages (--spans, --t-end, --sample); None: by spans, L/(400 v).
    o.spans = static_cast<int>(rule_arg(spans, "spans", analysis::spans_rule));
    o.window_spans = static_cast<int>(rule_arg(window_spans, "window_spans", analysis::window_spans_rule));
    o.t_end = t_end.is_none() ? -1.0 : rule_arg(t_end, "t_end", analysis::t_end_rule);
    o.sample = sample.is_none() ? -1.0 : rule_arg(sample, "sample", analysis::sample_rule);
    o.integrator = integrator_arg(integrator, method, rtol, atol, max_step);
    o.allow_supercritical = allow_supercritical;
    return run(progress, [&](Call& call) {
      const auto t0 = Clock::now();
      auto sim = std::make_shared<analysis::CoupledSimulation>(
          analysis::simulate_coupled(pantographs, *cat.catenary, speed, o, [&](double t, double te) {
            call.post([t, te](const py::object& cb) { cb(t, te); });
          }));
      return CoupledResult{sim, seconds_since(t0)};
    });
  }, py::arg("model"), py::arg("catenary"), py::arg("speed"), py::kw_only(), py::arg("contact") = py::none(),
        py::arg("positions") = py::none(), py::arg("spans") = 12, py::arg("t_end") = py::none(), py::arg("sample") = py::none(),
        py::arg("window_spans") = 2, py::arg("integrator") = py::none(), py::arg("method") = py::none(),
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("max_step") = py::none(),
        py::arg("progress") = py::none(), py::arg("max_seconds") = analysis::default_max_seconds,
        py::arg("allow_supercritical") = false,
        "Pantographs under a catenary at `speed` (m/s) from the coupled static equilibrium "
        "(analysis::simulate_coupled, as `inerta simulate --catenary`). model: a pantograph Model (copies at "
        "`positions`, m along the line; default one at 0) or a list of PantographOnLine. catenary: a Catenary, a "
        "CatenaryFile (its contact law is the default) or a file name. Run length: `spans` spans, or t_end (s); "
        "sample (s; default L/(400 v)). progress(t, t_end); Ctrl-C stops the run. The cost guard: an estimate "
        "(estimated_seconds) beyond 10 s is printed on sys.stderr before the run; above max_seconds (default 600; "
        "None: no limit) the run is refused with ModelError, before the line is built. A speed above the contact wire's "
        "wave speed is refused unless allow_supercritical (the CLI's --allow-supercritical); above 1000 m/s, or one "
        "whose run would last beyond 1e7 s, always (ModelError).");

}

// The results of a speed sweep.
void bind_sweep_results(py::module_& m) {
  // ---- Speed sweeps -----------------------------------------------------------------------------------
  py::class_<analysis::SpeedResult>(m, "SpeedResult", "The contact force at one speed.")
      .def_readonly("speed", &analysis::SpeedResult::speed, "m/s")
      .def_readonly("stats", &analysis::SpeedResult::stats, "of the leading pantograph")
      .def_readonly("contacts", &analysis::SpeedResult::contacts, "of every pantograph")
      .def_readonly("spans", &analysis::SpeedResult::spans, "spans simulated")
      .def_readonly("sigma_change", &analysis::SpeedResult::sigma_change, "last span-to-span relative change of σ")
      .def_readonly("converged", &analysis::SpeedResult::converged,
                    "time method: σ settled before the span limit (False: still changing)")
      .def_readonly("floquet", &analysis::SpeedResult::floquet,
                    "periodic method: the largest Floquet multiplier |μ| (>= 1: unstable, statistics NaN)")
      .def_property_readonly("stable", &analysis::SpeedResult::stable, "floquet < 1 (always True for the time method)")
      .def_property_readonly("support_x", [](const analysis::SpeedResult& s) { return copy(s.support_x); },
                             "a finite line: supports in the analysis section, m")
      .def_property_readonly("support_uplift", [](const analysis::SpeedResult& s) { return copy(s.support_uplift); },
                             "a finite line: the largest uplift of each, m")
      .def_readonly("loss_runs", &analysis::SpeedResult::loss_runs,
                    "a finite line: per pantograph, the lengths (samples) of the section's runs of raw F <= 0")
      .def_readonly("sample_dt", &analysis::SpeedResult::sample_dt, "s, the sampling step of a finite line's run")
      .def_readonly("uplift_limit", &analysis::SpeedResult::uplift_limit, "m, the line's registration uplift limit (NaN: none)")
      .def_readonly("uplift_limited", &analysis::SpeedResult::uplift_limited,
                    "the line's registration.uplift_limited: a stop limits the uplift (support_uplift takes its limited factor)")
      .def_readonly("filtered", &analysis::SpeedResult::filtered,
                    "a finite line: each contact's statistics after the 20 Hz low-pass (EN 50317)")
      .def_readonly("overlap", &analysis::SpeedResult::overlap,
                    "a line of tension sections: each contact's statistics over the overlap spans in the section")
      .def_readonly("overlap_filtered", &analysis::SpeedResult::overlap_filtered,
                    "the same after the 20 Hz low-pass")
      .def_property_readonly("t", [](py::object self) { return view(self.cast<const analysis::SpeedResult&>().t, self); },
                             "s (run_speed only; empty in sweeps)")
      .def_property_readonly("F", [](py::object self) { return view(self.cast<const analysis::SpeedResult&>().F, self); },
                             "contact force of the leading pantograph, N (run_speed only)")
      .def("__repr__", [](const analysis::SpeedResult& s) {
        return fmt::format("SpeedResult(v = {:.4g} m/s, σ = {:.4g} N, mean = {:.4g} N)", s.speed, s.stats.std,
                           s.stats.mean);
      })
      .def(py::pickle(
          [](const analysis::SpeedResult& s) {
            return py::make_tuple(s.speed, s.stats, s.contacts, s.spans, s.sigma_change, s.converged, s.floquet, s.t, s.F,
                                  s.support_x, s.support_uplift, s.filtered, s.loss_runs, s.sample_dt, s.uplift_limit,
                                  s.uplift_limited);
          },
          [](const py::tuple& t) {
            analysis::SpeedResult s;
            s.speed = t[0].cast<double>(), s.stats = t[1].cast<analysis::ContactStatistics>();
            s.contacts = t[2].cast<std::vector<analysis::ContactStatistics>>(), s.spans = t[3].cast<int>();
            s.sigma_change = t[4].cast<double>(), s.converged = t[5].cast<bool>(), s.floquet = t[6].cast<double>();
            s.t = t[7].cast<std::vector<double>>(), s.F = t[8].cast<std::vector<double>>();
            s.support_x = t[9].cast<std::vector<double>>(), s.support_uplift = t[10].cast<std::vector<double>>();
            s.filtered = t[11].cast<std::vector<analysis::ContactStatistics>>();
            s.loss_runs = t[12].cast<std::vector<std::vector<long>>>(), s.sample_dt = t[13].cast<double>();
            s.uplift_limit = t[14].cast<double>();
            if (t.size() > 15) s.uplift_limited = t[15].cast<bool>();  // a result pickled before issue 53 has not
            return s;
          }));

  py::class_<SweepResult>(m, "SweepResult",
                          "Contact statistics over speeds: NumPy arrays speed (m/s), mean, std, max, min, stat_max, "
                          "stat_min (N), loss_pct (%), spans, sigma_change; r[i] is the SpeedResult of speed i.")
      .def(py::init([](std::vector<analysis::SpeedResult> r, double wall_s, const std::string& method) {
             if (method != "time" && method != "periodic") throw py::value_error("method: expected 'time' or 'periodic'");
             return SweepResult{std::move(r), wall_s, method};
           }),
           py::arg("results"), py::arg("wall_s") = 0.0, py::arg("method") = "time",
           "A sweep from its speeds' results (inerta.sweep(..., client=c) gathers them from Dask workers).")
      .def("__len__", [](const SweepResult& s) { return s.r.size(); })
      .def("__getitem__", [](const SweepResult& s, long i) {
        const long n = static_cast<long>(s.r.size());
        if (i < 0) i += n;
        if (i < 0 || i >= n) throw py::index_error("speed index out of range");
        return s.r[static_cast<std::size_t>(i)];
      })
      .def_property_readonly("results", [](const SweepResult& s) { return s.r; })
      .def_property_readonly("speed", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.speed; }); })
      .def_property_readonly("mean", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.mean; }); })
      .def_property_readonly("std", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.std; }); })
      .def_property_readonly("max", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.max; }); })
      .def_property_readonly("min", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.min; }); })
      .def_property_readonly("stat_max", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.stat_max; }); })
      .def_property_readonly("stat_min", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.stat_min; }); })
      .def_property_readonly("loss_pct", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stats.loss_pct; }); })
      .def_property_readonly("spans", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.spans; }); })
      .def_property_readonly("sigma_change", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.sigma_change; }); })
      .def_property_readonly("converged", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.converged ? 1.0 : 0.0; }); },
                             "1 where σ settled (time method)")
      .def_property_readonly("floquet", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.floquet; }); },
                             "largest Floquet multiplier per speed (periodic method; 0 for the time method)")
      .def_property_readonly("stable", [](const SweepResult& s) { return column(s.r, [](auto& x) { return x.stable() ? 1.0 : 0.0; }); },
                             "1 where the periodic solution is stable")
      .def_property_readonly("sigma_max", [](const SweepResult& s) {
        if (s.r.empty()) throw py::value_error("empty sweep");
        if (s.worst() == s.r.size()) throw py::value_error("no stable speed: every periodic solution is unstable");
        const auto& w = s.r[s.worst()];
        return py::make_tuple(w.stats.std, w.speed, w.stats.mean);
      }, "(σ_max in N, its speed in m/s, the mean contact force there in N)")
      .def_property_readonly("wall_s", [](const SweepResult& s) { return s.wall_s; }, "wall time of the library call, s")
      .def_property_readonly("method", [](const SweepResult& s) { return s.method; }, "'time' or 'periodic'")
      .def("__repr__", [](const SweepResult& s) {
        return fmt::format("SweepResult({} speeds, {})", s.r.size(), s.method);
      });

}

// Speed sweeps, estimates, comparisons, one speed.
void bind_sweeps(py::module_& m) {
  m.def("sweep", [](const py::object& model, const py::object& catenary, const py::object& speeds,
                    const py::object& contact, const py::object& positions, const py::object& options,
                    const py::object& method, const py::object& rtol, const py::object& atol,
                    const py::object& progress, const py::object& max_seconds) {
    const CatenaryArg cat = catenary_arg(catenary);
    const auto pantographs = train(model, positions, contact_arg(contact, cat));
    const std::vector<double> v = doubles(speeds);
    const analysis::RunOptions o = run_options(options, method, rtol, atol);
    for (double s : v) {  // before the estimate (which divides by them)
      require(analysis::speed_rule, s, "speeds");
      analysis::check_run_speed(*cat.catenary, s, o.max_spans, o.allow_supercritical);
    }
    if (!v.empty()) print_warning(analysis::speed_warning(*cat.catenary, *std::max_element(v.begin(), v.end())));
    cost_guard(analysis::estimated_sweep_seconds(pantographs, *cat.catenary, v), cat.catenary->estimated_bytes(pantographs, 0, 0),
               max_seconds,
               fmt::format("this sweep of {} speeds", v.size()));
    return run(progress, [&](Call& call) {
      const auto t0 = Clock::now();
      auto r = analysis::sweep(pantographs, *cat.catenary, v, o, [&](int done, int total) {
        call.post([done, total](const py::object& cb) { cb(done, total); });
      });
      return SweepResult{std::move(r), seconds_since(t0), "time"};
    });
  }, py::arg("model"), py::arg("catenary"), py::arg("speeds"), py::kw_only(), py::arg("contact") = py::none(),
        py::arg("positions") = py::none(), py::arg("options") = py::none(), py::arg("method") = py::none(),
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("progress") = py::none(),
        py::arg("max_seconds") = analysis::default_max_seconds,
        "Speed sweep in the time domain (analysis::sweep, as `inerta sweep`): at every speed (m/s; inerta.kmh "
        "converts) the pantographs are coupled to the catenary and run span by span until σ settles, the speeds in "
        "parallel on all cores (oneTBB; the GIL is released). options: RunOptions; method/rtol/atol override its "
        "integrator. progress(done, total) after each speed, on this thread; Ctrl-C cancels the sweep "
        "(KeyboardInterrupt once the running speeds finish). The cost guard as simulate_coupled's: the estimate "
        "(estimated_sweep_seconds) beyond 10 s on sys.stderr; above max_seconds (default 600; None: no limit) ModelError.");

  m.def("estimated_seconds", [](const py::object& model, const py::object& catenary, double speed, const py::object& t_end,
                                const py::object& contact, const py::object& positions) {
    const CatenaryArg cat = catenary_arg(catenary);
    return cat.catenary->estimated_seconds(train(model, positions, contact_arg(contact, cat)), speed,
                                           t_end.is_none() ? -1.0 : rule_arg(t_end, "t_end", analysis::t_end_rule));
  }, py::arg("model"), py::arg("catenary"), py::arg("speed"), py::arg("t_end") = py::none(), py::kw_only(),
        py::arg("contact") = py::none(), py::arg("positions") = py::none(),
        "A rough wall time (s) of one run (simulate_coupled) on the 2-core reference machine "
        "(catenary::Catenary::estimated_seconds; t_end None: to the line's end, on a lumped line or wire profile a "
        "sweep's longest run of 40 spans).");
  m.def("estimated_sweep_seconds", [](const py::object& model, const py::object& catenary, const py::object& speeds,
                                      const py::object& contact, const py::object& positions) {
    const CatenaryArg cat = catenary_arg(catenary);
    return analysis::estimated_sweep_seconds(train(model, positions, contact_arg(contact, cat)), *cat.catenary, doubles(speeds));
  }, py::arg("model"), py::arg("catenary"), py::arg("speeds"), py::kw_only(), py::arg("contact") = py::none(),
        py::arg("positions") = py::none(), "The same for a sweep, its speeds shared among the cores.");

  py::class_<analysis::RunComparison>(m, "RunComparison", "One speed run on two catenaries (inerta.compare).")
      .def_readonly("speed", &analysis::RunComparison::speed, "m/s")
      .def_readonly("reference", &analysis::RunComparison::reference)
      .def_readonly("candidate", &analysis::RunComparison::candidate)
      .def_readonly("reference_s", &analysis::RunComparison::reference_s, "wall time of the reference run, s")
      .def_readonly("candidate_s", &analysis::RunComparison::candidate_s, "wall time of the candidate run, s");

  m.def("compare", [](const py::object& model, const py::object& reference, const py::object& candidate,
                      const py::object& speeds, const py::object& contact) {
    const CatenaryArg ref = catenary_arg(reference), cand = catenary_arg(candidate);
    const auto pantographs = train(model, py::none(), contact_arg(contact, ref));
    const std::vector<double> v = doubles(speeds);
    return run(py::none(), [&](Call&) { return analysis::compare(pantographs, *ref.catenary, *cand.catenary, v, {}); });
  }, py::arg("model"), py::arg("reference"), py::arg("candidate"), py::arg("speeds"), py::kw_only(),
        py::arg("contact") = py::none(),
        "The same runs on two catenaries, one speed after the other, each timed (analysis::compare; `inerta catenary "
        "check-reduction` compares a finite-element line's direct and modal solves this way). Speeds in m/s.");

  m.def("sweep_periodic", [](const Model& model, const py::object& catenary, const py::object& speeds,
                             const py::object& contact, const py::object& harmonics_arg) {
    const CatenaryArg cat = catenary_arg(catenary);
    const catenary::Contact c = contact_arg(contact, cat);
    const std::vector<double> v = doubles(speeds);
    const int harmonics = static_cast<int>(rule_arg(harmonics_arg, "harmonics", analysis::harmonics_rule));  // as --harmonics
    return run(py::none(), [&](Call&) {
      const auto t0 = Clock::now();
      auto r = analysis::sweep_periodic(model.p, *cat.catenary, c, v, harmonics);
      return SweepResult{std::move(r), seconds_since(t0), "periodic"};
    });
  }, py::arg("model"), py::arg("catenary"), py::arg("speeds"), py::kw_only(), py::arg("contact") = py::none(),
        py::arg("harmonics") = 8,
        "Periodic steady state by harmonic balance (analysis::sweep_periodic, `inerta sweep --method periodic`): "
        "the pantograph linearised about its static equilibrium under the mean catenary; needs a point-model "
        "catenary (the lumped one) without mass harmonics (ModelError otherwise). Speeds in m/s.");

  m.def("run_speed", [](const py::object& model, const py::object& catenary, double speed, const py::object& contact,
                        const py::object& positions, const py::object& options, const py::object& method,
                        const py::object& rtol, const py::object& atol) {
    const CatenaryArg cat = catenary_arg(catenary);
    const auto pantographs = train(model, positions, contact_arg(contact, cat));
    const analysis::RunOptions o = run_options(options, method, rtol, atol);
    return run(py::none(), [&](Call&) {
      auto sys = cat.catenary->couple(pantographs, speed);
      return analysis::run_speed(*sys, o);
    });
  }, py::arg("model"), py::arg("catenary"), py::arg("speed"), py::kw_only(), py::arg("contact") = py::none(),
        py::arg("positions") = py::none(), py::arg("options") = py::none(), py::arg("method") = py::none(),
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        "One speed of a sweep (analysis::run_speed on the coupled system): from the static equilibrium, span by span "
        "until σ settles; the SpeedResult keeps the contact-force history t, F of the leading pantograph.");

}

// Modes, linear models and FRFs.
void bind_modes_frfs(py::module_& m) {
  // ---- Modes and linear models ------------------------------------------------------------------------
  py::class_<mbs::LinearModel>(m, "LinearModel",
                               "Linearisation about a static equilibrium (spec/02 §2.5): q = q_e + N ξ, state "
                               "X = [ξ; ξ̇; z], Ẋ = A X; reduced M (incl. inerters), C, K. Arrays are views.")
      .def_readonly("equilibrium", &mbs::LinearModel::equilibrium)
      .def_readonly("t", &mbs::LinearModel::t)
      .def_readonly("N", &mbs::LinearModel::N)
      .def_readonly("Nt", &mbs::LinearModel::Nt, "ξ = Nt (q − q_e): selects the independent coordinates")
      .def_readonly("independent", &mbs::LinearModel::independent, "the coordinates ξ are (indices into q)")
      .def_readonly("A", &mbs::LinearModel::A, "state matrix of [ξ; ξ̇; z] (the state-space model Ẋ = A X)")
      .def_readonly("M", &mbs::LinearModel::M, "kg (kg·m² for angles)")
      .def_readonly("C", &mbs::LinearModel::C, "N·s/m")
      .def_readonly("K", &mbs::LinearModel::K, "N/m")
      .def_readonly("dof", &mbs::LinearModel::dof)
      .def_readonly("nz", &mbs::LinearModel::nz, "internal states");
  py::class_<mbs::Mode>(m, "Mode", "One mode: eigenvalue λ (1/s), |λ|/2π (Hz), damping ratio, real shape (body coordinates).")
      .def_readonly("eigenvalue", &mbs::Mode::eigenvalue)
      .def_readonly("frequency_hz", &mbs::Mode::frequency_hz, "|λ|/2π, Hz")
      .def_readonly("damped_frequency_hz", &mbs::Mode::damped_frequency_hz, "Im λ/2π, Hz")
      .def_readonly("damping_ratio", &mbs::Mode::damping_ratio)
      .def_readonly("shape", &mbs::Mode::shape)
      .def_readonly("description", &mbs::Mode::description)
      .def("__repr__", [](const mbs::Mode& o) {
        return fmt::format("Mode({:.4f} Hz, ζ = {:.4f}: {})", o.frequency_hz, o.damping_ratio, o.description);
      });
  m.def("linearise", [](const Model& h, const mbs::State& x, double t) { return mbs::linearise(h.model(), x, t); },
        py::arg("model"), py::arg("state"), py::arg("t") = 0.0,
        "Linearises the model about the equilibrium `state` (q̇ = 0) at time t (mbs::linearise).");
  m.def("modes", [](const Model& h, const mbs::LinearModel& lin) { return mbs::modes(h.model(), lin); },
        py::arg("model"), py::arg("linear"), "Modes of a linear model, sorted by frequency (mbs::modes).");

  py::class_<analysis::ModalAnalysis>(m, "ModalAnalysis", "Modes about a static equilibrium (as `inerta modes`).")
      .def_readonly("setting", &analysis::ModalAnalysis::setting, "what the modes are of, in words")
      .def_property_readonly("model", [](const analysis::ModalAnalysis& a) { return make_model(a.model); },
                             "the model that was linearised")
      .def_readonly("equilibrium", &analysis::ModalAnalysis::equilibrium)
      .def_readonly("linear", &analysis::ModalAnalysis::linear)
      .def_readonly("modes", &analysis::ModalAnalysis::modes)
      .def_property_readonly("frequencies", [](const analysis::ModalAnalysis& a) {
        return column(a.modes, [](auto& x) { return x.frequency_hz; });
      }, "Hz")
      .def_property_readonly("damping_ratios", [](const analysis::ModalAnalysis& a) {
        return column(a.modes, [](auto& x) { return x.damping_ratio; });
      })
      .def("to_json", [](const analysis::ModalAnalysis& a) {
        return py::module_::import("json").attr("loads")(io::json_text(io::linear_model_json(a.model, a.linear)));
      }, "the linear model document of `inerta modes --export` (io::linear_model_json) as a dict");
  m.def("modal_analysis", [](const Model& h, const py::object& catenary, const py::object& contact) {
    if (catenary.is_none()) return run(py::none(), [&](Call&) { return analysis::modal_analysis(h.model()); });
    const CatenaryArg cat = catenary_arg(catenary);
    const catenary::Contact c = contact_arg(contact, cat);
    return run(py::none(), [&](Call&) { return analysis::modal_analysis(h.p, *cat.catenary, c); });
  }, py::arg("model"), py::arg("catenary") = py::none(), py::arg("contact") = py::none(),
        "Modes of the model about its static equilibrium at t = 0, or, with a catenary, of the pantograph coupled "
        "to the catenary's mean (time-invariant part).");
  m.def("modal_analysis_free_head", [](const Model& h) {
    return run(py::none(), [&](Call&) { return analysis::modal_analysis_free_head(h.p); });
  }, py::arg("model"),
        "Modes of the free pantograph: the head released from the rig and loaded by the static contact force "
        "(ModelError without a rig joint). `inerta modes` uses this for a model with a rig.");
  m.def("linear_model_json", [](const Model& h, const mbs::LinearModel& lin) {
    return py::module_::import("json").attr("loads")(io::json_text(io::linear_model_json(h.model(), lin)));
  }, py::arg("model"), py::arg("linear"), "The linear-model document (A, N, M, C, K, ...) as a dict.");
  m.def("write_linear_model", [](const py::object& path, const Model& h, const mbs::LinearModel& lin) {
    io::write_linear_model(path_arg(path), h.model(), lin);
  }, py::arg("path"), py::arg("model"), py::arg("linear"), "Writes the linear model as JSON (`inerta modes --export`).");

  // ---- FRFs ---------------------------------------------------------------------------------------------
  py::class_<analysis::Frf>(m, "Frf",
                            "Frequency responses: f (Hz), outputs (names) and H[i, k], output i at f[k] per N of contact "
                            "force ((m/s²)/N for accelerations).")
      .def(py::init([](const py::object& f, std::vector<std::string> outputs, const py::array_t<std::complex<double>, py::array::forcecast>& H) {
             analysis::Frf r;
             r.f = doubles(f);
             r.outputs = std::move(outputs);
             set_frf_matrix(r, H);
             if (r.H.size() != r.outputs.size()) throw py::value_error("H: one row per output");
             for (const auto& row : r.H)
               if (row.size() != r.f.size()) throw py::value_error("H: one column per frequency");
             return r;
           }),
           py::arg("f"), py::arg("outputs"), py::arg("H"))
      .def_property_readonly("f", [](const analysis::Frf& r) { return copy(r.f); })
      .def_readonly("outputs", &analysis::Frf::outputs)
      .def_property_readonly("H", &frf_matrix, "complex array [output, frequency] (a copy)")
      .def("__getitem__", [](const analysis::Frf& r, const std::string& name) {
        for (std::size_t i = 0; i < r.outputs.size(); ++i)
          if (r.outputs[i] == name) return copy(r.H[i]);
        throw py::key_error(name);
      });
  py::class_<analysis::SteppedSine>(m, "SteppedSine", "Options of the stepped-sine FRF.")
      .def(py::init<>())
      .def_readwrite("vc", &analysis::SteppedSine::vc, "mean velocity amplitude V_c, m/s")
      .def_readwrite("cycles", &analysis::SteppedSine::cycles)
      .def_readwrite("analysed", &analysis::SteppedSine::analysed)
      .def_readwrite("samples_per_cycle", &analysis::SteppedSine::samples_per_cycle)
      .def_readwrite("integrator", &analysis::SteppedSine::integrator);
  m.def("frf_linear", [](const Model& h, const std::vector<std::string>& outputs, const py::object& f) {
    const std::vector<double> fv = doubles(f);
    return run(py::none(), [&](Call&) { return analysis::frf_linear(h.p, outputs, fv); });
  }, py::arg("model"), py::arg("outputs"), py::arg("f"),
        "Test-rig FRF (spec/04 §4.2) from the model linearised with the head held by its rig joint: outputs per N of "
        "contact force at frequencies f (Hz), as `inerta frf`.");
  m.def("frf_stepped_sine", [](const Model& h, const std::vector<std::string>& outputs, const py::object& f,
                               const py::object& options, const py::object& vc, const py::object& cycles,
                               const py::object& analysed) {
    const std::vector<double> fv = doubles(f);
    analysis::SteppedSine o = options.is_none() ? analysis::SteppedSine{} : options.cast<analysis::SteppedSine>();
    // Given: the CLI's rules and messages (--vc, --cycles, --analysed); the rest by analysis::check.
    if (!vc.is_none()) o.vc = rule_arg(vc, "vc", analysis::vc_rule);
    if (!cycles.is_none()) o.cycles = static_cast<int>(rule_arg(cycles, "cycles", analysis::cycles_rule));
    if (!analysed.is_none()) o.analysed = static_cast<int>(rule_arg(analysed, "analysed", analysis::analysed_rule));
    return run(py::none(), [&](Call&) { return analysis::frf_stepped_sine(h.p, outputs, fv, o); });
  }, py::arg("model"), py::arg("outputs"), py::arg("f"), py::kw_only(), py::arg("options") = py::none(),
        py::arg("vc") = py::none(), py::arg("cycles") = py::none(), py::arg("analysed") = py::none(),
        "Stepped-sine FRF by time simulation of the nonlinear model on the rig (frequencies in parallel).");

}

// The catenary alone; acceptance criteria and verdicts.
void bind_catenary_acceptance(py::module_& m) {
  // ---- Catenary alone ---------------------------------------------------------------------------------
  py::class_<analysis::CatenaryResponse>(m, "CatenaryResponse", "The lumped catenary's steady response at one f_p.")
      .def_readonly("fp", &analysis::CatenaryResponse::fp, "Hz")
      .def_readonly("speed", &analysis::CatenaryResponse::speed, "m/s")
      .def_readonly("acc_amplitude", &analysis::CatenaryResponse::acc_amplitude, "m/s²")
      .def_readonly("disp_amplitude", &analysis::CatenaryResponse::disp_amplitude, "m")
      .def_readonly("mean_uplift", &analysis::CatenaryResponse::mean_uplift, "m")
      .def_readonly("growth", &analysis::CatenaryResponse::growth)
      .def("stable", &analysis::CatenaryResponse::stable);
  py::class_<CatenaryResponses>(m, "CatenaryResponses",
                                "Arrays fp (Hz), speed (m/s), acc_amplitude (m/s²), disp_amplitude (m), mean_uplift "
                                "(m), growth, stable (bool); r[i] is one CatenaryResponse.")
      .def("__len__", [](const CatenaryResponses& c) { return c.r.size(); })
      .def("__getitem__", [](const CatenaryResponses& c, std::size_t i) { return c.r.at(i); })
      .def_property_readonly("fp", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.fp; }); })
      .def_property_readonly("speed", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.speed; }); })
      .def_property_readonly("acc_amplitude", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.acc_amplitude; }); })
      .def_property_readonly("disp_amplitude", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.disp_amplitude; }); })
      .def_property_readonly("mean_uplift", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.mean_uplift; }); })
      .def_property_readonly("growth", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.growth; }); })
      .def_property_readonly("stable", [](const CatenaryResponses& c) { return column(c.r, [](auto& x) { return x.stable(); }); });
  m.def("catenary_response", [](const py::object& catenary, const py::object& fp, const py::object& force_arg,
                                const py::object& settle_arg, const py::object& periods_arg) {
    catenary::LumpedCatenary store;
    const catenary::LumpedCatenary& cat = lumped_arg(catenary, store);
    const std::vector<double> f = doubles(fp);
    const double force = rule_arg(force_arg, "force", analysis::force_rule);  // as --force
    const double settle = rule_arg(settle_arg, "settle", analysis::settle_rule);
    const int periods = static_cast<int>(rule_arg(periods_arg, "periods", analysis::periods_rule));
    return run(py::none(), [&](Call&) { return CatenaryResponses{analysis::catenary_response(cat, force, f, settle, periods)}; });
  }, py::arg("catenary"), py::arg("fp"), py::arg("force") = 70.0, py::arg("settle") = 60.0, py::arg("periods") = 10,
        "The lumped catenary alone under a constant upward force (N): steady acceleration amplitude against the "
        "pumping frequency f_p = v/L (Hz), as `inerta catenary-response`. catenary: a LumpedCatenary, a lumped "
        "Catenary or CatenaryFile.");

  // ---- Acceptance (analysis/acceptance.hpp, docs/contact-quality.md "Acceptance") ----------------------
  py::class_<analysis::AcceptanceCriteria, std::shared_ptr<analysis::AcceptanceCriteria>>(m, "AcceptanceCriteria",
                                           "An acceptance criteria set (a preset or a file, load_acceptance).")
      .def_readonly("name", &analysis::AcceptanceCriteria::name)
      .def_readonly("source", &analysis::AcceptanceCriteria::source, "the file it was read from")
      .def_readonly("filter_cutoff", &analysis::AcceptanceCriteria::filter_cutoff, "Hz")
      .def_readonly("filter_order", &analysis::AcceptanceCriteria::filter_order)
      .def_readonly("has_target", &analysis::AcceptanceCriteria::has_target)
      .def("target", [](const analysis::AcceptanceCriteria& c, double v) {
        if (!c.has_target) throw py::value_error(fmt::format("the criteria set '{}' has no target curve", c.name));
        return c.target.at(v * 3.6);
      }, py::arg("speed"), "the mean-force target at a speed in m/s, N; InvalidArgument outside target_speeds")
      .def_property_readonly("target_speeds", [](const analysis::AcceptanceCriteria& c) {
        if (!c.has_target) throw py::value_error(fmt::format("the criteria set '{}' has no target curve", c.name));
        return py::make_tuple(c.target.speeds.from, c.target.speeds.to);
      }, "(from, to) km/h: the speeds the target's source gives it for (to included); outside them it is not assessed")
      .def_property_readonly("arcing_text", &analysis::arcing_text,
                             "what a verdict says about contact loss: it stands in for the measured percentage of arcing "
                             "(empty without contact_loss)")
      .def("__repr__", [](const analysis::AcceptanceCriteria& c) { return fmt::format("AcceptanceCriteria('{}', {})", c.name, c.source); });
  m.def("load_acceptance", [](const py::object& which) { return io::load_acceptance(path_arg(which)); }, py::arg("criteria"),
        "An acceptance criteria set: a preset name (en50367-ac, en50367-ac15, en50367-dc3, en50367-dc1.5; inerta.acceptance_presets()) or a criteria "
        "file. ModelError with file, line and key for a bad file.");
  m.def("acceptance_presets", &io::acceptance_presets, "The names of the shipped acceptance criteria presets.");
  // The verdict rows of a sweep or coupled result against a preset, file or AcceptanceCriteria.
  static const auto verdict_rows = [](const py::object& result, const py::object& criteria, const char* fn) {
    analysis::AcceptanceCriteria loaded;
    const analysis::AcceptanceCriteria* c = nullptr;
    if (py::isinstance<analysis::AcceptanceCriteria>(criteria))
      c = &criteria.cast<const analysis::AcceptanceCriteria&>();
    else
      loaded = io::load_acceptance(path_arg(criteria)), c = &loaded;
    if (py::isinstance<SweepResult>(result)) return analysis::verdict(*c, result.cast<const SweepResult&>().r);
    if (py::isinstance<CoupledResult>(result)) return analysis::verdict(*c, *result.cast<const CoupledResult&>().sim);
    throw py::type_error(fmt::format("{}: result: expected the result of inerta.sweep or inerta.simulate_coupled, got {}", fn,
                                     py::str(py::type::of(result)).cast<std::string>()));
  };
  py::class_<analysis::Verdict>(m, "Verdict",
                                "The verdict of a run: status 'PASS', 'FAIL' or 'NOT ASSESSED' (no criterion could be judged: "
                                "never a PASS); failed and not_assessed name the criteria.")
      .def_property_readonly("status", [](const analysis::Verdict& v) { return std::string(v.text()); })
      .def_readonly("failed", &analysis::Verdict::failed)
      .def_readonly("not_assessed", &analysis::Verdict::not_assessed)
      .def("__bool__", &analysis::Verdict::pass)
      .def("__repr__", [](const analysis::Verdict& v) {
        return fmt::format("Verdict({}, failed=[{}], not_assessed=[{}])", v.text(), fmt::join(v.failed, ", "), fmt::join(v.not_assessed, ", "));
      });
  m.def("report_html", [](const py::object& result, const py::object& criteria, const py::object& catenary,
                          const std::string& model) {
    report::RunContext ctx;
    std::vector<std::string> args{"python3"};
    for (const auto& a : py::module_::import("sys").attr("argv").cast<py::list>()) args.push_back(py::str(a));
    ctx.provenance = report::current_provenance(args);  // this Python's command line and the inputs the module read
    ctx.model = model;
    std::shared_ptr<const catenary::Catenary> cat;
    if (py::isinstance<io::CatenaryFile>(catenary))
      cat = catenary.cast<const io::CatenaryFile&>().catenary;
    else if (py::isinstance<catenary::Catenary>(catenary))
      cat = catenary.cast<std::shared_ptr<catenary::Catenary>>();
    else if (!catenary.is_none())
      throw py::type_error(fmt::format("report_html: catenary: expected the run's Catenary or CatenaryFile, got {}",
                                       py::str(py::type::of(catenary)).cast<std::string>()));
    if (cat) ctx.line = cat->describe();
    analysis::AcceptanceCriteria loaded;
    if (!criteria.is_none()) {
      loaded = py::isinstance<analysis::AcceptanceCriteria>(criteria) ? criteria.cast<analysis::AcceptanceCriteria>()
                                                                      : io::load_acceptance(path_arg(criteria));
      ctx.criteria = &loaded;
      ctx.verdict = verdict_rows(result, py::cast(loaded), "report_html");
    }
    report::Record record;
    if (py::isinstance<SweepResult>(result)) return report::sweep_report(ctx, result.cast<const SweepResult&>().r, record);
    if (py::isinstance<CoupledResult>(result))
      return report::simulate_report(ctx, *result.cast<const CoupledResult&>().sim,
                                     cat ? cat->features() : std::vector<catenary::LineFeature>{}, record);
    throw py::type_error(fmt::format("report_html: result: expected the result of inerta.sweep or inerta.simulate_coupled, got {}",
                                     py::str(py::type::of(result)).cast<std::string>()));
  }, py::arg("result"), py::arg("criteria") = py::none(), py::arg("catenary") = py::none(), py::arg("model") = "",
        "The HTML report of a sweep or a coupled simulation, as the CLI's --report writes it (docs/cli.md \"Reports\"): "
        "the verdict first when criteria (a preset, a file or AcceptanceCriteria) are given, the statistics, the figures "
        "as inline SVG, the line's masts, droppers, stitch wires and overlaps (give the run's catenary), the provenance "
        "(this Python's command line and every input the module read, with SHA-256). Returns the page (str).");
  m.def("verdict", [](const py::object& result, const py::object& criteria) {
    return analysis::judge(verdict_rows(result, criteria, "verdict"));
  }, py::arg("result"), py::arg("criteria"),
        "The verdict line of inerta.acceptance's rows: Verdict(status 'PASS' | 'FAIL' | 'NOT ASSESSED', failed, "
        "not_assessed); bool(v) is True only for PASS.");
  m.def("acceptance", [](const py::object& result, const py::object& criteria) {
    const std::vector<analysis::VerdictRow> rows = verdict_rows(result, criteria, "acceptance");
    py::list items;
    for (const auto& x : rows)
      items.append(py::make_tuple(x.speed, x.pantograph, x.result.criterion, x.result.unit, x.result.value, x.result.limit,
                                  x.result.margin, x.result.passed, x.result.assessed, x.result.statistic,
                                  !x.result.statistic.empty() && x.result.assumed, x.result.source));
    // The text columns as wide as their longest entry (a source may be long).
    std::size_t stat = 1, src = 1;
    for (const auto& x : rows)
      stat = std::max(stat, py::str(x.result.statistic).attr("__len__")().cast<std::size_t>()),
      src = std::max(src, py::str(x.result.source).attr("__len__")().cast<std::size_t>());
    py::list dtype;
    const std::string stat_t = fmt::format("U{}", stat), src_t = fmt::format("U{}", src);
    for (const auto& [name, type] : std::vector<std::pair<const char*, const char*>>{
             {"speed", "f8"}, {"pantograph", "i4"}, {"criterion", "U16"}, {"unit", "U2"}, {"value", "f8"},
             {"limit", "f8"}, {"margin", "f8"}, {"passed", "?"}, {"assessed", "?"}, {"statistic", stat_t.c_str()},
             {"assumed", "?"}, {"source", src_t.c_str()}})
      dtype.append(py::make_tuple(name, type));
    return py::module_::import("numpy").attr("array")(items, py::arg("dtype") = dtype);
  }, py::arg("result"), py::arg("criteria"),
        "The acceptance verdict of a sweep (inerta.sweep) or a coupled simulation (inerta.simulate_coupled), as the "
        "CLI's --acceptance: a NumPy structured array, one row per speed, pantograph and criterion, with fields speed "
        "(m/s), pantograph (1 = the leading one), criterion, unit (N, %, m), value, limit, margin (positive: passes), "
        "passed, assessed (False: outside the criterion's speeds or without the data it needs; passed is then False "
        "and the row does not decide the verdict), statistic (what the value is: 'filtered, F_m + 3σ', …; empty where "
        "no entry covers the speed), assumed (the entry's number is not verified against a public source), source "
        "(the document and public address the entry names). criteria: a preset name, a file or an AcceptanceCriteria. The runs "
        "give the 20 Hz statistics with their own filter (20 Hz, order 4 by default); a set with another filter needs "
        "runs made with it (RunOptions.filter_cutoff / filter_order).");

  py::class_<analysis::AeroFit>(m, "AeroFit", "The aerodynamic uplift a v² that brings the mean contact force to a target.")
      .def_readonly("reached", &analysis::AeroFit::reached)
      .def_readonly("a", &analysis::AeroFit::a, "N·s²/m² (b = c = 0)")
      .def_readonly("mean", &analysis::AeroFit::mean, "N, the mean contact force with that a")
      .def_readonly("mean_without", &analysis::AeroFit::mean_without, "N, with a = 0")
      .def_readonly("target", &analysis::AeroFit::target, "N")
      .def_readonly("runs", &analysis::AeroFit::runs)
      .def("__repr__", [](const analysis::AeroFit& f) {
        return fmt::format("AeroFit(reached={}, a={:.6g}, mean={:.3f} N, target={:.3f} N)", f.reached ? "True" : "False", f.a,
                           f.mean, f.target);
      });
  m.def("fit_aerodynamic", [](const Model& model, const py::object& catenary, double speed, const py::object& criteria,
                              const py::object& contact) {
    const CatenaryArg cat = catenary_arg(catenary);
    const catenary::Contact k = contact_arg(contact, cat);
    const analysis::AcceptanceCriteria c = py::isinstance<analysis::AcceptanceCriteria>(criteria)
                                               ? criteria.cast<analysis::AcceptanceCriteria>()
                                               : io::load_acceptance(path_arg(criteria));
    if (!c.has_target) throw py::value_error(fmt::format("the criteria set '{}' has no mean-force target curve", c.name));
    analysis::RunOptions o;
    o.filter_cutoff = c.filter_cutoff, o.filter_order = c.filter_order;
    const auto stats = c.mean.empty() ? analysis::Statistics::Raw : c.mean.front().statistics;
    return run(py::none(), [&](Call&) {
      return analysis::fit_aerodynamic(model.p, *cat.catenary, k, speed, c.target.at(speed * 3.6), stats, o);
    });
  }, py::arg("model"), py::arg("catenary"), py::arg("speed"), py::arg("criteria"), py::kw_only(), py::arg("contact") = py::none(),
        "The a >= 0 of an aerodynamic uplift a v² (b = c = 0) for which the mean contact force at `speed` (m/s) equals "
        "the criteria set's target curve (as `inerta pantograph aero-fit`); reached is False if none does.");
}

}  // namespace

void bind_analysis(py::module_& m) {
  bind_options_statistics(m);
  bind_time_histories(m);
  bind_under_catenary(m);
  bind_sweep_results(m);
  bind_sweeps(m);
  bind_modes_frfs(m);
  bind_catenary_acceptance(m);
}

}  // namespace inerta::python
