// Contact statistics and speed runs (spec/06 §6.1) on a minimal pantograph: a head on a slider,
// lifted by an actuator (constant force + S2-default network) against a spring.
#include "inerta/analysis/contact_statistics.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_contact_statistics {

using namespace inerta;

namespace {
std::string mini(double lift) {
  return fmt::format(R"(
ground: {{markers: {{G: [0, 0], B: [-1, 5]}}}}
bodies:
  - {{name: head, mass: 10, inertia: 0.1, position: [0, 5], markers: {{top: [0, 0.1]}}}}
joints:
  - {{name: slide, type: prismatic, markers: [ground.G, head.cm], axis: [0, 1]}}
  - {{name: contact, type: driving, body: head, coordinate: y, motion: 0}}
forces:
  - {{name: act, type: actuator, markers: [ground.G, head.cm], constant_force: {}}}
  - {{name: k, type: spring, markers: [ground.B, head.cm], k: 2000}}
outputs:
  - {{name: F_contact, type: reaction, joint: contact, component: y, scale: -1}}
pantograph: {{contact: head.top, rig_joint: contact}}
)",
                     -lift);
}
const std::string kCatenary = std::string(INERTA_SOURCE_DIR) + "/models/catenary.yaml";
}  // namespace

TEST(ContactStatistics, FormulasOnAKnownSeries) {
  std::vector<double> F;
  for (int i = 0; i < 1000; ++i) F.push_back(70 + 10 * std::sin(2 * M_PI * i / 1000.0));
  auto s = analysis::statistics(F);
  EXPECT_NEAR(s.mean, 70, 1e-12);
  EXPECT_NEAR(s.std, 10 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.stat_max, 70 + 30 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.max, 80, 1e-9);
  EXPECT_EQ(s.loss_pct, 0.0);
  F.push_back(0.0);
  EXPECT_NEAR(analysis::statistics(F).loss_pct, 100.0 / 1001, 1e-12);
}

TEST(SpeedRun, NoHarmonicsGiveConstantForceAtAnySpeed) {
  const pantograph::Pantograph panto = io::parse_pantograph(mini(168.1), "mini.yaml");
  io::CatenaryFile c = io::load_catenary(kCatenary, {"catenary.kc1=0", "catenary.kc2=0", "catenary.kc3=0"});
  // σ is the integrator's noise only (σ ≈ 14 N with the harmonics): it shrinks with the tolerance
  // (measured at 50 km/h: 3e-3, 1e-5, 1e-6 N at rtol 1e-6, 1e-7, 1e-8; at 1e-6 it depends on the
  // step sizes' rounding), so the check runs at rtol 1e-8.
  analysis::RunOptions o;
  o.integrator.rtol = 1e-8, o.integrator.atol = 1e-10;
  auto r = analysis::sweep(panto, *c.catenary, c.contact, {50 / 3.6, 150 / 3.6, 300 / 3.6}, o);
  for (const auto& s : r) {
    EXPECT_NEAR(s.stats.mean, 70.0, 0.01);
    EXPECT_LT(s.stats.std, 1e-4);
  }
}

TEST(SpeedRun, StatisticsAreConverged) {
  // Doubling the window changes σ by less than 1 % (issue 4).
  const pantograph::Pantograph panto = io::parse_pantograph(mini(168.1), "mini.yaml");
  io::CatenaryFile c = io::load_catenary(kCatenary);
  for (double v : {80 / 3.6, 250 / 3.6}) {
    auto sys = c.catenary->couple(panto, c.contact, v);
    analysis::RunOptions o;
    analysis::SpeedResult r = analysis::run_speed(*sys, o);
    EXPECT_LT(r.sigma_change, 0.005);
    const long per = static_cast<long>(r.F.size()) / r.spans;
    ASSERT_GE(r.spans, 4);
    auto last = [&](int spans) {
      return analysis::statistics(std::vector<double>(r.F.end() - per * spans, r.F.end())).std;
    };
    EXPECT_GT(last(2), 1.0);
    EXPECT_LT(std::abs(last(4) - last(2)) / last(2), 0.01) << "v = " << v * 3.6 << " km/h";
  }
}

