// What the layout optimiser's cost turns into +∞ (spec/07): a rigid suspension and numerical
// failures (NumericalError) only. Any other error — a model the fast path cannot handle, or a bug —
// leaves optimise_layout at the first evaluation instead of being read as a bad design.
#include <gtest/gtest.h>

#include <cmath>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/optim/study.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_errors {

using namespace inerta;

namespace {
const std::string kStudy = std::string("name: small\nmodel: ") + INERTA_SOURCE_DIR +
                           "/models/hsx.yaml\ncatenary: " + INERTA_SOURCE_DIR +
                           "/models/catenary.yaml\n"
                           "speeds: {from: 150, to: 250, step: 50, unit: kmh}\n"
                           "search: {starts: 1, seed: 3, min_step: 0.1, lo: 1e5, hi: 1.1e5}\n"
                           "layouts: [k]\n";
}  // namespace

TEST(StudyErrors, ARigidSuspensionCostsInfinityWithoutCatchingModelErrors) {
  const optim::Study s = io::load_study(inerta::testing::write_study("study_errors.yaml", kStudy));
  // The model refuses a rigid suspension (ModelError) ...
  EXPECT_THROW(optim::evaluate(s, network::resolve("k", {{"k", INFINITY}})), ModelError);
  // ... which the search over "k" meets and scores +∞ explicitly: with the values' range
  // [1e5, 1.1e5] N/m its box is log10 k ∈ [4, 6.04], so the first poll (±1 decade from the centre)
  // evaluates k = ∞ (rigid) and k = 0 (open).
  int polls = 0;
  const optim::LayoutResult r = optim::optimise_layout(s, "k", [&](int, int, double) { ++polls; });
  EXPECT_GT(polls, 0);
  EXPECT_TRUE(std::isfinite(r.cost.J));
  EXPECT_FALSE(std::isinf(r.values.at("k")));
}

TEST(StudyErrors, AnErrorThatIsNotNumericalStopsTheSearchAtOnce) {
  optim::Study s = io::load_study(inerta::testing::write_study("study_errors2.yaml", kStudy));
  // Mass harmonics: the periodic fast path refuses the catenary with a ModelError at every
  // evaluation. Read as +∞ the search would run to its end; it must stop at the first point.
  catenary::LumpedCatenary with_mass_harmonic = *s.catenaries[0]->point_model();
  with_mass_harmonic.m[1] = 1.0;
  s.catenaries[0] = std::make_shared<catenary::Lumped>(with_mass_harmonic);
  int polls = 0;
  EXPECT_THROW(optim::optimise_layout(s, "b|k", [&](int, int, double) { ++polls; }), ModelError);
  EXPECT_EQ(polls, 0);
}

TEST(StudyErrors, ALayoutTwiceOrAsAMappingIsAnErrorAtItsLine) {
  // Issue 38: [S2-5, S2-5] optimised the same layout twice; a mapping gave yaml-cpp's "bad conversion".
  auto error_of = [](const std::string& layouts) -> std::string {
    std::string text = kStudy;
    text.replace(text.find("layouts: [k]"), 12, "layouts: " + layouts);
    try {
      io::load_study(inerta::testing::write_study("study_errors3.yaml", text));
    } catch (const ModelError& e) {
      return e.what();
    }
    return "";
  };
  std::string e = error_of("[S2-5, S2-5]");
  EXPECT_NE(e.find(":6: 'layouts': 'S2-5' is given twice"), std::string::npos) << e;
  e = error_of("[{S2-5: 1}]");
  EXPECT_NE(e.find(":6: 'layouts': expected a layout name"), std::string::npos) << e;
  e = error_of("[]");
  EXPECT_NE(e.find(":6: 'layouts': expected a list of layouts"), std::string::npos) << e;
  // Without layouts at all: the key named at the study's line, not yaml-cpp's ":0: invalid node".
  std::string text = kStudy;
  text.erase(text.find("layouts: [k]\n"));
  try {
    io::load_study(inerta::testing::write_study("study_errors4.yaml", text));
    ADD_FAILURE() << "accepted";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find(":1: 'layouts': missing; expected a list of layouts"), std::string::npos)
        << err.what();
  }
}

}  // namespace test_optim_study_errors
