#include "inerta/analysis/cost_guard.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cmath>

namespace inerta::analysis {

std::string format_duration(double s) {
  if (!std::isfinite(s)) return "without end";
  if (s < 90) return fmt::format("about {:.0f} s", s);
  if (s < 5400) return fmt::format("about {:.0f} min", s / 60);
  if (s < 2 * 86400) return fmt::format("about {:.1f} h", s / 3600);
  return fmt::format("about {:.3g} days", s / 86400);
}

std::string cost_note(double seconds, const std::string& what) {
  if (!(seconds > cost_note_seconds)) return {};
  return fmt::format(
      "note: {} is estimated at {} on a 2-core machine (docs/benchmarks.md \"Run-time estimate\"); Ctrl-C stops it "
      "and leaves no partial output file",
      what, format_duration(seconds));
}

void check_cost(double seconds, double max_seconds, const std::string& what, const std::string& raise,
                const std::string& cheaper) {
  if (!(seconds > max_seconds)) return;
  const double needed = std::ceil(seconds * 1.5 / 60) * 60;  // room for the estimate's error
  throw CostLimitError(fmt::format("{} is estimated at {} on a 2-core machine, above the limit of {:g} s; {} {:.0f} "
                                   "to run it anyway{}",
                                   what, format_duration(seconds), max_seconds, raise, needed,
                                   cheaper.empty() ? "" : ", or make it cheaper (" + cheaper + ")"));
}

void check_memory(double bytes, const std::string& what, const std::string& cheaper) {
  const double physical = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (!(physical > 0) || !(bytes > 0.8 * physical)) return;
  throw CostLimitError(fmt::format("{} needs about {:.3g} GB of memory (the line's matrices and its windows' modes), "
                                   "more than this machine's {:.3g} GB; make it cheaper ({})",
                                   what, bytes / 1e9, physical / 1e9, cheaper));
}

}  // namespace inerta::analysis
