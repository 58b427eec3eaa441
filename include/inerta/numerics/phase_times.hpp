#pragma once
// Where a process's time goes, by phase (docs/benchmarks.md "Where a run's time goes"): off unless
// enabled — by the environment's INERTA_TIMINGS=1, which also prints the table on stderr when the
// process ends (docs/cli.md "Environment") — then each timed phase adds its wall time. Phases
// may nest (a nested phase's time is also in its parent's) and may run on several threads at once
// (their times add up, so a parallel phase can exceed the wall time).
#include <chrono>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace inerta::numerics {

class PhaseTimes {
 public:
  /// The process's one record (enabled at first use if INERTA_TIMINGS is 1).
  static PhaseTimes& process();
  void enable(bool on);
  bool enabled() const;
  /// Adds `seconds` (and one call) to `phase`; thread-safe.
  void add(std::string_view phase, double seconds);
  struct Entry {
    std::string phase;
    double seconds = 0;
    long calls = 0;
  };
  /// The phases in the order they were first timed.
  std::vector<Entry> entries() const;
  /// The table INERTA_TIMINGS prints: each phase's seconds, calls and share of `total` seconds.
  std::string table(double total) const;
};

/// Times its own lifetime as `phase` when the process's record is enabled (a static string: no
/// allocation when disabled).
class PhaseTimer {
 public:
  explicit PhaseTimer(const char* phase)
      : phase_(PhaseTimes::process().enabled() ? phase : nullptr), start_(std::chrono::steady_clock::now()) {}
  ~PhaseTimer() {
    if (phase_)
      PhaseTimes::process().add(phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  const char* phase_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace inerta::numerics
