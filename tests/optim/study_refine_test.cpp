// The multi-fidelity refinement's optimiser (issue 36): `refine: {optimiser: bobyqa | cobyla |
// pattern}` parses (COBYLA the default), an unknown name is a file error (file, line, key; the CLI exits 2), and on a
// small cheap study (periodic fast path on the lumped line, coarse then fine speeds) BOBYQA and
// COBYLA reach the pattern search's optimum.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_refine {

using namespace inerta;
using inerta::testing::write_study;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
// Lines 1–8: the refinement's options are on line 8.
std::string study_text(const std::string& refine) {
  return "name: small refine\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
         "/models/catenary.yaml\n"
         "speeds: {from: 100, to: 300, step: 50, unit: kmh}\n"
         "search: {starts: 1, seed: 7, min_step: 0.1}\n"
         "layouts: [S2-5, S2-4]\n"
         "coarse: {speeds: {from: 100, to: 300, step: 100, unit: kmh}}\n"
         "refine: {" + refine + "}\n";
}
}  // namespace

TEST(StudyRefine, TheOptimiserKeyParsesAndDefaultsToCobyla) {
  // COBYLA by default (it refined the FE-line study best: docs/studies.md); a Study built in code
  // keeps the pattern search.
  const optim::Study p = io::load_study(write_study("refine_default.yaml", study_text("max_evaluations: 5")));
  EXPECT_EQ(p.refine_optimiser, numerics::Optimiser::Cobyla);
  EXPECT_EQ(optim::Study{}.refine_optimiser, numerics::Optimiser::Pattern);
  for (const auto& [name, which] : {std::pair{"bobyqa", numerics::Optimiser::Bobyqa},
                                    std::pair{"cobyla", numerics::Optimiser::Cobyla},
                                    std::pair{"pattern", numerics::Optimiser::Pattern}}) {
    const optim::Study s = io::load_study(write_study("refine_named.yaml", study_text(std::string("optimiser: ") + name)));
    EXPECT_EQ(s.refine_optimiser, which) << name;
  }
}

TEST(StudyRefine, AnUnknownOptimiserNamesFileLineAndKeyAndTheCliExitsTwo) {
  const std::string path = write_study("bad_refine.yaml", study_text("optimiser: newuoa"));
  try {
    io::load_study(path);
    ADD_FAILURE() << "accepted an unknown optimiser";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad_refine.yaml:8: 'optimiser': unknown optimiser; expected pattern, bobyqa or cobyla"),
              std::string::npos)
        << what;
  }
  const std::string err = path + ".stderr";
  const int status = std::system((std::string(INERTA_CLI) + " optimise '" + path + "' > /dev/null 2> '" + err + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::stringstream text;
  text << std::ifstream(err).rdbuf();
  EXPECT_NE(text.str().find("bad_refine.yaml:8: 'optimiser'"), std::string::npos) << text.str();
}

TEST(StudyRefine, BobyqaAndCobylaReachThePatternSearchsOptimumOnACheapStudy) {
  const std::string opts = "initial_step: 0.3, min_step: 0.01, max_evaluations: 60";
  const optim::Study pattern = io::load_study(write_study("refine_pattern.yaml", study_text(opts + ", optimiser: pattern")));
  for (const std::string layout : {"S2-5", "S2-4"}) {
    const optim::LayoutResult p = optim::optimise_layout(pattern, layout);
    ASSERT_TRUE(std::isfinite(p.cost.J)) << layout;
    for (const char* name : {"bobyqa", "cobyla"}) {
      SCOPED_TRACE(layout + " " + name);
      const optim::Study s =
          io::load_study(write_study("refine_nlopt.yaml", study_text(opts + ", optimiser: " + std::string(name))));
      const optim::LayoutResult r = optim::optimise_layout(s, layout);
      EXPECT_EQ(r.coarse_values, p.coarse_values);  // the same start
      EXPECT_LE(r.cost.penalised(), r.coarse_here.penalised());  // never worse than its start
      EXPECT_NEAR(r.cost.J, p.cost.J, 0.01 * p.cost.J);
      EXPECT_LE(r.evaluations, 60);
      EXPECT_FALSE(r.budget_exhausted);
      // The result is the study's evaluation of the values it reports.
      EXPECT_EQ(r.cost.J, optim::evaluate(s, network::resolve(layout, r.values)).J);
    }
  }
}

}  // namespace test_optim_study_refine
