// LaneBatcher (issue 50): searches on threads of their own get exactly what evaluating their designs
// alone gives, in batches that mix the searches' designs; a search that stops early or fails never
// blocks the others.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "inerta/optim/lane_batcher.hpp"

namespace test_optim_lane_batcher {

using namespace inerta;
using optim::LaneBatcher;
using optim::StudyCost;

// A stand-in evaluation: J from the design's values; "bad" throws for that design alone.
StudyCost cost_of_design(const LaneBatcher::Design& d) {
  if (d.layout == "bad") throw std::runtime_error("no static equilibrium");
  StudyCost c;
  c.J = std::sqrt(d.params.at("k")) + static_cast<double>(d.layout.size());
  return c;
}

TEST(LaneBatcher, EachSearchGetsItsOwnDesignsCostsFromBatchesThatMixTheSearches) {
  std::vector<std::size_t> sizes;
  LaneBatcher b(3, [&](const std::vector<LaneBatcher::Design>& ds) {
    sizes.push_back(ds.size());  // one batch at a time: no lock needed
    std::vector<LaneBatcher::Outcome<StudyCost>> out(ds.size());
    for (std::size_t i = 0; i < ds.size(); ++i) try {
        out[i].value = cost_of_design(ds[i]);
      } catch (...) {
        out[i].error = std::current_exception();
      }
    return out;
  });
  std::atomic<int> wrong{0};
  auto search = [&](int s, int asks) {
    for (int i = 0; i < asks; ++i) {
      const std::vector<LaneBatcher::Design> ds = {{std::string(static_cast<std::size_t>(s + 1), 'k'), {{"k", 10.0 * i + s}}}};
      if (b.ask(ds).at(0).J != cost_of_design(ds[0]).J) ++wrong;
    }
    b.done();  // the searches stop after different numbers of asks
  };
  std::thread t0(search, 0, 5), t1(search, 1, 9), t2(search, 2, 2);
  t0.join(), t1.join(), t2.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(b.designs(), 16);
  EXPECT_EQ(b.batches(), 9);  // while all three ask: 2 batches of 3, then of 2 until the 5th, then alone
  EXPECT_EQ(sizes.front(), 3u);
}

TEST(LaneBatcher, ADesignThatFailsFailsItsSearchAloneAndAFailedBatchFailsEach) {
  LaneBatcher b(2, [&](const std::vector<LaneBatcher::Design>& ds) {
    std::vector<LaneBatcher::Outcome<StudyCost>> out(ds.size());
    for (std::size_t i = 0; i < ds.size(); ++i) try {
        out[i].value = cost_of_design(ds[i]);
      } catch (...) {
        out[i].error = std::current_exception();
      }
    return out;
  });
  double good = 0;
  bool threw = false;
  std::thread a([&] {
    good = b.ask({{"k", {{"k", 4.0}}}}).at(0).J;
    b.done();
  });
  std::thread c([&] {
    try {
      (void)b.ask({{"bad", {{"k", 1.0}}}});
    } catch (const std::runtime_error&) {
      threw = true;
    }
    b.done();
  });
  a.join(), c.join();
  EXPECT_EQ(good, 3.0);
  EXPECT_TRUE(threw);
  LaneBatcher broken(1, [](const std::vector<LaneBatcher::Design>&) -> std::vector<LaneBatcher::Outcome<StudyCost>> {
    throw std::runtime_error("the cluster is gone");
  });
  EXPECT_THROW((void)broken.ask({{"k", {{"k", 1.0}}}}), std::runtime_error);
  EXPECT_THROW(LaneBatcher(0, {}), std::invalid_argument);
}

}  // namespace test_optim_lane_batcher
