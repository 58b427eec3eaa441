// The process's phase times (numerics/phase_times.hpp): off by default, then each timer adds its wall
// time and one call under its phase, phases listed in the order first timed.
#include "inerta/numerics/phase_times.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace inerta::numerics {
namespace {

const PhaseTimes::Entry* find(const std::vector<PhaseTimes::Entry>& es, const std::string& name) {
  for (const auto& e : es)
    if (e.phase == name) return &e;
  return nullptr;
}

TEST(PhaseTimes, DisabledTimersRecordNothing) {
  PhaseTimes& p = PhaseTimes::process();
  p.enable(false);
  { const PhaseTimer t("test: disabled phase"); }
  EXPECT_EQ(find(p.entries(), "test: disabled phase"), nullptr);
}

TEST(PhaseTimes, EnabledTimersAddTheirWallTimeAndCalls) {
  PhaseTimes& p = PhaseTimes::process();
  p.enable(true);
  for (int i = 0; i < 2; ++i) {
    const PhaseTimer t("test: sleeping phase");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  { const PhaseTimer t("test: second phase"); }
  p.enable(false);
  const auto es = p.entries();
  const PhaseTimes::Entry* a = find(es, "test: sleeping phase");
  const PhaseTimes::Entry* b = find(es, "test: second phase");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(a->calls, 2);
  EXPECT_GE(a->seconds, 0.040);  // two sleeps of 20 ms at least
  EXPECT_LT(a - es.data(), b - es.data());  // in the order first timed
  const std::string table = p.table(a->seconds * 2);
  EXPECT_NE(table.find("test: sleeping phase"), std::string::npos);
  EXPECT_NE(table.find("50.0%"), std::string::npos);  // its share of a total twice its time
}

}  // namespace
}  // namespace inerta::numerics