TEST(SpeedRun, BilateralTensionStopsTheRun) {
  // Actuator force reduced below the head's weight: the head is pulled down by the wire.
  const pantograph::Pantograph panto = io::parse_pantograph(mini(90), "mini.yaml");
  io::CatenaryFile c = io::load_catenary(kCatenary);
  auto sys = c.catenary->couple(panto, c.contact, 200 / 3.6);
  analysis::RunOptions o;
  try {
    analysis::run_speed(*sys, o);
    FAIL() << "expected the bilateral sign check to stop the run";
  } catch (const NumericalError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("t = "), std::string::npos) << msg;
    EXPECT_NE(msg.find("< 0"), std::string::npos) << msg;
  }
  // The same with a penalty contact runs and reports contact loss instead.
  c.contact.kind = catenary::Contact::Kind::Penalty;
  auto penalty = c.catenary->couple(panto, c.contact, 200 / 3.6);
  analysis::SpeedResult r = analysis::run_speed(*penalty, o);
  EXPECT_GT(r.stats.loss_pct, 0.0);
}

TEST(Suspension, ReplacingTheActuatorNetworkKeepsItsConstantForce) {
  const pantograph::Pantograph panto = io::parse_pantograph(mini(168.1), "mini.yaml");
  EXPECT_EQ(panto.model.n_states(), 1);  // S2-default
  mbs::Model s = pantograph::with_suspension(panto.model, network::resolve("S2-1", {{"b", 500}, {"c", 100}, {"k", 5e4}}));
  EXPECT_EQ(s.n_states(), 0);
  const auto& a = dynamic_cast<const mbs::Actuator&>(*s.forces[1]);
  EXPECT_EQ(a.params().constant_force, -168.1);
  EXPECT_NEAR(a.realisation().d2, 500, 1e-9);
  EXPECT_THROW(pantograph::with_suspension(panto.model, network::resolve("k", {{"k", INFINITY}})), ModelError);
}

TEST(CatenaryFile, ErrorsNameTheFileLineOrOverride) {
  auto message = [](const std::vector<std::string>& sets) {
    try {
      io::load_catenary(kCatenary, sets);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({"catenary.kc9=1"}).find("unknown key"), std::string::npos);
  EXPECT_NE(message({"catenary.kc0"}).find("expected section.key=value"), std::string::npos);
  EXPECT_NE(message({"catenary.kc0=abc"}).find("not a number"), std::string::npos);
  EXPECT_NE(message({"catenary.kc1=8000"}).find("kc0 must exceed"), std::string::npos);
  EXPECT_EQ(message({"catenary.kc0=5000", "contact.type=penalty"}), "");
  io::CatenaryFile c = io::load_catenary(kCatenary, {"catenary.kc0=5000"});
  ASSERT_NE(c.catenary->point_model(), nullptr);
  EXPECT_EQ(c.catenary->point_model()->k[0], 5000);
  EXPECT_EQ(c.catenary->point_model()->k[1], 2100);
  // A file with a bad key names its line.
  const std::string bad = (inerta::testing::temp_dir() / "bad_catenary.yaml").string();
  std::ofstream(bad) << "catenary:\n  span: 60\n  kc: [7000, 1, 2]\n";
  try {
    io::load_catenary(bad);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ":3: 'kc': expected four coefficients"), std::string::npos) << e.what();
  }
}

TEST(CatenaryFile, WrongNodeTypeIsAModelErrorWithTheLine) {
  const std::string bad = (inerta::testing::temp_dir() / "bad_catenary2.yaml").string();
  std::ofstream(bad) << "catenary:\n  span: 60\n  kc: [7000, 0, 0, 0]\n  mc: [177, 0, 0, 0]\n  cc: [1, 0, 0, 0]\n"
                        "contact:\n  type: [penalty]\n";
  try {
    io::load_catenary(bad);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ":7: "), std::string::npos) << e.what();
  }
}
}  // namespace test_analysis_contact_statistics
