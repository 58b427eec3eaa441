#pragma once
// The HTML reports of the commands (issue 53, docs/cli.md "Reports"): a sweep, a coupled simulation,
// the reduction check, a study. Each is one self-contained page — the verdict first (when criteria
// were given), tables with margins, inline SVG figures, the provenance — and its numbers record.
#include <optional>
#include <string>
#include <vector>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/catenary.hpp"
#include "inerta/network/network.hpp"
#include "inerta/report/provenance.hpp"
#include "inerta/report/record.hpp"

namespace inerta::report {

/// What a run report says about its run besides the results.
struct RunContext {
  Provenance provenance;
  std::string model;  ///< the pantograph model (path and suspension)
  /// The suspension network replacing the model's own (--suspension), drawn as a schematic; none: the model's.
  std::optional<network::Network> suspension;
  std::string line;   ///< the catenary's describe()
  bool kmh = true;    ///< speeds shown in km/h (else m/s)
  const analysis::AcceptanceCriteria* criteria = nullptr;  ///< the verdict's criteria; nullptr: none
  std::vector<analysis::VerdictRow> verdict;              ///< rows of analysis::verdict
};

/// The report of a sweep (analysis::sweep): the verdict table, the EN 50317 statistics per speed,
/// σ(v) and F_m(v) against the criteria's band, the supports' uplift against their limit.
/// `record` receives every number shown.
std::string sweep_report(const RunContext& context, const std::vector<analysis::SpeedResult>& results, Record& record);

/// The report of a coupled simulation: the verdict, each contact's statistics, the contact force along
/// the analysis section with the line's features (masts, droppers, stitch wires, overlaps) marked,
/// the supports' uplift against the limit.
std::string simulate_report(const RunContext& context, const analysis::CoupledSimulation& simulation,
                            const std::vector<catenary::LineFeature>& features, Record& record);

/// The report of `catenary check-reduction`: the direct and the modal solve side by side at each speed
/// (statistics, their difference, the wall times), both verdicts with the criteria that differ, σ(v) of
/// both. `context.verdict` is the direct solve's; `modal_verdict` the modal one's.
std::string reduction_report(const RunContext& context, const std::vector<analysis::RunComparison>& rows,
                             const std::vector<analysis::VerdictRow>& modal_verdict, double tolerance_pct, Record& record);

}  // namespace inerta::report
