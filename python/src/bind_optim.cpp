// Design studies (spec/07): a study from a file or from Python objects, J2 of a design (periodic
// fast path and time domain), layout optimisation, the figures' data, and the result writers.
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/error.hpp"
#include "inerta/io/files.hpp"
#include "inerta/io/json.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/io/study_report.hpp"
#include "inerta/io/study_results.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/numerics/pattern_search.hpp"
#include "inerta/optim/report.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::python {

namespace {

using optim::Study;

std::vector<std::shared_ptr<catenary::Catenary>> catenaries_of(const Study& s) {
  std::vector<std::shared_ptr<catenary::Catenary>> v;
  for (const auto& c : s.catenaries) v.push_back(std::const_pointer_cast<catenary::Catenary>(c));
  return v;
}

network::Network net_arg(const py::object& net, const py::object& params) { return network_arg(net, params); }

// A study's speeds (m/s): at least one, each by the library's speed rule (issue 52: none gave J2 = −1).
std::vector<double> study_speeds(const py::object& speeds, const char* fn) {
  std::vector<double> v = doubles(speeds);
  if (v.empty()) throw InvalidArgument(fmt::format("{}: speeds: empty; a study needs at least one speed (m/s)", fn));
  for (double x : v)
    if (const std::string e = analysis::speed_rule.check(x, fmt::format("{:g}", x)); !e.empty())
      throw InvalidArgument(fmt::format("{}: speeds: {}", fn, e));
  return v;
}

Study make_study(const Model& pantograph, const py::object& catenaries, const py::object& speeds,
                 const std::vector<std::string>& layouts, const py::object& contact, const py::object& labels,
                 const py::object& search, double lo, double hi, int harmonics, const std::string& name) {
  Study s;
  s.name = name.empty() ? "study" : name;
  s.source = "<python>";
  s.pantograph = pantograph.p;
  std::optional<catenary::Contact> file_contact;
  py::list cats = py::isinstance<py::list>(catenaries) || py::isinstance<py::tuple>(catenaries)
                      ? py::list(catenaries)
                      : py::list(py::make_tuple(catenaries));
  for (auto c : cats) {
    CatenaryArg a = catenary_arg(py::reinterpret_borrow<py::object>(c));
    s.catenaries.push_back(a.catenary);
    if (a.contact && !file_contact) file_contact = a.contact;
  }
  if (s.catenaries.empty()) throw InvalidArgument("study: at least one catenary");
  s.contact = contact_arg(contact, {nullptr, file_contact});
  if (labels.is_none()) {
    for (std::size_t i = 0; i < s.catenaries.size(); ++i) s.catenary_labels.push_back(s.catenaries[i]->describe());
  } else {
    s.catenary_labels = labels.cast<std::vector<std::string>>();
    if (s.catenary_labels.size() != s.catenaries.size()) throw InvalidArgument("study: one label per catenary");
  }
  s.speeds = study_speeds(speeds, "study");
  if (layouts.empty()) throw InvalidArgument("study: at least one layout");
  for (const auto& l : layouts) network::parse(network::find_layout(l) ? network::find_layout(l)->expression : l);
  s.layouts = layouts;
  if (!search.is_none()) s.search = search.cast<numerics::Options>();
  if (!(lo > 0) || !(hi > lo)) throw InvalidArgument(fmt::format("study: expected 0 < lo < hi, got {:g}, {:g}", lo, hi));
  s.lo = lo, s.hi = hi, s.harmonics = harmonics;
  {
    py::gil_scoped_release nogil;
    s.operating_length = optim::operating_lengths(s);
  }
  return s;
}

}  // namespace

