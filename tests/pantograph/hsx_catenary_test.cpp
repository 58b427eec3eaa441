// The HSX pantograph under the lumped catenary (issue 4): constant force without harmonics, the
// bilateral sign check, and penalty against bilateral contact.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_pantograph_hsx_catenary {

using namespace inerta;

namespace {
pantograph::Pantograph hsx() { return io::load_pantograph(inerta::testing::model_path("hsx.yaml")); }
const std::string kCatenary = inerta::testing::model_path("catenary.yaml");
}  // namespace

TEST(HsxCatenary, WithoutHarmonicsTheContactForceIsConstant) {
  io::CatenaryFile c = io::load_catenary(kCatenary, {"catenary.kc1=0", "catenary.kc2=0", "catenary.kc3=0"});
  analysis::RunOptions o;
  auto r = analysis::sweep(hsx(), *c.catenary, c.contact, {60 / 3.6, 200 / 3.6, 300 / 3.6}, o);
  for (const auto& s : r) {
    EXPECT_GT(s.stats.mean, 60.0);
    EXPECT_LT(s.stats.std, 1e-3) << "v = " << s.speed * 3.6 << " km/h";
  }
}

TEST(HsxCatenary, PenaltyAndBilateralAgreeOnSigma) {
  io::CatenaryFile c = io::load_catenary(kCatenary);
  analysis::RunOptions o;
  const std::vector<double> v = {120 / 3.6, 210 / 3.6, 280 / 3.6};
  auto bil = analysis::sweep(hsx(), *c.catenary, c.contact, v, o);
  c.contact.kind = catenary::Contact::Kind::Penalty;  // k_s = 50 kN/m
  auto pen = analysis::sweep(hsx(), *c.catenary, c.contact, v, o);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(pen[i].stats.loss_pct, 0.0);
    EXPECT_GT(bil[i].stats.std, 0.5);
    EXPECT_NEAR(pen[i].stats.std, bil[i].stats.std, 0.02 * bil[i].stats.std) << "v = " << v[i] * 3.6 << " km/h";
  }
}

TEST(HsxCatenary, BilateralSignCheckTriggersWhenTheActuatorIsWeak) {
  // F_c reduced from 5374 N to 4000 N: the frame sinks, the wire must pull the head down.
  std::string text;
  {
    std::ifstream in(inerta::testing::model_path("hsx.yaml"));
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  text.replace(text.find("constant_force: -5374"), 21, "constant_force: -4000");
  const pantograph::Pantograph weak = io::parse_pantograph(text, "hsx-weak.yaml");
  io::CatenaryFile c = io::load_catenary(kCatenary);
  try {
    analysis::sweep(weak, *c.catenary, c.contact, {180 / 3.6}, analysis::RunOptions{});
    FAIL() << "expected the bilateral sign check";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("bilateral contact force"), std::string::npos) << e.what();
  }
}

TEST(HsxCatenary, StatisticsAreConvergedOverTheWindow) {
  // Doubling the statistics window changes σ by less than 1 % (issue 4).
  io::CatenaryFile c = io::load_catenary(kCatenary);
  for (double v : {100 / 3.6, 210 / 3.6}) {
    auto sys = c.catenary->couple(hsx(), c.contact, v);
    analysis::RunOptions o;
    analysis::SpeedResult r = analysis::run_speed(*sys, o);
    const long per = static_cast<long>(r.F.size()) / r.spans;
    auto last = [&](int spans) {
      return analysis::statistics(std::vector<double>(r.F.end() - per * spans, r.F.end())).std;
    };
    ASSERT_GE(r.spans, 4);
    EXPECT_LT(std::abs(last(4) - last(2)) / last(2), 0.01) << "v = " << v * 3.6 << " km/h";
  }
}
}  // namespace test_pantograph_hsx_catenary
