// The process's phase times (numerics/phase_times.hpp).
#include "inerta/numerics/phase_times.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace inerta::numerics {

namespace {
std::atomic<bool> g_enabled{false};
std::mutex g_mutex;
std::vector<PhaseTimes::Entry> g_entries;
}  // namespace

namespace {
// With INERTA_TIMINGS=1: the table on stderr at exit, against the time since the program started
// (this object's construction, at static initialisation).
struct AtExit {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  bool print = false;
  ~AtExit() {
    if (!print) return;
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fflush(stdout);
    std::fputs(PhaseTimes::process().table(total).c_str(), stderr);
  }
} g_at_exit;
}  // namespace

PhaseTimes& PhaseTimes::process() {
  static PhaseTimes p = [] {
    PhaseTimes q;
    const char* v = std::getenv("INERTA_TIMINGS");
    if (v && std::strcmp(v, "1") == 0) q.enable(true), g_at_exit.print = true;
    return q;
  }();
  return p;
}

void PhaseTimes::enable(bool on) { g_enabled.store(on, std::memory_order_relaxed); }

bool PhaseTimes::enabled() const { return g_enabled.load(std::memory_order_relaxed); }

void PhaseTimes::add(std::string_view phase, double seconds) {
  const std::lock_guard lock(g_mutex);
  for (Entry& e : g_entries)
    if (e.phase == phase) {
      e.seconds += seconds, ++e.calls;
      return;
    }
  g_entries.push_back({std::string(phase), seconds, 1});
}

std::vector<PhaseTimes::Entry> PhaseTimes::entries() const {
  const std::lock_guard lock(g_mutex);
  return g_entries;
}

std::string PhaseTimes::table(double total) const {
  std::string out = fmt::format("timings (INERTA_TIMINGS; nested phases are also in their parents, parallel ones add up):\n"
                                "  {:<40} {:>9} {:>7} {:>6}\n", "phase", "seconds", "calls", "share");
  for (const Entry& e : entries())
    out += fmt::format("  {:<40} {:>9.4f} {:>7} {:>5.1f}%\n", e.phase, e.seconds, e.calls, total > 0 ? 100 * e.seconds / total : 0.0);
  out += fmt::format("  {:<40} {:>9.4f}\n", "process (from start to exit)", total);
  return out;
}

}  // namespace inerta::numerics
