#pragma once
// The cost guard (issue 38): before any work whose estimated wall time (Catenary::estimated_seconds,
// estimated_sweep_seconds, optim::estimated_evaluation_seconds) exceeds cost_note_seconds, the CLI
// and Python say so first; simulate, sweep and the catenary commands refuse an estimate above their
// limit (--max-seconds, Python max_seconds=; default_max_seconds) with a CostLimitError that says how
// to proceed.
#include <string>

#include "inerta/error.hpp"

namespace inerta::analysis {

/// Estimates above this many seconds are announced before the work starts.
inline constexpr double cost_note_seconds = 10;
/// The default limit of simulate, sweep and the catenary commands (--max-seconds, max_seconds=).
inline constexpr double default_max_seconds = 600;
/// --max-seconds / max_seconds=: > 0 s, at most 1e9 s (≈ 32 years; `inf` is refused, give a number).
inline constexpr NumberRule max_seconds_rule{1e-3, 1e9, "> 0 s, at most 1e9 s"};

/// A refused estimate: bad input in the sense of the exit codes (the CLI's exit 2).
struct CostLimitError : ModelError {
  using ModelError::ModelError;
};

/// "about 12 s", "about 37 min", "about 2.5 h", "about 3.1 days".
std::string format_duration(double seconds);

/// The note printed before work estimated above cost_note_seconds, else "": "note: <what> is
/// estimated at about 37 min on a 2-core machine (docs/benchmarks.md \"Run-time estimate\"); Ctrl-C
/// stops it and leaves no partial output file". `what`: "this run", "this sweep of 21 speeds".
std::string cost_note(double seconds, const std::string& what);

/// CostLimitError if `seconds` > max_seconds: "<what> is estimated at about 3.1 h on a 2-core
/// machine, above the limit of 600 s; <raise> to run it anyway, or make it cheaper (<cheaper>)".
/// `raise`: how to raise the limit ("give --max-seconds 12000", "pass max_seconds=12000").
void check_cost(double seconds, double max_seconds, const std::string& what, const std::string& raise,
                const std::string& cheaper);

/// CostLimitError if `bytes` exceed 80 % of this machine's physical memory: "<what> needs about
/// 31 GB of memory (...), more than this machine's 23 GB; make it cheaper (<cheaper>)".
void check_memory(double bytes, const std::string& what, const std::string& cheaper);

}  // namespace inerta::analysis
