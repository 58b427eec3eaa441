// The periodic fast path (harmonic balance on the linearised pantograph + LTP catenary) against
// the time-domain reference (issue 5): σ within 2 % at every speed of a coarse grid.
#include "inerta/analysis/periodic.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "inerta/io/catenary_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "support/run.hpp"

using namespace inerta;

namespace {
void compare(const pantograph::Pantograph& panto) {
  io::CatenaryFile c = io::load_catenary(inerta::testing::model_path("catenary.yaml"));
  const std::vector<double> v = {70 / 3.6, 140 / 3.6, 210 / 3.6, 280 / 3.6};
  auto time = analysis::sweep(panto, *c.catenary, c.contact, v, analysis::RunOptions{});
  auto fast = analysis::sweep_periodic(panto, *c.catenary, c.contact, v, 8);
  for (std::size_t i = 0; i < v.size(); ++i) {
    SCOPED_TRACE("v = " + std::to_string(v[i] * 3.6) + " km/h");
    EXPECT_GT(time[i].stats.std, 0.5);
    EXPECT_NEAR(fast[i].stats.std, time[i].stats.std, 0.02 * time[i].stats.std);
    EXPECT_NEAR(fast[i].stats.mean, time[i].stats.mean, 0.01 * time[i].stats.mean);
  }
}
}  // namespace

TEST(Periodic, AgreesWithTimeDomainForTheDefaultSuspension) {
  compare(io::load_pantograph(inerta::testing::model_path("hsx.yaml")));
}

TEST(Periodic, AgreesWithTimeDomainForAnInerterLayout) {
  pantograph::Pantograph hsx = io::load_pantograph(inerta::testing::model_path("hsx.yaml"));
  hsx.model = pantograph::with_suspension(hsx.model, network::resolve("S2-1", {{"b", 500}, {"c", 100}, {"k", 5e4}}));
  compare(hsx);
}

TEST(Periodic, NoHarmonicsNoFluctuation) {
  io::CatenaryFile c = io::load_catenary(inerta::testing::model_path("catenary.yaml"),
                                         {"catenary.kc1=0", "catenary.kc2=0", "catenary.kc3=0"});
  auto r = analysis::sweep_periodic(io::load_pantograph(inerta::testing::model_path("hsx.yaml")), *c.catenary, c.contact,
                                    {100 / 3.6, 250 / 3.6});
  for (const auto& x : r) EXPECT_LT(x.stats.std, 1e-9);
}
