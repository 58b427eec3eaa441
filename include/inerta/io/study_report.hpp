#pragma once
// Files of `inerta optimise --out DIR`: the figures' data computed by optim::make_report, as CSV
// and JSON for scripts/plot-study (docs/cli.md#inerta-optimise lists their columns).
#include <string>
#include <vector>

#include "inerta/optim/report.hpp"

namespace inerta::io {

/// Writes DIR/sigma.csv, frf.csv, contact.csv, j2_map.csv (if there is a map), centripetal.csv and
/// report.json. Returns the files written.
std::vector<std::string> write_study_report(const optim::Report& report, const std::string& dir);

}  // namespace inerta::io
