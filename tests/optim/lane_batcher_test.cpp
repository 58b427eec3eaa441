// LaneBatcher (issue 50): searches on threads of their own get exactly what evaluating their designs
// alone gives, in batches that mix the searches' designs; a search that stops early or a design that
// fails never blocks or changes the others.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "inerta/network/layouts.hpp"
#include "inerta/optim/lane_batcher.hpp"

namespace test_optim_lane_batcher {

using namespace inerta;
using optim::BatchEvaluation;
using optim::LaneBatcher;

// A stand-in evaluation: J from the spring's value; a negative one fails for that design alone.
BatchEvaluation stand_in(const network::Network& n) {
  BatchEvaluation e;
  const double k = n.value;
  if (k < 0) e.error = std::make_exception_ptr(std::runtime_error("no static equilibrium"));
  else e.cost.J = 2 * k + 1;
  return e;
}
network::Network spring(double k) {
  network::Network n;
  n.kind = network::Network::Kind::Spring, n.value = k;
  return n;
}

TEST(LaneBatcher, EachSearchGetsItsOwnDesignsCostsFromBatchesThatMixTheSearches) {
  std::vector<std::size_t> sizes;
  LaneBatcher b(3, [&](const std::vector<network::Network>& ds) {
    sizes.push_back(ds.size());  // one batch at a time: no lock needed
    std::vector<BatchEvaluation> out;
    for (const auto& d : ds) out.push_back(stand_in(d));
    return out;
  });
  std::atomic<int> wrong{0};
  auto search = [&](int s, int asks) {
    for (int i = 0; i < asks; ++i) {
      const double k = 10.0 * i + s;
      const std::vector<BatchEvaluation> got = b.ask({spring(k), spring(k + 0.5)});
      if (got.size() != 2 || got[0].get().J != 2 * k + 1 || got[1].get().J != 2 * k + 2) ++wrong;
    }
    b.done();  // the searches stop after different numbers of asks
  };
  std::thread t0(search, 0, 5), t1(search, 1, 9), t2(search, 2, 2);
  t0.join(), t1.join(), t2.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(b.designs(), 32);
  EXPECT_EQ(b.batches(), 9);  // while all three ask: 2 batches of 3 searches, then of 2 until the 5th, then 1
  EXPECT_EQ(sizes.front(), 6u);
}

TEST(LaneBatcher, ADesignThatFailsFailsAloneAndAFailedBatchFailsEach) {
  LaneBatcher b(2, [&](const std::vector<network::Network>& ds) {
    std::vector<BatchEvaluation> out;
    for (const auto& d : ds) out.push_back(stand_in(d));
    return out;
  });
  double good = 0;
  bool failed = false;
  std::thread a([&] {
    good = b.ask({spring(4.0)}).at(0).get().J;
    b.done();
  });
  std::thread c([&] {
    failed = static_cast<bool>(b.ask({spring(-1.0)}).at(0).error);
    b.done();
  });
  a.join(), c.join();
  EXPECT_EQ(good, 9.0);
  EXPECT_TRUE(failed);
  LaneBatcher broken(1, [](const std::vector<network::Network>&) -> std::vector<BatchEvaluation> {
    throw std::runtime_error("the cluster is gone");
  });
  const auto got = broken.ask({spring(1.0), spring(2.0)});
  ASSERT_EQ(got.size(), 2u);
  EXPECT_THROW((void)got[1].get(), std::runtime_error);
  EXPECT_THROW(LaneBatcher(0, {}), std::invalid_argument);
}

}  // namespace test_optim_lane_batcher
