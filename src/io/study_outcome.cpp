#include "inerta/io/study_outcome.hpp"

#include <filesystem>

#include "inerta/error.hpp"
#include "inerta/io/files.hpp"
#include "inerta/io/model_study_results.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/io/study_report.hpp"
#include "inerta/io/study_results.hpp"

namespace inerta::io {

std::vector<std::string> write_study_outcome(const std::string& dir, const optim::StudyOutcome& o) {
  if (o.model)
    return write_model_study_results(dir, *o.model, o.model_figures ? *o.model_figures : optim::model_study_figures(*o.model));
  if (!o.study) throw InvalidArgument("write_study_outcome: the outcome has no study");
  const optim::Study& study = *o.study;
  std::filesystem::create_directories(dir);
  std::vector<std::string> files;
  auto add = [&](const std::vector<std::string>& more) { files.insert(files.end(), more.begin(), more.end()); };
  if (study.all) {  // multi-fidelity: the refined networks; else the time-domain re-checks
    const std::string name = study.coarse ? "/refined.csv" : "/recheck.csv";
    write_text_file(dir + name, study.coarse ? o.refined_csv() : o.recheck_csv());
    files.push_back(dir + name);
  }
  if (!o.screened.empty()) {
    write_text_file(dir + "/screened.csv", o.screened_csv());
    files.push_back(dir + "/screened.csv");
  }
  if (!o.admittance.empty()) add(write_admittance_results(dir, o.admittance, o.default_cost.J));
  if (study.all)  // a multi-fidelity study's entries are of its coarse study: compared with the default there
    add(write_structure_results(dir, study.name, "J2", "N", study.coarse ? o.coarse_default_cost.J : o.default_cost.J,
                                o.entries));
  add(write_study_results(dir, study.name, o.default_cost, o.results));
  if (o.report) add(write_study_report(*o.report, dir));
  return files;
}

}  // namespace inerta::io
