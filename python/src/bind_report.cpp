// Reports (report/*.hpp): the program's build, reading a report's numbers record and comparing two.
// The reports themselves are written by the CLI's --report (docs/cli.md "Reports").
#include "common.hpp"

#include "inerta/io/files.hpp"
#include "inerta/report/provenance.hpp"
#include "inerta/report/record.hpp"
#include "inerta/report/study_report.hpp"

namespace inerta::python {

void bind_report(py::module_& m) {
  using namespace report;
  py::class_<BuildInfo>(m, "BuildInfo", "The program as built: version, git commit, whether the tree was modified.")
      .def_readonly("version", &BuildInfo::version)
      .def_readonly("commit", &BuildInfo::commit)
      .def_readonly("modified", &BuildInfo::modified)
      .def("__repr__", [](const BuildInfo& b) {
        return fmt::format("BuildInfo(version='{}', commit='{}', modified={})", b.version, b.commit, b.modified ? "True" : "False");
      });
  m.def("build_info", &build_info, py::return_value_policy::copy, "The version and git commit this module was built from.");
  py::class_<InputFile>(m, "InputFile", "An input file of a report: path, role, SHA-256 of the bytes read, size.")
      .def_readonly("path", &InputFile::path)
      .def_readonly("what", &InputFile::what)
      .def_readonly("sha256", &InputFile::sha256)
      .def_readonly("bytes", &InputFile::bytes);
  py::class_<Record>(m, "Record", "The numbers record of a report (HTML), with its provenance.")
      .def_readonly("command", &Record::command)
      .def_readonly("verdict", &Record::verdict)
      .def_property_readonly("numbers", [](const Record& r) {
        py::dict d;
        for (const auto& [k, v] : r.numbers) d[py::str(k)] = v;
        return d;
      }, "{key: value} of every number the report shows (exact)")
      .def_property_readonly("argv", [](const Record& r) { return r.provenance.argv; })
      .def_property_readonly("cwd", [](const Record& r) { return r.provenance.cwd; })
      .def_property_readonly("date", [](const Record& r) { return r.provenance.date; })
      .def_property_readonly("commit", [](const Record& r) { return r.provenance.build.commit; })
      .def_property_readonly("inputs", [](const Record& r) { return r.provenance.inputs; });
  m.def("read_report", [](const std::string& path) { return read_record(io::read_input_text(path, "report"), path); },
        py::arg("path"), "The numbers record and provenance of a report written by the CLI's --report (ModelError if it is none).");
  py::class_<Difference>(m, "Difference", "A number that differs between two reports.")
      .def_readonly("key", &Difference::key)
      .def_readonly("reported", &Difference::reported)
      .def_readonly("now", &Difference::now)
      .def_readonly("missing", &Difference::missing);
  m.def("compare_reports", &compare, py::arg("a"), py::arg("b"), py::arg("rtol") = 0.0,
        "The numbers of b that differ from a's (or are only in one), key by key; equal within rtol relative.");
  record_inputs();  // the module's inputs (models, lines, studies) with their SHA-256, for a study's report.html
  m.def("write_study_report", [](const optim::StudyOutcome& o, const std::string& dir) {
    const py::list argv = py::module_::import("sys").attr("argv");
    std::vector<std::string> args{"python3"};
    for (const auto& a : argv) args.push_back(py::str(a));
    return write_study_report(dir, current_provenance(args), o);
  }, py::arg("outcome"), py::arg("dir"),
        "Writes DIR/report.html of a study's outcome (as `inerta optimise --out` does): the recommendation, the ranking with "
        "margins, the networks drawn, σ(v), the provenance (this Python's command line and every input read); returns its path.");
  m.def("sha256", &sha256_hex, py::arg("data"), "SHA-256 of a str (UTF-8 bytes) as lowercase hex, as reports give their inputs'.");
}

}  // namespace inerta::python
