// `inerta check` on every kind of input file, and the lumped pantograph under `simulate --catenary`.
#include <cmath>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_check_cli {

using inerta::testing::contains;
using inerta::testing::quote;

namespace {
std::string model(const std::string& name) { return quote(std::string(INERTA_SOURCE_DIR) + "/models/" + name); }

// The mean contact force of the summary line "contact force over ...: mean X N, ...".
double mean_force(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("contact force over .*: mean ([-0-9.]+) N"))) return NAN;
  return std::stod(m[1]);
}

class CheckCli : public inerta::testing::CliTest {};
}  // namespace

TEST_F(CheckCli, AFiniteElementCatenaryFilePrintsItsLineWireSpeedsAndMesh) {
  const auto r = run_inerta("check " + model("catenary-fe.yaml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "type: finite_element")) << r.out;
  EXPECT_TRUE(contains(r.out, "line: 10 spans of 55 m, length 550 m, encumbrance 1.2 m")) << r.out;
  // sqrt(16000 / 1.08) = 121.716 m/s, sqrt(22000 / 1.35) = 127.657 m/s
  EXPECT_TRUE(contains(r.out, "wave speed sqrt(T/rho A) = 121.72 m/s (438.2 km/h)")) << r.out;
  EXPECT_TRUE(contains(r.out, "wave speed sqrt(T/rho A) = 127.66 m/s (459.6 km/h)")) << r.out;
  EXPECT_TRUE(contains(r.out, "droppers: 9 a span, 90 in all")) << r.out;
  EXPECT_TRUE(contains(r.out, "\n  mesh: element_length 0.25 m\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "contact: penalty, k_s = 50000 N/m")) << r.out;
  EXPECT_TRUE(contains(r.out, "\nok\n")) << r.out;
}

TEST_F(CheckCli, LumpedAndProfileCatenariesPrintTheirDescription) {
  const auto lumped = run_inerta("check " + model("catenary.yaml"));
  ASSERT_EQ(lumped.code, 0) << lumped.err;
  EXPECT_TRUE(contains(lumped.out, "lumped catenary (eq. 7.1): span 60 m")) << lumped.out;
  EXPECT_TRUE(contains(lumped.out, "contact: bilateral")) << lumped.out;
  const auto profile = run_inerta("check " + model("wire-profile.yaml"));
  ASSERT_EQ(profile.code, 0) << profile.err;
  EXPECT_TRUE(contains(profile.out, "wire profile")) << profile.out;
}

TEST_F(CheckCli, ALumpedPantographFilePrintsItsDataAndTheModel) {
  const auto r = run_inerta("check " + model("pantograph-3mass.yaml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "lumped pantograph: 3 masses, head first: m = [7.12, 6, 5.8] kg")) << r.out;
  EXPECT_TRUE(contains(r.out, "static uplift 70 N on the lowest mass")) << r.out;
  EXPECT_TRUE(contains(r.out, "bodies (3)")) << r.out;
  // 9 coordinates − 3 sliders × 2 − the rig's hold of the head = 2
  EXPECT_TRUE(contains(r.out, "degrees of freedom: 2")) << r.out;
  EXPECT_TRUE(contains(r.out, "\nok\n")) << r.out;
}

TEST_F(CheckCli, AnUnknownFileListsWhatWasExpected) {
  std::ofstream(dir_ / "odd.yaml") << "colour: blue\nsize: 3\n";
  const auto r = run_inerta("check " + quote((dir_ / "odd.yaml").string()));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "not a file that Inerta reads: expected a model file (top-level 'bodies'")) << r.err;
  EXPECT_TRUE(contains(r.err, "'lumped_pantograph'")) << r.err;
  EXPECT_TRUE(contains(r.err, "found keys: colour, size")) << r.err;
  const auto study = run_inerta("check " + quote(std::string(INERTA_SOURCE_DIR) + "/studies/hsx-s2.yaml"));
  EXPECT_EQ(study.code, 2);
  EXPECT_TRUE(contains(study.err, "a study file")) << study.err;
  // A bad catenary file is reported with its line.
  std::ofstream(dir_ / "fe.yaml") << "type: finite_element\nline: {span: 55}\n";
  const auto fe = run_inerta("check " + quote((dir_ / "fe.yaml").string()));
  EXPECT_EQ(fe.code, 2);
  EXPECT_TRUE(contains(fe.err, "fe.yaml:1: 'messenger': missing")) << fe.err;
}

TEST_F(CheckCli, TheThreeMassPantographRunsUnderTheLumpedCatenaryAndTakesItsOverrides) {
  const auto csv = dir_ / "x.csv";
  const std::string base = "simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary.yaml") +
                           " --speed 250 --unit kmh --out " + quote(csv.string());
  const auto r = run_inerta(base);
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,y_head,y_m2,y_m3,F_contact");
  // The mean contact force is the static uplift less the roof spring's share, 0.1 N/m × about 2 cm
  // (over 12 spans, the default: the slow mode of the masses on the roof damper has settled).
  EXPECT_NEAR(mean_force(r.out), 70.0, 0.05) << r.out;
  const auto up = run_inerta(base + " --set lumped_pantograph.static_uplift=90 --set catenary.kc0=8000");
  ASSERT_EQ(up.code, 0) << up.err;
  EXPECT_NEAR(mean_force(up.out), 90.0, 0.05) << up.out;
  const auto bad = run_inerta(base + " --set lumped_pantograph.uplift=90");
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(contains(bad.err, "override 'lumped_pantograph.uplift=90': unknown key")) << bad.err;
}
}  // namespace test_apps_check_cli
