// The study engine (optim/study_run.hpp): run_study with progress events, the executor interface that
// inerta.distributed implements with a Dask client, the outcome and its files.
#include <cmath>

#include <pybind11/functional.h>

#include "common.hpp"
#include "inerta/io/study_outcome.hpp"
#include "inerta/optim/study_run.hpp"

namespace inerta::python {

namespace {

using Searching = optim::StudyExecutor::Searching;
template <class Result>
using Done = optim::StudyExecutor::Done<Result>;

// A StudyExecutor written in Python (inerta.distributed's Dask executor): search(study, tasks, done, searching)
// and check(study, tasks) for either kind of study.
class PyStudyExecutor : public optim::StudyExecutor {
 public:
  std::vector<optim::LayoutResult> search(const optim::Study& study, const std::vector<optim::SearchTask>& tasks,
                                          const Done<optim::LayoutResult>& done, const Searching& searching) override {
    PYBIND11_OVERRIDE_PURE(std::vector<optim::LayoutResult>, optim::StudyExecutor, search, study, tasks, done, searching);
  }
  std::vector<optim::ModelLayoutResult> search(const optim::ModelStudy& study, const std::vector<optim::SearchTask>& tasks,
                                               const Done<optim::ModelLayoutResult>& done, const Searching& searching) override {
    PYBIND11_OVERRIDE_PURE(std::vector<optim::ModelLayoutResult>, optim::StudyExecutor, search, study, tasks, done, searching);
  }
  std::vector<optim::CheckResult> check(const optim::Study& study, const std::vector<optim::CheckTask>& tasks) override {
    PYBIND11_OVERRIDE_PURE(std::vector<optim::CheckResult>, optim::StudyExecutor, check, study, tasks);
  }
  std::vector<optim::ModelCheckResult> check(const optim::ModelStudy& study, const std::vector<optim::CheckTask>& tasks) override {
    PYBIND11_OVERRIDE_PURE(std::vector<optim::ModelCheckResult>, optim::StudyExecutor, check, study, tasks);
  }
};

// The engine's events as progress(event, *values) on the calling thread (Call queues the others).
class PyEvents : public optim::StudyEvents {
 public:
  explicit PyEvents(Call& call) : call_(call) {}
  using optim::StudyEvents::searched;
  void searching(std::size_t i, int start, int evals, double best) override {
    call_.post([=](const py::object& cb) { cb("searching", i, start, evals, best); });
  }
  void searched(std::size_t i, const optim::LayoutResult& r) override {
    call_.post([i, r](const py::object& cb) { cb("searched", i, r); });
  }
  void searched(std::size_t i, const optim::ModelLayoutResult& r) override {
    call_.post([i, r](const py::object& cb) { cb("searched", i, r); });
  }
  void network(const optim::StructureProgress& p) override {
    call_.post([done = p.done, total = p.total, b = p.best_J](const py::object& cb) { cb("network", done, total, b); });
  }
  void screening(const std::vector<std::size_t>& entries) override {
    call_.post([entries](const py::object& cb) { cb("screening", entries); });
  }
  void refining(const std::vector<std::size_t>& entries) override {
    call_.post([entries](const py::object& cb) { cb("refining", entries); });
  }
  void refined(std::size_t k, const optim::LayoutResult& r) override {
    call_.post([k, r](const py::object& cb) { cb("refined", k, r); });
  }
  void searches_done(const optim::StudyOutcome& o) override {
    call_.post([o](const py::object& cb) { cb("searches_done", o); });
  }
  void bound(const optim::AdmittanceBound& b) override {
    call_.post([b](const py::object& cb) { cb("bound", b); });
  }
  void report(int step, int steps, const std::string& what, int done, int total) override {
    call_.post([=](const py::object& cb) { cb("report", step, steps, what, done, total); });
  }

