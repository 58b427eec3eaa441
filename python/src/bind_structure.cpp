// Every network up to N elements, the positive-real test and network synthesis (network layer), and
// the exhaustive structure search and admittance bound of design studies (optim layer).
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/positive_real.hpp"
#include "inerta/network/synthesis.hpp"
#include "inerta/optim/admittance_search.hpp"
#include "inerta/optim/structure_search.hpp"
#include "inerta/optim/study_run.hpp"
#include "inerta/io/model_study_results.hpp"

namespace inerta::python {

namespace {

// Network enumeration, the positive-real test and synthesis.
void bind_enumeration_synthesis(py::module_& m) {
  using network::Network;
  // ---- enumeration ----
  py::class_<network::ElementCounts>(m, "ElementCounts", "Elements of each type of a network.")
      .def_readonly("elements", &network::ElementCounts::elements)
      .def_readonly("springs", &network::ElementCounts::springs)
      .def_readonly("dampers", &network::ElementCounts::dampers)
      .def_readonly("inerters", &network::ElementCounts::inerters);
  m.def("count_elements", &network::count_elements, py::arg("network"), "Elements of each type (network::count_elements).");
  m.def("static_path", &network::static_path, py::arg("network"),
        "True if springs alone connect the terminals (the network carries a static load).");
  m.def("canonical", &network::canonical, py::arg("network"),
        "The canonical form of a simplified network: groups flattened, same-type neighbours merged (values combined), "
        "members ordered.");
  m.def("structure", &network::structure, py::arg("network"),
        "The canonical structure with bare type letters, e.g. 'k-(c|b)': equal exactly for the same network.");
  m.def("renamed", &network::renamed, py::arg("network"),
        "The network with elements renamed k, c, b (or k1, k2, … when a type occurs more than once).");
  py::enum_<network::StaticLoad>(m, "StaticLoad")
      .value("any", network::StaticLoad::Any)
      .value("required", network::StaticLoad::Required)
      .value("excluded", network::StaticLoad::Excluded);
  py::class_<network::EnumerationOptions>(m, "EnumerationOptions",
                                          "Which networks network::enumerate lists (docs/networks.md).")
      .def(py::init([](int max_elements, bool springs, bool dampers, bool inerters, int max_springs, int max_dampers,
                       int max_inerters, network::StaticLoad static_load) {
             return network::EnumerationOptions{max_elements, springs, dampers, inerters, max_springs, max_dampers,
                                                max_inerters, static_load};
           }),
           py::arg("max_elements") = 4, py::arg("springs") = true, py::arg("dampers") = true, py::arg("inerters") = true,
           py::arg("max_springs") = -1, py::arg("max_dampers") = -1, py::arg("max_inerters") = -1,
           py::arg("static_load") = network::StaticLoad::Any)
      .def_readwrite("max_elements", &network::EnumerationOptions::max_elements)
      .def_readwrite("springs", &network::EnumerationOptions::springs)
      .def_readwrite("dampers", &network::EnumerationOptions::dampers)
      .def_readwrite("inerters", &network::EnumerationOptions::inerters)
      .def_readwrite("max_springs", &network::EnumerationOptions::max_springs, "-1: no limit")
      .def_readwrite("max_dampers", &network::EnumerationOptions::max_dampers, "-1: no limit")
      .def_readwrite("max_inerters", &network::EnumerationOptions::max_inerters, "-1: no limit")
      .def_readwrite("static_load", &network::EnumerationOptions::static_load);
  m.def("enumerate_networks", &network::enumerate, py::arg("options") = network::EnumerationOptions{},
        "Every series–parallel network the options allow, each once, as canonical expressions by size "
        "(network::enumerate).");
  m.def("admittance_leaf", &network::admittance_leaf, py::arg("num"), py::arg("den"),
        "A network of one given admittance Y(s) = num(s)/den(s) (coefficients ascending, SI: N·s/m at s in rad/s).");

  // ---- positive-real test and synthesis ----
  py::class_<network::PrTest>(m, "PrTest", "The positive-real test of an admittance and its certificate.")
      .def_readonly("positive_real", &network::PrTest::positive_real)
      .def_readonly("reason", &network::PrTest::reason, "why not (empty if positive real)")
      .def_readonly("re_min", &network::PrTest::re_min, "min over ω ≥ 0 of Re Y(jω), N·s/m (NaN if rejected earlier)")
      .def_readonly("omega_min", &network::PrTest::omega_min, "where, rad/s (inf: ω → ∞)");
  m.def("positive_real", [](const std::vector<double>& num, const std::vector<double>& den, double rel_tol) {
    return network::positive_real(network::Rational{num, den}, rel_tol);
  }, py::arg("num"), py::arg("den"), py::arg("rel_tol") = 1e-9,
        "Exact positive-real test of Y(s) = num/den (coefficients ascending): Hurwitz roots, jω-axis residues and "
        "min Re Y(jω) over the stationary points, not a frequency grid (docs/synthesis.md).");
  m.def("biquadratic_positive_real", &network::biquadratic_positive_real, py::arg("a0"), py::arg("a1"), py::arg("a2"),
        py::arg("d0"), py::arg("d1"), py::arg("d2"),
        "The closed-form test of Y = (a2 s² + a1 s + a0)/(d2 s² + d1 s + d0), coefficients ≥ 0.");
  py::class_<network::Synthesis>(m, "Synthesis", "A series–parallel network realising an admittance.")
      .def_readonly("network", &network::Synthesis::network)
      .def_readonly("elements", &network::Synthesis::elements)
      .def_readonly("reactive", &network::Synthesis::reactive, "springs + inerters")
      .def_readonly("degree", &network::Synthesis::degree, "McMillan degree of Y")
      .def_readonly("bott_duffin", &network::Synthesis::bott_duffin)
      .def_readonly("minimal_reactive", &network::Synthesis::minimal_reactive, "reactive == degree")
      .def_readonly("method", &network::Synthesis::method);
  m.def("synthesise", [](const std::vector<double>& num, const std::vector<double>& den) {
    return network::synthesise(network::Rational{num, den});
  }, py::arg("num"), py::arg("den"),
        "A spring/damper/inerter network whose admittance is num/den (Foster removals, dampers, Bott–Duffin steps); "
        "NetworkError if it is not positive real.");

}

// The structure search over every network.
void bind_structure_search(py::module_& m) {
  using network::Network;
  // ---- structure search ----
  py::class_<optim::StructureEntry>(m, "StructureEntry", "One network of an exhaustive structure search at its optimum.")
      .def_readonly("expression", &optim::StructureEntry::expression)
      .def_readonly("counts", &optim::StructureEntry::counts)
      .def_readonly("values", &optim::StructureEntry::values, "SI; 0 open, inf rigid")
      .def_readonly("J", &optim::StructureEntry::J, "the objective, the study's unit")
      .def_readonly("cost", &optim::StructureEntry::cost, "what the search minimised")
      .def_readonly("feasible", &optim::StructureEntry::feasible)
      .def_readonly("evaluations", &optim::StructureEntry::evaluations)
      .def_readonly("unstable", &optim::StructureEntry::unstable, "designs refused as unstable (J2 studies, Floquet)")
      .def_readonly("reduced", &optim::StructureEntry::reduced, "the optimum without its open/rigid elements, with values")
      .def_readonly("reduced_structure", &optim::StructureEntry::reduced_structure)
      .def_readonly("reduced_counts", &optim::StructureEntry::reduced_counts)
      .def_readonly("warm_from", &optim::StructureEntry::warm_from, "the sub-network whose optimum was a start")
      .def_readonly("seconds", &optim::StructureEntry::seconds)
      .def("reduces", &optim::StructureEntry::reduces, "True if the reduced network has fewer elements");
  m.def("reduced_design", &optim::reduced_design, py::arg("entry"),
        "An entry's reduced network as a design: (expression, values), or None (no design, open or rigid).");
  m.def("ranking", &optim::ranking, py::arg("entries"), "Indices of the entries from best to worst (feasible first).");
  py::class_<optim::ParetoPoint>(m, "ParetoPoint", "The best reduced network with these many elements and inerters.")
      .def_readonly("elements", &optim::ParetoPoint::elements)
      .def_readonly("inerters", &optim::ParetoPoint::inerters)
      .def_readonly("J", &optim::ParetoPoint::J)
      .def_readonly("network", &optim::ParetoPoint::network)
      .def_readonly("entry", &optim::ParetoPoint::entry)
      .def_readonly("pareto", &optim::ParetoPoint::pareto);
  m.def("pareto_points", &optim::pareto_points, py::arg("entries"), "Performance against complexity (optim::pareto_points).");
  m.def("prune", [](const std::string& expression, const network::Params& values, const py::function& cost, double tolerance) {
    return optim::prune(expression, values, [&](const network::Params& p) { return cost(p).cast<double>(); }, tolerance);
  }, py::arg("expression"), py::arg("values"), py::arg("cost"), py::arg("tolerance") = 1e-4,
        "The values with every element opened or locked whose removal raises cost(values) by at most `tolerance` "
        "relative (called on this thread).");
  auto progress_of = [](Call& call) {
    return [&call](const optim::StructureProgress& p) {
      call.post([done = p.done, total = p.total, elapsed = p.elapsed, left = p.remaining, best = p.best_J](const py::object& cb) {
        cb(done, total, elapsed, left, best);
      });
    };
  };
  m.def("optimise_all", [progress_of](const optim::Study& s, const py::object& progress) {
    return run(progress, [&](Call& call) {
      std::vector<optim::LayoutResult> results;
      auto entries = optim::optimise_all(s, results, progress_of(call));
      return std::make_pair(std::move(entries), std::move(results));
    });
  }, py::arg("study"), py::kw_only(), py::arg("progress") = py::none(),
        "Optimises every layout of a J2 study as an exhaustive structure search (smallest first, warm starts from "
        "sub-networks): (entries, layout results). progress(done, total, elapsed s, remaining s, best J).");
  m.def("optimise_all", [progress_of](const optim::ModelStudy& s, const py::object& progress) {
    return run(progress, [&](Call& call) {
      std::vector<optim::ModelLayoutResult> results;
      auto entries = optim::optimise_all(s, results, progress_of(call));
      return std::make_pair(std::move(entries), std::move(results));
    });
  }, py::arg("study"), py::kw_only(), py::arg("progress") = py::none(),
        "The same for a model study: (entries, model layout results).");
  py::class_<optim::ModelStudyResult>(m, "ModelStudyResult", "A whole model study as `inerta optimise` runs it.")
      .def_readonly("study", &optim::ModelStudyResult::study)
      .def_readonly("baseline", &optim::ModelStudyResult::baseline, "the strut's own network")
      .def_readonly("baseline_cost", &optim::ModelStudyResult::baseline_cost)
      .def_readonly("results", &optim::ModelStudyResult::results, "study order; layouts: all: ranked, best first")
      .def_readonly("entries", &optim::ModelStudyResult::entries, "layouts: all: the structure search's entries")
      .def_readonly("best", &optim::ModelStudyResult::best, "index in results")
      .def_readonly("admittance", &optim::ModelStudyResult::admittance, "the admittance bounds the study asks for")
      .def_readonly("seconds", &optim::ModelStudyResult::seconds, "wall time, s");
  m.def("run_model_study", [](const optim::ModelStudy& s, const py::object& progress) {
    return run(progress, [&](Call& call) {
      // The study engine's events as progress(done, total, best J) after each layout or network.
      struct Events : optim::StudyEvents {
        Call& call;
        int total;
        double best = std::numeric_limits<double>::infinity();
        Events(Call& c, int n) : call(c), total(n) {}
        using optim::StudyEvents::searched;
        void searched(std::size_t l, const optim::ModelLayoutResult& r) override {
          best = std::min(best, r.cost.J);
          call.post([done = static_cast<int>(l) + 1, n = total, b = best](const py::object& cb) { cb(done, n, b); });
        }
        void network(const optim::StructureProgress& q) override {
          call.post([done = q.done, n = q.total, b = q.best_J](const py::object& cb) { cb(done, n, b); });
        }
      } events(call, static_cast<int>(s.layouts.size()));
      return *optim::run_study(s, {}, &events).model;
    });
  }, py::arg("study"), py::kw_only(), py::arg("progress") = py::none(),
        "Runs a model study as `inerta optimise` does (the study engine, optim::run_study: the default, then each layout "
        "warm-started, or the structure search for layouts: all); its ModelStudyResult. progress(done, total, best J) "
        "after each layout or network.");
  m.def("model_study_table", &io::model_study_table, py::arg("result"),
        "The table `inerta optimise` prints for a model study (io::model_study_table), as text.");
  m.def("model_study_figures", [](const optim::ModelStudyResult& r) {
    py::gil_scoped_release release;
    return optim::model_study_figures(r);
  }, py::arg("result"), "The report's FRFs (default and best) and objective map (optim::model_study_figures).");
  py::class_<optim::ModelStudyFigures>(m, "ModelStudyFigures")
      .def_readonly("frf_default", &optim::ModelStudyFigures::frf_default)
      .def_readonly("frf_best", &optim::ModelStudyFigures::frf_best)
      .def_readonly("map", &optim::ModelStudyFigures::map);
  m.def("write_study_results", [](const optim::ModelStudyResult& r, const py::object& dir) {
    optim::ModelStudyFigures fig;
    {
      py::gil_scoped_release release;
      fig = optim::model_study_figures(r);
    }
    return io::write_model_study_results(path_arg(dir), r, fig);
  }, py::arg("result"), py::arg("dir"),
        "Writes a model study's files in DIR, the same as `inerta optimise STUDY --out DIR` (results.csv, "
        "results.json, frf.csv, map.csv, and structure.csv/json, pareto.csv for layouts: all); returns their paths.");

}

// The positive-real admittance bound.
void bind_admittance_bound(py::module_& m) {
  using network::Network;
  // ---- admittance bound ----
  py::class_<optim::AdmittanceResult>(m, "AdmittanceResult", "The best positive-real admittance of a degree, realised.")
      .def_readonly("degree", &optim::AdmittanceResult::degree)
      .def_readonly("y", &optim::AdmittanceResult::y, "Y(s), N·s/m")
      .def_readonly("J", &optim::AdmittanceResult::J)
      .def_readonly("cost", &optim::AdmittanceResult::cost)
      .def_readonly("evaluations", &optim::AdmittanceResult::evaluations)
      .def_readonly("pr", &optim::AdmittanceResult::pr, "the certificate at the optimum")
      .def_readonly("synthesis", &optim::AdmittanceResult::synthesis, "the realisation, or None")
      .def_readonly("synthesis_error", &optim::AdmittanceResult::synthesis_error)
      .def_readonly("J_realised", &optim::AdmittanceResult::J_realised)
      .def_readonly("warm_from", &optim::AdmittanceResult::warm_from);
  m.def("admittance_bound", [](const optim::Study& s, int degree, const Network& warm) {
    return run(py::none(), [&](Call&) { return optim::admittance_bound(s, degree, warm); });
  }, py::arg("study"), py::arg("degree"), py::arg("warm"),
        "The best positive-real admittance of degree ≤ `degree` for a J2 study, started from the bound network `warm`.");
  m.def("admittance_bound", [](const optim::ModelStudy& s, int degree, const Network& warm) {
    return run(py::none(), [&](Call&) { return optim::admittance_bound(s, degree, warm); });
  }, py::arg("study"), py::arg("degree"), py::arg("warm"), "The same for a model study.");
  py::class_<optim::BoundCandidate>(m, "BoundCandidate", "A design an admittance bound starts from and is compared with.")
      .def_readonly("label", &optim::BoundCandidate::label)
      .def_readonly("network", &optim::BoundCandidate::net, "bound")
      .def_readonly("cost", &optim::BoundCandidate::cost)
      .def_readonly("J", &optim::BoundCandidate::J);
  py::class_<optim::AdmittanceBound>(m, "AdmittanceBound", "One degree's bound and the best network of at most that degree.")
      .def_readonly("result", &optim::AdmittanceBound::result)
      .def_readonly("best", &optim::AdmittanceBound::best)
      .def_readonly("seconds", &optim::AdmittanceBound::seconds)
      .def_property_readonly("feasible", &optim::AdmittanceBound::feasible)
      .def_property_readonly("gap_pct", &optim::AdmittanceBound::gap_pct, "100 (best J − J)/J");
  m.def("write_admittance_results", [](const py::object& dir, const std::vector<optim::AdmittanceBound>& bounds, double default_J) {
    return io::write_admittance_results(path_arg(dir), bounds, default_J);
  }, py::arg("dir"), py::arg("bounds"), py::arg("default_J"), "Writes DIR/admittance.csv and admittance.json; returns their paths.");
  m.def("reactive_elements", &optim::reactive_elements, py::arg("network"),
        "Springs + inerters of a bound network (the degree of a given admittance).");
  m.def("write_structure_results", [](const py::object& dir, const std::string& study, const std::string& objective,
                                      const std::string& unit, double default_J, const std::vector<optim::StructureEntry>& e) {
    return io::write_structure_results(path_arg(dir), study, objective, unit, default_J, e);
  }, py::arg("dir"), py::arg("study"), py::arg("objective"), py::arg("unit"), py::arg("default_J"), py::arg("entries"),
        "Writes structure.csv, structure.json and pareto.csv in dir (docs/networks.md); returns their paths.");
  m.def("structure_results_json", [](const std::string& study, const std::string& objective, const std::string& unit,
                                     double default_J, const std::vector<optim::StructureEntry>& e) {
    return py::module_::import("json").attr("loads")(io::json_text(io::structure_results_json(study, objective, unit, default_J, e)));
  }, py::arg("study"), py::arg("objective"), py::arg("unit"), py::arg("default_J"), py::arg("entries"),
        "The structure.json document as a dict.");
}

}  // namespace

void bind_structure(py::module_& m) {
  bind_enumeration_synthesis(m);
  bind_structure_search(m);
  bind_admittance_bound(m);
}

}  // namespace inerta::python
