#pragma once
// The HTML report of a study (issue 53): `report.html` in every study's output folder — the
// recommendation first, the ranking with each design's margins, every ranked network drawn as a
// mechanical schematic with its values, σ(v) of the default and the best design, the acceptance
// margins, the provenance.
#include <string>

#include "inerta/optim/study_run.hpp"
#include "inerta/report/provenance.hpp"
#include "inerta/report/record.hpp"

namespace inerta::report {

/// The page of a study's outcome (a J2 study or a model study); `record` receives every number shown.
std::string study_report(const Provenance& provenance, const optim::StudyOutcome& outcome, Record& record);

/// Writes DIR/report.html (a safe output: complete or absent) and returns its path.
std::string write_study_report(const std::string& dir, const Provenance& provenance, const optim::StudyOutcome& outcome);

}  // namespace inerta::report