 private:
  Call& call_;
};

}  // namespace

// The units of a study's work and where they run (the executor).
static void bind_study_tasks(py::module_& m) {
  py::class_<optim::SearchTask>(m, "SearchTask", "One search of a study: a layout and further starts (optim::SearchTask).")
      .def(py::init([](std::string layout, std::vector<network::Params> warm, bool network, bool coarse, bool refine) {
             return optim::SearchTask{std::move(layout), std::move(warm), network, coarse, refine};
           }),
           py::arg("layout"), py::arg("warm") = std::vector<network::Params>{}, py::arg("network") = false,
           py::arg("coarse") = false, py::arg("refine") = false)
      .def_readonly("layout", &optim::SearchTask::layout)
      .def_readonly("warm", &optim::SearchTask::warm, "further starts: complete value sets")
      .def_readonly("network", &optim::SearchTask::network, "a network of layouts: all (grid start, pruned optimum)")
      .def_readonly("coarse", &optim::SearchTask::coarse, "multi-fidelity layouts: all: searched on the study's coarse study")
      .def_readonly("refine", &optim::SearchTask::refine,
                    "multi-fidelity layouts: all: refined on this study from warm[0] (a coarse optimum)")
      .def(py::pickle([](const optim::SearchTask& t) { return py::make_tuple(t.layout, t.warm, t.network, t.coarse, t.refine); },
                      [](const py::tuple& t) {
                        return optim::SearchTask{t[0].cast<std::string>(), t[1].cast<std::vector<network::Params>>(),
                                                 t[2].cast<bool>(), t[3].cast<bool>(), t[4].cast<bool>()};
                      }));
  py::class_<optim::CheckTask>(m, "CheckTask",
                               "One design to evaluate: the default suspension (layout '') or a layout's values, by the "
                               "study's method or (time) in the time domain.")
      .def(py::init([](std::string layout, network::Params values, bool time, double above, int catenary, double speed) {
             return optim::CheckTask{std::move(layout), std::move(values), time, optim::EarlyStop{above, catenary, speed}};
           }),
           py::arg("layout") = "", py::arg("values") = network::Params{}, py::arg("time") = false,
           py::arg("stop_above") = INFINITY, py::arg("stop_catenary") = -1, py::arg("stop_speed") = NAN)
      .def_readonly("layout", &optim::CheckTask::layout)
      .def_readonly("values", &optim::CheckTask::values)
      .def_readonly("time", &optim::CheckTask::time)
      .def_property_readonly("stop_above", [](const optim::CheckTask& t) { return t.stop.above; },
                             "a feasible incumbent's J: a time-domain evaluation stops once the design ranks behind it (inf: none)")
      .def_property_readonly("stop_catenary", [](const optim::CheckTask& t) { return t.stop.catenary; },
                             "the incumbent's worst run, run first: its catenary (index; -1 unknown)")
      .def_property_readonly("stop_speed", [](const optim::CheckTask& t) { return t.stop.speed; }, "and its speed, m/s")
      .def(py::pickle([](const optim::CheckTask& t) {
                        return py::make_tuple(t.layout, t.values, t.time, t.stop.above, t.stop.catenary, t.stop.speed);
                      },
                      [](const py::tuple& t) {
                        optim::CheckTask task{t[0].cast<std::string>(), t[1].cast<network::Params>(), t[2].cast<bool>(), {}};
                        if (t.size() > 5)  // a checkpoint written before the early stops has three
                          task.stop = {t[3].cast<double>(), t[4].cast<int>(), t[5].cast<double>()};
                        return task;
                      }));
  py::class_<optim::CheckResult>(m, "CheckResult", "A design's cost, or why its evaluation failed.")
      .def_readonly("cost", &optim::CheckResult::cost)
      .def_readonly("failure", &optim::CheckResult::failure, "a numerical failure's message, or ''")
      .def_readonly("stopped", &optim::CheckResult::stopped, "stopped early behind the incumbent: cost.J is a lower bound")
      .def(py::pickle([](const optim::CheckResult& r) { return py::make_tuple(r.cost, r.failure, r.stopped); },
                      [](const py::tuple& t) {
                        // a checkpoint written before the early stops: (cost, failure)
                        return optim::CheckResult{t[0].cast<optim::StudyCost>(), t[1].cast<std::string>(),
                                                  t.size() > 2 && t[2].cast<bool>()};
                      }));
  m.def("run_search", [](const optim::Study& s, const optim::SearchTask& task, const py::object& batch) {
    optim::DesignBatch designs;
    if (!batch.is_none())
      designs = [&batch](const std::vector<network::Params>& params) {
        py::gil_scoped_acquire gil;
        return batch(py::cast(params)).cast<std::vector<optim::DesignCost>>();
      };
    return run(py::none(), [&](Call&) { return optim::run_search(s, task, {}, designs); });
  }, py::arg("study"), py::arg("task"), py::kw_only(), py::arg("batch") = py::none(),
        "What a search task computes (optim::run_search): optimise_layout with the task's warm starts; a network of "
        "layouts: all pruned as optimise_all does. batch: as optimise_layout's.");
  m.def("run_check", [](const optim::Study& s, const optim::CheckTask& task) {
    return run(py::none(), [&](Call&) { return optim::run_check(s, task); });
  }, py::arg("study"), py::arg("task"), "What a check task computes: evaluate or evaluate_time of its design.");
  py::class_<optim::ModelCheckResult>(m, "ModelCheckResult", "A model study's design cost, or why its evaluation failed.")
      .def_readonly("cost", &optim::ModelCheckResult::cost)
      .def_readonly("failure", &optim::ModelCheckResult::failure, "a numerical failure's message, or ''")
      .def(py::pickle([](const optim::ModelCheckResult& r) { return py::make_tuple(r.cost, r.failure); },
                      [](const py::tuple& t) {
                        return optim::ModelCheckResult{t[0].cast<optim::ModelCost>(), t[1].cast<std::string>()};
                      }));
  m.def("run_search", [](const optim::ModelStudy& s, const optim::SearchTask& task) {
    return run(py::none(), [&](Call&) { return optim::run_search(s, task); });
  }, py::arg("study"), py::arg("task"),
        "The same for a model study: optimise_layout with the task's warm starts; a network of layouts: all pruned.");
  m.def("run_check", [](const optim::ModelStudy& s, const optim::CheckTask& task) {
    return run(py::none(), [&](Call&) { return optim::run_check(s, task); });
  }, py::arg("study"), py::arg("task"), "The same for a model study: evaluate of its design.");
  m.def("best_design", &optim::best_design, py::arg("penalised"),
        "The one rule for a study's best design: the index of the first smallest penalised cost.");

  py::class_<optim::StudyExecutor, PyStudyExecutor>(
      m, "StudyExecutor",
      "Where a study's evaluations run (subclass it: search(study, tasks, done, searching) -> [LayoutResult] (a model "
      "study: [ModelLayoutResult]), calling done(i, result) as each finishes; check(study, tasks) -> [CheckResult] "
      "([ModelCheckResult]); study is a Study or a ModelStudy); inerta.distributed's runs them on Dask.")
      .def(py::init<>())
      .def("search",
           py::overload_cast<const optim::Study&, const std::vector<optim::SearchTask>&, const Done<optim::LayoutResult>&,
                             const Searching&>(&optim::StudyExecutor::search),
           py::arg("study"), py::arg("tasks"), py::arg("done"), py::arg("searching"))
      .def("search",
           py::overload_cast<const optim::ModelStudy&, const std::vector<optim::SearchTask>&,
                             const Done<optim::ModelLayoutResult>&, const Searching&>(&optim::StudyExecutor::search),
           py::arg("study"), py::arg("tasks"), py::arg("done"), py::arg("searching"))
      .def("check",
           py::overload_cast<const optim::Study&, const std::vector<optim::CheckTask>&>(&optim::StudyExecutor::check),
           py::arg("study"), py::arg("tasks"))
      .def("check",
           py::overload_cast<const optim::ModelStudy&, const std::vector<optim::CheckTask>&>(&optim::StudyExecutor::check),
           py::arg("study"), py::arg("tasks"));
  py::class_<optim::LocalExecutor, optim::StudyExecutor>(m, "LocalExecutor", "This process (the default of run_study).")
      .def(py::init<>());

}

void bind_study_run(py::module_& m) {
  bind_study_tasks(m);
  py::class_<optim::StudyOptions>(m, "StudyOptions", "What run_study computes besides the searches.")
      .def(py::init([](bool report, const py::object& ro, int rechecks, bool early_stops) {
             optim::StudyOptions o;
             o.report = report;
             if (!ro.is_none()) o.report_options = ro.cast<optim::ReportOptions>();
             o.rechecks = rechecks;
             o.early_stops = early_stops;
             return o;
           }),
           py::kw_only(), py::arg("report") = false, py::arg("report_options") = py::none(), py::arg("rechecks") = 5,
           py::arg("early_stops") = true)
      .def_readwrite("report", &optim::StudyOptions::report, "compute the report's data (what out= writes)")
      .def_readwrite("report_options", &optim::StudyOptions::report_options)
      .def_readwrite("rechecks", &optim::StudyOptions::rechecks, "layouts: all: designs re-checked in the time domain")
      .def_readwrite("early_stops", &optim::StudyOptions::early_stops,
                     "stop the re-checks and a screen's evaluations that can no longer win (exact; stopped: J a lower bound)");
  py::class_<optim::Recheck>(m, "Recheck", "A layouts: all design re-checked in the time domain.")
      .def_readonly("entry", &optim::Recheck::entry, "index in StudyOutcome.entries")
      .def_readonly("periodic_rank", &optim::Recheck::periodic_rank)
      .def_readonly("time", &optim::Recheck::time, "its J2 in the time domain")
      .def_readonly("failure", &optim::Recheck::failure)
      .def_readonly("settling_spans", &optim::Recheck::settling_spans)
      .def_readonly("stopped", &optim::Recheck::stopped, "stopped early behind the best: time.J is a lower bound");
  py::class_<optim::Refinement>(m, "Refinement", "Multi-fidelity layouts: all: where a refined network came from.")
      .def_readonly("entry", &optim::Refinement::entry, "index in StudyOutcome.entries (the coarse search's)")
      .def_readonly("coarse_rank", &optim::Refinement::coarse_rank,
                    "its rank among the refined (with a screen: the screened) by the coarse search")
      .def_readonly("screen_rank", &optim::Refinement::screen_rank, "with a screen: its rank by the screen's cost; else 0");
  py::class_<optim::Screened>(m, "Screened", "Multi-fidelity layouts: all, refine: {screen: N}: a network evaluated at its coarse optimum.")
      .def_readonly("entry", &optim::Screened::entry, "index in StudyOutcome.entries")
      .def_readonly("coarse_rank", &optim::Screened::coarse_rank, "its rank among the screened by the coarse search")
      .def_readonly("cost", &optim::Screened::cost, "on this study at its coarse optimum")
      .def_readonly("failure", &optim::Screened::failure)
      .def_readonly("refined", &optim::Screened::refined)
      .def_readonly("stopped", &optim::Screened::stopped, "stopped early behind the refined: cost.J is a lower bound");
  py::class_<optim::BestDesign>(m, "BestDesign", "The design a study recommends.")
      .def_readonly("index", &optim::BestDesign::index, "in StudyOutcome.results (a model study: model.results)")
      .def_readonly("layout", &optim::BestDesign::layout)
      .def_readonly("expression", &optim::BestDesign::expression)
      .def_readonly("values", &optim::BestDesign::values, "every element value, SI (0 open, inf rigid)")
      .def_readonly("network", &optim::BestDesign::net, "bound")
      .def_readonly("J", &optim::BestDesign::J, "a J2 study's verified J2 (time domain), N; a model study's J")
      .def_readonly("J2", &optim::BestDesign::J, "= J")
      .def_readonly("feasible", &optim::BestDesign::feasible)
      .def_readonly("verified", &optim::BestDesign::verified, "layouts: all: the best of the time-domain re-checks")
      .def("__repr__", [](const optim::BestDesign& b) {
        return "BestDesign('" + b.layout + "', " + b.expression + ", J=" + std::to_string(b.J) + ")";
      });
  py::class_<optim::StudyOutcome>(m, "StudyOutcome", "Everything a study computed (optim::run_study).")
      .def_readonly("study", &optim::StudyOutcome::study, "a J2 study, or None")
      .def_readonly("model", &optim::StudyOutcome::model, "a model study's ModelStudyResult, or None")
      .def_readonly("baseline", &optim::StudyOutcome::baseline, "the default suspension")
      .def_readonly("default_cost", &optim::StudyOutcome::default_cost)
      .def_readonly("coarse_default_cost", &optim::StudyOutcome::coarse_default_cost,
                    "multi-fidelity layouts: all: the default on the coarse study (the entries' baseline)")
      .def_readonly("results", &optim::StudyOutcome::results,
                    "study order; layouts: all: ranked, best first (with a coarse study: the refined networks)")
      .def_readonly("entries", &optim::StudyOutcome::entries)
      .def_readonly("order", &optim::StudyOutcome::order,
                    "ranking(entries); without a coarse study results[k] is entries[order[k]]")
      .def_readonly("refinements", &optim::StudyOutcome::refinements,
                    "multi-fidelity layouts: all: results[k] refined from entries[refinements[k].entry]")
      .def_readonly("rechecks", &optim::StudyOutcome::rechecks, "ranked by the time-domain J2")
      .def_readonly("admittance", &optim::StudyOutcome::admittance)
      .def_readonly("report", &optim::StudyOutcome::report)
      .def_readonly("model_figures", &optim::StudyOutcome::model_figures)
      .def_readonly("time_check", &optim::StudyOutcome::time_check, "the best design's J2 in the time domain")
      .def_readonly("best", &optim::StudyOutcome::best)
      .def_readonly("seconds", &optim::StudyOutcome::seconds, "wall time of the default and the searches, s")
      .def_readonly("rank_agreement", &optim::StudyOutcome::rank_agreement,
                    "multi-fidelity layouts: all: Spearman's ρ of the order the refined networks were chosen in (the screen's, "
                    "else the coarse search's) and this study's ranking of them")
      .def_readonly("coarse_rank_agreement", &optim::StudyOutcome::coarse_rank_agreement,
                    "with a screen: Spearman's ρ of the coarse search's own order of the refined networks and this study's")
      .def_readonly("screened", &optim::StudyOutcome::screened, "refine: {screen: N}: by their cost here, best first")
      .def_readonly("stock_best", &optim::StudyOutcome::stock_best,
                    "the recommendation is the stock suspension (a commissioned study: nothing ranked ahead of it)")
      .def("recheck_csv", &optim::StudyOutcome::recheck_csv)
      .def("refined_csv", &optim::StudyOutcome::refined_csv)
      .def("screened_csv", &optim::StudyOutcome::screened_csv);
  m.def("run_study", [](const py::object& study, const py::object& options, const py::object& progress,
                        optim::StudyExecutor* executor) {
    // Arguments checked by name (issue 52): not "Unable to cast" or an error from inside the study.
    if (!py::isinstance<optim::ModelStudy>(study) && !py::isinstance<optim::Study>(study))
      throw py::type_error(fmt::format("run_study: study: expected a Study or a ModelStudy (inerta.load_study(path), "
                                       "or inerta.optimise(path)), got {}",
                                       py::str(py::type::of(study).attr("__name__")).cast<std::string>()));
    if (!options.is_none() && !py::isinstance<optim::StudyOptions>(options))
      throw py::type_error(fmt::format("run_study: options: expected a StudyOptions, got {}",
                                       py::str(py::type::of(options).attr("__name__")).cast<std::string>()));
    if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
      throw py::type_error(fmt::format("run_study: progress: expected a callable progress(event, *values), got {}",
                                       py::str(py::type::of(progress).attr("__name__")).cast<std::string>()));
    const optim::StudyOptions o = options.is_none() ? optim::StudyOptions{} : options.cast<optim::StudyOptions>();
    if (py::isinstance<optim::ModelStudy>(study)) {
      const auto& s = study.cast<const optim::ModelStudy&>();
      return run(progress, [&](Call& call) {
        PyEvents events(call);
        return optim::run_study(s, o, &events, executor);
      });
    }
    const auto& s = study.cast<const optim::Study&>();
    return run(progress, [&](Call& call) {
      PyEvents events(call);
      return optim::run_study(s, o, &events, executor);
    });
  }, py::arg("study"), py::arg("options") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
        py::arg("executor") = nullptr,
        "A whole study in one call (optim::run_study): a Study or a ModelStudy. progress(event, *values): "
        "('searching', i, start, evaluations, best), ('searched', i, result), ('network', done, total, best J), ('screening', [entry]), ('refining', [entry]), ('refined', k, result), "
        "('searches_done', outcome), ('bound', AdmittanceBound), ('report', step, steps, what, done, total). "
        "executor: a StudyExecutor (default: this process). inerta.optimise is the convenient form.");
  m.def("write_study_outcome", [](const optim::StudyOutcome& o, const std::string& dir) {
    return io::write_study_outcome(dir, o);
  }, py::arg("outcome"), py::arg("dir"), "Every file of the outcome in dir, as `inerta optimise --out dir`; returns the paths.");
}

}  // namespace inerta::python
