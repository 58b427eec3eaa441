// Study files and layout optimisation (spec/07) on a reduced HSX study (one catenary, 5 speeds).
#include "inerta/io/study_file.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/optim/structure_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study {

using namespace inerta;

namespace {
using inerta::testing::write_study;
const std::string kStudy = std::string("name: small\nmodel: ") + INERTA_SOURCE_DIR +
                           "/models/hsx.yaml\ncatenary: " + INERTA_SOURCE_DIR +
                           "/models/catenary.yaml\n"
                           "catenaries: [[catenary.kc0=7000]]\n"
                           "speeds: {from: 100, to: 300, step: 50, unit: kmh}\n"
                           "search: {starts: 2, seed: 7, min_step: 0.05}\n"
                           "layouts: [S2-default, k-c]\n";
}  // namespace

TEST(Study, OptimisingTheDefaultLayoutNeverDoesWorseAndIsDeterministic) {
  optim::Study s = io::load_study(write_study("small_study.yaml", kStudy));
  ASSERT_EQ(s.speeds.size(), 5u);
  EXPECT_NEAR(s.speeds.front(), 100 / 3.6, 1e-12);
  const optim::StudyCost def = optim::evaluate(s, optim::default_suspension(s));
  EXPECT_GT(def.J, 0.5);
  optim::LayoutResult fixed = optim::optimise_layout(s, "S2-default");
  EXPECT_NEAR(fixed.cost.J, def.J, 1e-9);  // S2-default is the model's own suspension
  optim::LayoutResult a = optim::optimise_layout(s, "k-c"), b = optim::optimise_layout(s, "k-c");
  EXPECT_LE(a.cost.J, def.J + 1e-9);  // the free Maxwell element includes the default
  EXPECT_EQ(a.values, b.values);      // same seed, same result
  EXPECT_EQ(a.cost.J, b.cost.J);
}

TEST(Study, FileErrorsNameTheLineAndKey) {
  std::string bad = kStudy;
  bad.replace(bad.find("layouts: [S2-default, k-c]"), 26, "layouts: [S2-default, b-k|c]");
  try {
    io::load_study(write_study("bad_study.yaml", bad));
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_study.yaml:7: 'layouts': 'b-k|c'"), std::string::npos) << e.what();
  }
  std::string unknown = kStudy + "colour: red\n";
  EXPECT_THROW(io::load_study(write_study("bad_study2.yaml", unknown)), ModelError);
}

TEST(Study, CandidateSuspensionsCarryNoStaticLoad) {
  // Relaxed at the operating point, a stiff spring changes the dynamics but not the static contact
  // force: without catenary harmonics the contact force is the default's whatever the spring.
  // (With harmonics the mean may shift: a spring gives the pantograph a static stiffness, so the
  // force follows the span's stiffness variation; the optimiser's table reports that mean.)
  std::string text = kStudy;
  text.replace(text.find("[[catenary.kc0=7000]]"), 21, "[[catenary.kc1=0, catenary.kc2=0, catenary.kc3=0]]");
  optim::Study s = io::load_study(write_study("small_study3.yaml", text));
  const optim::StudyCost def = optim::evaluate(s, optim::default_suspension(s));
  for (double k : {1e4, 3e5, 1e7}) {
    const optim::StudyCost c = optim::evaluate(s, network::resolve("S2-5", {{"k", k}}));
    EXPECT_NEAR(c.mean, def.mean, 1e-6 * def.mean) << "k = " << k;
    EXPECT_LT(c.J, 1e-6);
  }
}

TEST(Study, WrongNodeTypesAreModelErrorsWithTheLine) {
  std::string bad = kStudy;
  bad.replace(bad.find("layouts: [S2-default, k-c]"), 26, "layouts: [{S2-default: 1}]");
  try {
    io::load_study(write_study("bad_study4.yaml", bad));
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_study4.yaml:7: "), std::string::npos) << e.what();
  }
}

TEST(Study, UnstableDesignsAreInfeasibleAndCounted) {
  // Issue 15: with kc1 = 6500 N/m the default HSX's periodic solution is unstable at 380–400 km/h
  // (parametric resonance; its growth in the time domain: tests/analysis/periodic_test.cpp). Such a
  // design costs J = ∞ with the speed named; a search counts the designs it refused, and whatever it
  // returns as finite is stable at every speed.
  std::string text = kStudy;
  text.replace(text.find("[[catenary.kc0=7000]]"), 21, "[[catenary.kc1=6500]]");
  text.replace(text.find("{from: 100, to: 300, step: 50, unit: kmh}"), 41, "{from: 380, to: 400, step: 10, unit: kmh}");
  text.replace(text.find("layouts: [S2-default, k-c]"), 26, "layouts: [S2-1]");
  text += "harmonics: 4\n";
  optim::Study s = io::load_study(write_study("unstable_study.yaml", text));
  const optim::StudyCost def = optim::evaluate(s, optim::default_suspension(s));
  EXPECT_TRUE(std::isinf(def.J));
  EXPECT_NEAR(def.unstable_speed * 3.6, 380, 1e-9);  // the first speed unstable
  s.search.max_evaluations = 60;
  const optim::LayoutResult r = optim::optimise_layout(s, "S2-1");
  EXPECT_GT(r.unstable, 0) << "the search met no unstable design";
  if (std::isfinite(r.cost.J)) {
    const optim::StudyCost again = optim::evaluate(s, network::resolve("S2-1", r.values));
    EXPECT_EQ(again.unstable_speed, 0);
    EXPECT_EQ(again.J, r.cost.J);
  }
  // The structure search carries the count per network (structure.csv's `unstable` column).
  s.layouts = {"k"};
  std::vector<optim::LayoutResult> all;
  const auto entries = optim::optimise_all(s, all);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_GT(entries[0].unstable, 0);
  EXPECT_EQ(entries[0].unstable, all[0].unstable);
}
}  // namespace test_optim_study
