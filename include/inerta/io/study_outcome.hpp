#pragma once
// Every file of a study's outcome (optim::run_study) in one folder — what `inerta optimise --out DIR`,
// `inerta.optimise(study, out=DIR)` and the Dask driver write, identical but for wall-clock columns
// (structure.csv's seconds). J2 study: recheck.csv (layouts: all; refined.csv with a coarse study: the refined
// networks), admittance.csv/json (admittance:),
// structure.csv/json and pareto.csv (layouts: all), results.csv/json, and with the report's data
// sigma.csv, frf.csv, contact.csv, j2_map.csv, centripetal.csv, report.json. Model study: the files of
// io::write_model_study_results.
#include <string>
#include <vector>

#include "inerta/optim/study_run.hpp"

namespace inerta::io {

/// Writes the files in DIR (created if needed); returns their paths in the order written.
std::vector<std::string> write_study_outcome(const std::string& dir, const optim::StudyOutcome& outcome);

}  // namespace inerta::io