namespace {

// A study and its limits and bounds.
void bind_study_file(py::module_& m) {
  py::class_<optim::ContactLimits>(m, "ContactLimits", "Hard limits of a study over every catenary and speed; NaN: none.")
      .def_readonly("mean_min", &optim::ContactLimits::mean_min, "N")
      .def_readonly("mean_max", &optim::ContactLimits::mean_max, "N")
      .def_readonly("loss_max", &optim::ContactLimits::loss_max, "%")
      .def_readonly("statistical_min", &optim::ContactLimits::statistical_min, "N, F_m − 3σ at least")
      .def_readonly("uplift_max", &optim::ContactLimits::uplift_max, "m, support uplift at most")
      .def_property_readonly("acceptance", [](const optim::ContactLimits& l) {
        return std::const_pointer_cast<analysis::AcceptanceCriteria>(l.acceptance);
      }, "an acceptance criteria set as limits, or None")
      .def("any", &optim::ContactLimits::any);
  py::class_<optim::ElementBounds>(m, "ElementBounds", "The physical range [lo, hi] of one kind of element, SI.")
      .def_readonly("lo", &optim::ElementBounds::lo)
      .def_readonly("hi", &optim::ElementBounds::hi);
  py::class_<Study>(m, "Study",
                    "A structure-based suspension design study (spec/07): a pantograph, catenary variants, speeds "
                    "(m/s), candidate layouts and the search options. From a file with load_study, or from Python "
                    "objects with the constructor. Immutable: replace(...) returns a changed copy.")
      .def(py::init(&make_study), py::arg("pantograph"), py::arg("catenaries"), py::arg("speeds"), py::arg("layouts"),
           py::kw_only(), py::arg("contact") = py::none(), py::arg("labels") = py::none(),
           py::arg("search") = py::none(), py::arg("lo") = 0.1, py::arg("hi") = 1e9, py::arg("harmonics") = 8,
           py::arg("name") = "",
           "pantograph: a Model with a pantograph section; catenaries: Catenary, CatenaryFile or file names (the "
           "first file's contact law is the default); speeds in m/s; layouts: names (S2-1) or expressions; search: "
           "SearchOptions; lo, hi: bounds of every free value (SI); harmonics: of the periodic fast path.")
      .def_readonly("name", &Study::name)
      .def_readonly("source", &Study::source)
      .def_readonly("positions", &Study::positions, "the pantographs' positions along the line at t = 0, m")
      .def_property_readonly("pantograph", [](const Study& s) { return make_model(s.pantograph); })
      .def_property_readonly("catenaries", &catenaries_of)
      .def_readonly("catenary_labels", &Study::catenary_labels)
      .def_readonly("contact", &Study::contact)
      .def_property_readonly("speeds", [](const Study& s) { return copy(s.speeds); }, "m/s")
      .def_readonly("layouts", &Study::layouts)
      .def_readonly("search", &Study::search)
      .def_readonly("lo", &Study::lo)
      .def_readonly("hi", &Study::hi)
      .def_readonly("harmonics", &Study::harmonics)
      .def_property_readonly("method", [](const Study& s) { return s.method == Study::Method::Time ? "time" : "periodic"; },
                             "how J2 is computed: 'periodic' (fast path, lumped catenary) or 'time' (time domain)")
      .def_readonly("limits", &Study::limits)
      .def_readonly("bounds", &Study::bounds, "per element kind ('b', 'c', 'k'): its ElementBounds")
      .def_property_readonly("coarse", [](const Study& s) -> py::object {
        return s.coarse ? py::cast(*s.coarse) : py::none();
      }, "multi-fidelity: the coarse study each layout is first searched on, or None")
      .def_readonly("refine", &Study::refine, "multi-fidelity: the refinement's search options")
      .def_readonly("worst_speed_first", &Study::worst_speed_first,
                    "multi-fidelity: the refinement first at the start's worst speed only")
      .def_readonly("refine_candidates", &Study::refine_candidates,
                    "multi-fidelity: the refinement starts from this many best coarse end points")
      .def_readonly("refine_networks", &Study::refine_networks,
                    "multi-fidelity layouts: all (refine: {best_networks: K}): the K best distinct reduced networks refined")
      .def_readonly("refine_screen", &Study::refine_screen,
                    "refine: {screen: N}: the N best distinct reduced networks evaluated here first (0: no screen)")
      .def_property_readonly("refine_optimiser", [](const Study& s) { return numerics::optimiser_name(s.refine_optimiser); },
                             "multi-fidelity: the refinement's optimiser, 'pattern', 'bobyqa' or 'cobyla'")
      .def_property_readonly("all_networks", [](const Study& s) { return s.all.has_value(); },
                             "`layouts: all`: the layouts are every network the study's networks options allow")
      .def_readonly("operating_length", &Study::operating_length,
                    "m, per catenary: the actuator's length at the static equilibrium with the model's suspension")
      .def_readonly("trim", &Study::trim, "`trim:`: each design commissioned once on the reference line (None: the thesis's relaxation under each catenary)")
      .def_readonly("working_range", &Study::working_range, "`working_range:` (m around the reference line's height)")
      .def_property_readonly("objective", [](const Study& s) { return s.objective == Study::Objective::J2 ? "j2" : "sigma_over_mean"; },
                             "'j2' (max σ, N) or 'sigma_over_mean' (max σ/F_m)")
      .def_property_readonly("reference", [](const Study& s) { return std::const_pointer_cast<catenary::Catenary>(s.reference); },
                             "the study's catenary as written: the line designs are commissioned on")
      .def("replace", [](const Study& s, const py::object& speeds, const py::object& layouts, const py::object& search,
                         const py::object& lo, const py::object& hi, const py::object& harmonics, const py::object& name) {
        Study r = s;
        if (!speeds.is_none()) r.speeds = study_speeds(speeds, "Study.replace");
        if (!layouts.is_none()) r.layouts = layouts.cast<std::vector<std::string>>();
        if (r.layouts.empty()) throw InvalidArgument("Study.replace: layouts: empty; a study needs at least one layout");
        if (!search.is_none()) r.search = search.cast<numerics::Options>();
        if (!lo.is_none()) r.lo = lo.cast<double>();
        if (!hi.is_none()) r.hi = hi.cast<double>();
        if (!harmonics.is_none()) r.harmonics = harmonics.cast<int>();
        if (!name.is_none()) r.name = name.cast<std::string>();
        return r;
      }, py::kw_only(), py::arg("speeds") = py::none(), py::arg("layouts") = py::none(), py::arg("search") = py::none(),
           py::arg("lo") = py::none(), py::arg("hi") = py::none(), py::arg("harmonics") = py::none(),
           py::arg("name") = py::none(), "A copy with some settings changed (speeds in m/s).")
      .def("__repr__", [](const Study& s) {
        return fmt::format("Study('{}': {} layouts, {} catenaries, {} speeds)", s.name, s.layouts.size(),
                           s.catenaries.size(), s.speeds.size());
      });
  m.def("load_study", [](const py::object& path) { return io::load_study(path_arg(path)); }, py::arg("path"),
        "Reads a study file (paths in it are relative to the file). ModelError 'file:line: key: ...'.");
  m.def("operating_lengths", [](const Study& s) {
    py::gil_scoped_release nogil;
    return optim::operating_lengths(s);
  }, py::arg("study"), "Per catenary: the actuator's length at the static equilibrium with its own suspension, m.");

}

// What a design costs; a layout's optimum and refinement.
void bind_design_costs(py::module_& m) {
  py::class_<optim::StudyCost>(m, "StudyCost", "J2 of a design: max over catenaries of σ_max over the speeds.")
      .def_readonly("J", &optim::StudyCost::J, "N")
      .def_readonly("speed", &optim::StudyCost::speed, "m/s of the worst σ")
      .def_readonly("mean", &optim::StudyCost::mean, "mean contact force there, N")
      .def_readonly("catenary", &optim::StudyCost::catenary, "index of the worst catenary")
      .def_readonly("unstable_speed", &optim::StudyCost::unstable_speed,
                    "> 0: the periodic solution is unstable at this speed, m/s (J = inf, infeasible)")
      .def("penalised", &optim::StudyCost::penalised,
           "what the search minimises and designs rank by: J within the study's limits, else 1e100 (1 + excess)")
      .def_readonly("excess", &optim::StudyCost::excess, "Σ relative excess of the limits broken")
      .def_readonly("floquet", &optim::StudyCost::floquet, "periodic method: the largest Floquet multiplier |μ| per span")
      .def("settling_spans", &optim::StudyCost::settling_spans,
           "spans for the slowest free vibration to decay to 1 % (0: not computed)")
      .def_readonly("feasible", &optim::StudyCost::feasible, "every limit of the study kept")
      .def_readonly("violation", &optim::StudyCost::violation, "the worst limit broken, in words ('' if feasible)")
      .def_readonly("mean_min", &optim::StudyCost::mean_min, "lowest mean contact force over catenaries and speeds, N")
      .def_readonly("mean_max", &optim::StudyCost::mean_max, "highest mean contact force, N")
      .def_readonly("loss_pct", &optim::StudyCost::loss_pct, "largest contact loss, %")
      .def_readonly("statistical_min", &optim::StudyCost::statistical_min, "lowest F_m − 3σ, N")
      .def_readonly("uplift", &optim::StudyCost::uplift, "largest support uplift (a finite line), m; NaN otherwise")
      .def_readonly("binding", &optim::StudyCost::binding,
                    "with acceptance limits: the criterion with the least relative margin ('sigma at 300 km/h')")
      .def_readonly("binding_margin", &optim::StudyCost::binding_margin, "its margin relative to its limit (< 0: fails)")
      .def_readonly("sigma", &optim::StudyCost::sigma, "N: σ at the worst J (with the objective sigma_over_mean, J = sigma / mean)")
      .def_readonly("commissioning", &optim::StudyCost::commissioning,
                    "a commissioned study (trim:): what commissioning set for this design (Commissioning), else None")
      .def("__repr__", [](const optim::StudyCost& c) {
        return fmt::format("StudyCost(J={:.4f} N at {:.4g} km/h, catenary {}{})", c.J, c.speed * 3.6, c.catenary,
                           c.feasible ? "" : "; outside the limits: " + c.violation);
      })
      .def(py::pickle(  // exact (Dask workers return their layouts' results, docs/distributed.md)
          [](const optim::StudyCost& c) {
            return py::make_tuple(c.J, c.excess, c.feasible, c.violation, c.mean_min, c.mean_max, c.loss_pct,
                                  c.statistical_min, c.uplift, c.speed, c.mean, c.catenary, c.unstable_speed, c.floquet,
                                  c.binding, c.binding_margin, c.sigma, c.commissioning);
          },
          [](const py::tuple& t) {
            optim::StudyCost c;
            c.J = t[0].cast<double>(), c.excess = t[1].cast<double>(), c.feasible = t[2].cast<bool>();
            c.violation = t[3].cast<std::string>(), c.mean_min = t[4].cast<double>(), c.mean_max = t[5].cast<double>();
            c.loss_pct = t[6].cast<double>(), c.statistical_min = t[7].cast<double>(), c.uplift = t[8].cast<double>();
            c.speed = t[9].cast<double>(), c.mean = t[10].cast<double>(), c.catenary = t[11].cast<int>();
            c.unstable_speed = t[12].cast<double>(), c.floquet = t[13].cast<double>();
            c.binding = t[14].cast<std::string>(), c.binding_margin = t[15].cast<double>();
            c.sigma = t[16].cast<double>(), c.commissioning = t[17].cast<std::optional<analysis::Commissioning>>();
            return c;
          }));
  py::class_<optim::LayoutResult>(m, "LayoutResult", "The optimum of one layout.")
      .def_readonly("layout", &optim::LayoutResult::layout)
      .def_readonly("expression", &optim::LayoutResult::expression)
      .def_readonly("values", &optim::LayoutResult::values, "all element values, SI (0 open, inf rigid)")
      .def_readonly("cost", &optim::LayoutResult::cost)
      .def_readonly("evaluations", &optim::LayoutResult::evaluations)
      .def_readonly("unstable", &optim::LayoutResult::unstable, "designs the search refused as unstable")
      .def_readonly("budget_exhausted", &optim::LayoutResult::budget_exhausted, "the search stopped at max_evaluations")
      .def_readonly("stock", &optim::LayoutResult::stock, "the pantograph's own suspension, ranked with the others")
      .def_readonly("at_bounds", &optim::LayoutResult::at_bounds, "free values that ended on the search's limits")
      .def_readonly("coarse_values", &optim::LayoutResult::coarse_values, "multi-fidelity: the coarse study's optimum")
      .def_readonly("coarse_cost", &optim::LayoutResult::coarse_cost, "multi-fidelity: its cost on the coarse study")
      .def_readonly("coarse_here", &optim::LayoutResult::coarse_here, "multi-fidelity: its cost here, before the refinement")
      .def_readonly("coarse_evaluations", &optim::LayoutResult::coarse_evaluations)
      .def_readonly("ends", &optim::LayoutResult::ends, "where each start of the search ended: (values, cost), best first")
      .def_readonly("refined_from", &optim::LayoutResult::refined_from,
                    "multi-fidelity: how many coarse end points the refinement started from")
      .def("network", [](const optim::LayoutResult& r) { return optim::design_network(r.layout, r.values); },
           "the bound network of the optimum")
      .def(py::pickle(
          [](const optim::LayoutResult& r) {
            return py::make_tuple(r.layout, r.expression, r.values, r.cost, r.evaluations, r.unstable, r.budget_exhausted,
                                  r.at_bounds, r.coarse_values, r.coarse_cost, r.coarse_here, r.coarse_evaluations, r.ends,
                                  r.refined_from);
          },
          [](const py::tuple& t) {
            optim::LayoutResult r;
            r.layout = t[0].cast<std::string>(), r.expression = t[1].cast<std::string>();
            r.values = t[2].cast<network::Params>(), r.cost = t[3].cast<optim::StudyCost>();
            r.evaluations = t[4].cast<int>(), r.unstable = t[5].cast<int>(), r.budget_exhausted = t[6].cast<bool>();
            r.at_bounds = t[7].cast<std::vector<std::string>>(), r.coarse_values = t[8].cast<network::Params>();
            r.coarse_cost = t[9].cast<optim::StudyCost>(), r.coarse_here = t[10].cast<optim::StudyCost>();
            r.coarse_evaluations = t[11].cast<int>();
            r.ends = t[12].cast<std::vector<std::pair<network::Params, double>>>(), r.refined_from = t[13].cast<int>();
            return r;
          }))
      .def("__repr__", [](const optim::LayoutResult& r) {
        return fmt::format("LayoutResult('{}', J={:.4f} N, {} evaluations)", r.layout, r.cost.J, r.evaluations);
      });

  m.def("default_suspension", &optim::default_suspension, py::arg("study"),
        "The pantograph's own suspension network (its actuator's), the study's baseline.");
  m.def("evaluate", [](const Study& s, const py::object& net, const py::object& params) {
    const network::Network n = net_arg(net, params);
    return run(py::none(), [&](Call&) { return optim::evaluate(s, n); });
  }, py::arg("study"), py::arg("network"), py::arg("params") = py::none(),
        "J2 of the pantograph with its suspension replaced by `network` (a Network, or a layout/expression with "
        "`params`), by the study's method (the periodic fast path, or the time domain on a finite-element line) "
        "with its limits (optim::evaluate).");
  m.def("evaluate_batch", [](const Study& s, const py::list& designs) {
    // Every design read first (a wrong one raises before any run), as evaluate reads its one.
    std::vector<network::Network> nets;
    std::size_t i = 0;
    for (const py::handle d : designs) {
      const auto design = py::reinterpret_borrow<py::object>(d);
      try {
        if ((py::isinstance<py::tuple>(design) || py::isinstance<py::list>(design)) && py::len(design) == 2) {
          const py::sequence t = design.cast<py::sequence>();
          nets.push_back(net_arg(t[0], t[1]));
        } else {
          nets.push_back(net_arg(design, py::none()));
        }
      } catch (const py::cast_error&) {  // the design's form, not its values (those raise their own errors)
        throw py::type_error("evaluate_batch: designs[" + std::to_string(i) + "] = " +
                             py::repr(design).cast<std::string>() +
                             ": expected a (layout or expression, params) pair, a layout or expression, or a Network");
      }
      ++i;
    }
    const std::vector<optim::BatchEvaluation> got = run(py::none(), [&](Call&) { return optim::evaluate_batch(s, nets); });
    std::vector<optim::StudyCost> costs;
    for (const optim::BatchEvaluation& e : got) costs.push_back(e.get());  // the first failing design's exception
    return costs;
  }, py::arg("study"), py::arg("designs"),
        "evaluate of several designs, each a (layout or expression, params) pair or a Network: the list of "
        "StudyCost that evaluate gives one by one, bit for bit; a time-domain study steps them together on each line "
        "(lanes, optim::evaluate_batch). If a design's evaluation raises, the first such design's exception is "
        "raised (after every design ran); a design that cannot be read raises before any run.");
  m.def("evaluate_time", [](const Study& s, const py::object& net, const py::object& params) {
    const network::Network n = net_arg(net, params);
    return run(py::none(), [&](Call&) { return optim::evaluate_time(s, n); });
  }, py::arg("study"), py::arg("network"), py::arg("params") = py::none(),
        "J2 by the time-domain reference (analysis::sweep per catenary; all cores).");
  m.def("estimated_evaluation_seconds", &optim::estimated_evaluation_seconds, py::arg("study"),
        "A rough wall time (s) of one evaluation of a time-domain study (0 with the periodic fast path).");
  py::class_<optim::StudyEstimate>(m, "StudyEstimate", "A whole study's estimated wall time, every stage (s).")
      .def_readonly("search_evaluations", &optim::StudyEstimate::search_evaluations)
      .def_readonly("refine_evaluations", &optim::StudyEstimate::refine_evaluations)
      .def_readonly("search_seconds", &optim::StudyEstimate::search_seconds)
      .def_readonly("refine_seconds", &optim::StudyEstimate::refine_seconds)
      .def_property_readonly("seconds", &optim::StudyEstimate::seconds);
  m.def("estimated_study_seconds", [](const optim::Study& s) {
    py::gil_scoped_release release;
    return optim::estimated_study_seconds(s);
  }, py::arg("study"),
        "The estimated wall time of a whole study (s), every stage: the search or coarse search (the periodic path: "
        "about 60 evaluations per free value and start, one evaluation of the stock suspension timed) and the "
        "refinements at their limit.");
  m.def("cost_of", &optim::cost_of, py::arg("study"), py::arg("sweeps"), py::arg("commissioning") = py::none(),
        "The study's cost of one SpeedResult list per catenary (its limits applied): J2, penalised, feasible, "
        "violation and the limited quantities.");
  m.def("search_variables", &optim::search_variables, py::arg("study"), py::arg("layout"),
        "The search variables of a layout's free elements (the study's range or its element kind's bounds).");
  m.def("free_parameters", &optim::free_parameters, py::arg("layout"),
        "The element names of a layout that the optimiser varies.");
  py::class_<optim::DesignCost>(m, "DesignCost", "What the search minimises for one design (optim::design_cost).")
      .def(py::init<>())
      .def_readonly("cost", &optim::DesignCost::cost, "J2 penalised by the limits, N (inf: no design)")
      .def_readonly("unstable", &optim::DesignCost::unstable, "a periodic solution was unstable at some speed")
      .def_readonly("J", &optim::DesignCost::J, "J2 alone, N (inf: no design)")
      .def_readonly("excess", &optim::DesignCost::excess, "total relative excess of the limits (0: feasible)")
      .def(py::pickle([](const optim::DesignCost& c) { return py::make_tuple(c.cost, c.unstable, c.J, c.excess); },
                      [](const py::tuple& t) {
                        optim::DesignCost c{t[0].cast<double>(), t[1].cast<bool>()};
                        if (t.size() >= 4) {
                          c.J = t[2].cast<double>(), c.excess = t[3].cast<double>();
                        } else if (c.cost < 1e100) {  // an earlier version's (cost, unstable): J or the penalty
                          c.J = c.cost;
                        } else {
                          c.excess = c.cost / 1e100 - 1;
                        }
                        return c;
                      }))
      .def("__repr__", [](const optim::DesignCost& c) {
        return fmt::format("DesignCost({:.6g}{})", c.cost, c.unstable ? ", unstable" : "");
      });
  m.def("design_cost", [](const Study& s, const std::string& layout, const network::Params& params) {
    return run(py::none(), [&](Call&) { return optim::design_cost(s, layout, params); });
  }, py::arg("study"), py::arg("layout"), py::arg("params"),
        "What the search minimises for one design of a layout: J2 penalised by the limits (inf for a rigid "
        "suspension or no steady state).");
  m.def("optimise_layout", [](const Study& s, const std::string& layout, const py::object& progress,
                              const py::object& batch) {
    optim::DesignBatch designs;
    if (!batch.is_none())  // called from this call's own thread: take the GIL for Python
      designs = [&batch](const std::vector<network::Params>& params) {
        py::gil_scoped_acquire gil;
        const py::object r = batch(py::cast(params));
        return r.cast<std::vector<optim::DesignCost>>();
      };
    return run(progress, [&](Call& call) {
      return optim::optimise_layout(
          s, layout,
          [&](int start, int evals, double best) {
            call.post([start, evals, best](const py::object& cb) { cb(start, evals, best); });
          },
          {}, designs);
    });
  }, py::arg("study"), py::arg("layout"), py::kw_only(), py::arg("progress") = py::none(), py::arg("batch") = py::none(),
        "Optimises one layout's free values by the multi-start pattern search (poll points in parallel). "
        "progress(start, evaluations, best J in N); batch(list of params dicts) -> list of DesignCost: "
        "evaluates a time-domain search's polls elsewhere (inerta.distributed); Ctrl-C cancels.");

  m.def("refine_layout", [](const Study& s, const std::string& layout, const optim::LayoutResult& coarse) {
    return run(py::none(), [&](Call&) { return optim::refine_layout(s, layout, coarse); });
  }, py::arg("study"), py::arg("layout"), py::arg("coarse"),
        "Multi-fidelity: the refinement of a layout on a study with a coarse study, from a coarse LayoutResult "
        "(its values and ends), as optimise_layout does after its coarse search.");

}

// σ and F_m over the speeds; contact histories, cost maps.
void bind_speed_curves(py::module_& m) {
  py::class_<optim::SpeedCurve>(m, "SpeedCurve", "σ and the mean contact force over the speeds under one catenary.")
      .def_readonly("catenary", &optim::SpeedCurve::catenary)
      .def_property_readonly("speed", [](const optim::SpeedCurve& c) { return copy(c.speed); }, "m/s")
      .def_property_readonly("sigma", [](const optim::SpeedCurve& c) { return copy(c.sigma); }, "N")
      .def_property_readonly("mean", [](const optim::SpeedCurve& c) { return copy(c.mean); }, "N");
  m.def("sigma_curves", [](const Study& s, const py::object& net, const py::object& params) {
    const network::Network n = net_arg(net, params);
    return run(py::none(), [&](Call&) { return optim::sigma_curves(s, n); });
  }, py::arg("study"), py::arg("network"), py::arg("params") = py::none(),
        "σ(v) per catenary for a suspension, periodic fast path.");
  m.def("sigma_curves_time", [](const Study& s, const py::object& net, const py::object& params, bool centripetal,
                                const py::object& progress) {
    const network::Network n = net_arg(net, params);
    return run(progress, [&](Call& call) {
      return optim::sigma_curves_time(s, n, centripetal, [&](int done, int total) {
        call.post([done, total](const py::object& cb) { cb(done, total); });
      });
    });
  }, py::arg("study"), py::arg("network"), py::arg("params") = py::none(), py::kw_only(), py::arg("centripetal") = true,
        py::arg("progress") = py::none(),
        "σ(v) per catenary in the time domain, with or without the inerter's centripetal correction; "
        "progress(done, total) over all speeds.");
  m.def("worst_of", &optim::worst_of, py::arg("curves"), "J2 of a set of SpeedCurves.");
  m.def("rig_model", [](const Study& s, const py::object& net, const py::object& params) {
    return make_model(optim::rig_model(s, net_arg(net, params)));
  }, py::arg("study"), py::arg("network"), py::arg("params") = py::none(),
        "The pantograph on its test rig with the suspension `network`, relaxed at the rig's static length.");

  py::class_<optim::ForceHistory>(m, "ForceHistory", "The contact force in time under one catenary at one speed.")
      .def_readonly("catenary", &optim::ForceHistory::catenary)
      .def_readonly("speed", &optim::ForceHistory::speed, "m/s")
      .def_property_readonly("t", [](py::object self) { return view(self.cast<const optim::ForceHistory&>().t, self); }, "s")
      .def_property_readonly("F", [](py::object self) { return view(self.cast<const optim::ForceHistory&>().F, self); }, "N")
      .def_readonly("stats", &optim::ForceHistory::stats);
  m.def("contact_histories", [](const Study& s, const py::object& net, double speed, const py::object& params) {
    const network::Network n = net_arg(net, params);
    return run(py::none(), [&](Call&) { return optim::contact_histories(s, n, speed); });
  }, py::arg("study"), py::arg("network"), py::arg("speed"), py::arg("params") = py::none(),
        "The contact force at `speed` (m/s) under each catenary (time domain, analysed window).");

  py::class_<optim::CostMap>(m, "CostMap", "J2 over a grid of two element values of a layout.")
      .def_readonly("layout", &optim::CostMap::layout)
      .def_readonly("x", &optim::CostMap::x)
      .def_readonly("y", &optim::CostMap::y)
      .def_readonly("values", &optim::CostMap::values, "the other element values")
      .def_property_readonly("xs", [](const optim::CostMap& c) { return copy(c.xs); })
      .def_property_readonly("ys", [](const optim::CostMap& c) { return copy(c.ys); })
      .def_property_readonly("J", [](const optim::CostMap& c) {
        py::array_t<double> a({static_cast<py::ssize_t>(c.xs.size()), static_cast<py::ssize_t>(c.ys.size())});
        std::copy(c.J.begin(), c.J.end(), a.mutable_data());
        return a;
      }, "N, array [i, j] = J2 at (xs[i], ys[j]); NaN where no steady state exists");
  m.def("cost_map", [](const Study& s, const std::string& layout, const network::Params& values, const std::string& x,
                       const py::object& xs, const std::string& y, const py::object& ys, const py::object& progress) {
    const std::vector<double> xv = doubles(xs), yv = doubles(ys);
    return run(progress, [&](Call& call) {
      return optim::cost_map(s, layout, values, x, xv, y, yv, [&](int done, int total) {
        call.post([done, total](const py::object& cb) { cb(done, total); });
      });
    });
  }, py::arg("study"), py::arg("layout"), py::arg("values"), py::arg("x"), py::arg("xs"), py::arg("y"), py::arg("ys"),
        py::kw_only(), py::arg("progress") = py::none(),
        "J2 (periodic fast path) at every (x, y) grid point, in parallel; progress(done, total).");
  m.def("best_with", &optim::best_with, py::arg("results"), py::arg("x"), py::arg("y"),
        "Index of the best result whose layout has free elements x and y, or −1.");
  m.def("has_inerter", &optim::has_inerter, py::arg("network"), "True if the simplified network has an inerter.");

}

// A study's report data and result files.
void bind_report_data(py::module_& m) {
  py::class_<optim::Design>(m, "Design", "A suspension design: a label and its bound network.")
      .def_readonly("label", &optim::Design::label)
      .def_readonly("layout", &optim::Design::layout)
      .def_readonly("values", &optim::Design::values)
      .def_readonly("net", &optim::Design::net);
  py::class_<optim::ReportOptions>(m, "ReportOptions", "What make_report computes.")
      .def(py::init<>())
      .def_readwrite("history_speed", &optim::ReportOptions::history_speed, "m/s")
      .def_readwrite("frf_f", &optim::ReportOptions::frf_f, "Hz; empty: 0.1 … 20 Hz")
      .def_readwrite("frf_output", &optim::ReportOptions::frf_output)
      .def_readwrite("map_size", &optim::ReportOptions::map_size, "map points per axis; 0: no map")
      .def_readwrite("map_b_max", &optim::ReportOptions::map_b_max, "kg")
      .def_readwrite("map_k_max", &optim::ReportOptions::map_k_max, "N/m")
      .def_readwrite("best", &optim::ReportOptions::best, "index in results of the design reported; -1: the lowest cost within the limits");
  py::class_<optim::Report::Centripetal>(m, "ReportCentripetal", "σ(v) with the centripetal correction on and off.")
      .def_readonly("design", &optim::Report::Centripetal::design)
      .def_readonly("on", &optim::Report::Centripetal::on)
      .def_readonly("off", &optim::Report::Centripetal::off)
      .def_readonly("off_simulated", &optim::Report::Centripetal::off_simulated);
  py::class_<optim::MarginRow>(m, "MarginRow",
                               "One acceptance criterion for one design, catenary variant, speed and contact (Report.margins).")
      .def_readonly("design", &optim::MarginRow::design)
      .def_readonly("catenary", &optim::MarginRow::catenary)
      .def_readonly("speed", &optim::MarginRow::speed, "m/s")
      .def_readonly("contact", &optim::MarginRow::contact)
      .def_property_readonly("criterion", [](const optim::MarginRow& r) { return r.result.criterion; })
      .def_property_readonly("value", [](const optim::MarginRow& r) { return r.result.value; })
      .def_property_readonly("limit", [](const optim::MarginRow& r) { return r.result.limit; })
      .def_property_readonly("unit", [](const optim::MarginRow& r) { return r.result.unit; })
      .def_property_readonly("margin", [](const optim::MarginRow& r) { return r.result.margin; }, "in the unit, > 0: passes")
      .def_property_readonly("assessed", [](const optim::MarginRow& r) { return r.result.assessed; })
      .def_property_readonly("passed", [](const optim::MarginRow& r) { return r.result.passed; })
      .def_readonly("relative", &optim::MarginRow::relative, "the margin relative to the limit (< 0: fails)");
  py::class_<optim::Report>(m, "Report", "The data behind a study's figures (optim::make_report).")
      .def_readonly("study", &optim::Report::study)
      .def_readonly("catenaries", &optim::Report::catenaries)
      .def_readonly("baseline", &optim::Report::baseline)
      .def_readonly("best", &optim::Report::best)
      .def_readonly("default_cost", &optim::Report::default_cost)
      .def_readonly("best_cost", &optim::Report::best_cost)
      .def_readonly("sigma_default", &optim::Report::sigma_default)
      .def_readonly("sigma_best", &optim::Report::sigma_best)
      .def_readonly("frf_output", &optim::Report::frf_output)
      .def_readonly("frf_default", &optim::Report::frf_default)
      .def_readonly("frf_best", &optim::Report::frf_best)
      .def_readonly("history_speed", &optim::Report::history_speed)
      .def_readonly("history_default", &optim::Report::history_default)
      .def_readonly("history_best", &optim::Report::history_best)
      .def_readonly("map", &optim::Report::map)
      .def_readonly("map_note", &optim::Report::map_note)
      .def_readonly("map_opt_x", &optim::Report::map_opt_x)
      .def_readonly("map_opt_y", &optim::Report::map_opt_y)
      .def_readonly("map_opt_J", &optim::Report::map_opt_J)
      .def_readonly("centripetal", &optim::Report::centripetal)
      .def_readonly("time_check", &optim::Report::time_check)
      .def_readonly("acceptance", &optim::Report::acceptance, "the acceptance set of the study's limits, or ''")
      .def_readonly("margins", &optim::Report::margins, "every criterion's margin, default and best, per variant and speed");
  m.def("make_report", [](const Study& s, const std::vector<optim::LayoutResult>& results, const py::object& options,
                          const py::object& progress) {
    const optim::ReportOptions o = options.is_none() ? optim::ReportOptions{} : options.cast<optim::ReportOptions>();
    return run(progress, [&](Call& call) {
      return optim::make_report(s, results, o, [&](int step, int steps, const std::string& what, int done, int total) {
        call.post([=](const py::object& cb) { cb(step, steps, what, done, total); });
      });
    });
  }, py::arg("study"), py::arg("results"), py::arg("options") = py::none(), py::kw_only(),
        py::arg("progress") = py::none(),
        "The figures' data for the default suspension and the best layout result (as `inerta optimise --out`); "
        "progress(step, steps, what, done, total).");
  m.def("write_study_report", [](const optim::Report& r, const py::object& dir) {
    return io::write_study_report(r, path_arg(dir));
  }, py::arg("report"), py::arg("dir"), "Writes sigma.csv, frf.csv, contact.csv, j2_map.csv, centripetal.csv, report.json.");
  m.def("write_study_results", [](const py::object& dir, const std::string& study, const optim::StudyCost& def,
                                  const std::vector<optim::LayoutResult>& results) {
    return io::write_study_results(path_arg(dir), study, def, results);
  }, py::arg("dir"), py::arg("study"), py::arg("default_cost"), py::arg("results"),
        "Writes DIR/results.csv and DIR/results.json (as `inerta optimise --out`).");
  m.def("prepare_output_folder", &io::prepare_output_folder, py::arg("dir"), py::arg("owned"), py::arg("force"),
        "Creates a study's output folder; refuses one that holds files unless force, which removes the `owned` "
        "files in it first (io::prepare_output_folder, as `inerta optimise --out`/--force).");
  m.def("study_output_names", &io::study_output_names, "The files `inerta optimise` may write in its --out folder.");
  m.def("study_table", &io::study_table, py::arg("study"), py::arg("default_cost"), py::arg("results"),
        "The table `inerta optimise` prints for named layouts (io::study_table), as text.");
  m.def("study_results_json", [](const std::string& study, const optim::StudyCost& def,
                                 const std::vector<optim::LayoutResult>& results) {
    return py::module_::import("json").attr("loads")(io::json_text(io::study_results_json(study, def, results)));
  }, py::arg("study"), py::arg("default_cost"), py::arg("results"), "The results.json document as a dict.");
}

}  // namespace

void bind_optim(py::module_& m) {
  bind_study_file(m);
  bind_design_costs(m);
  bind_speed_curves(m);
  bind_report_data(m);
}

}  // namespace inerta::python
