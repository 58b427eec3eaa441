// `inerta simulate --catenary` through the catenary interface: the wire profile, several
// pantographs, and what a catenary type cannot do.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_catenary_cli {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;

namespace {
std::string model(const std::string& name) { return quote(std::string(INERTA_SOURCE_DIR) + "/models/" + name); }
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  for (std::string l; std::getline(ss, l);) lines.push_back(l);
  return lines;
}
class CatenaryCli : public inerta::testing::CliTest {};
}  // namespace

TEST_F(CatenaryCli, HsxUnderTheWireProfileWritesTheContactForceAndItsStatistics) {
  const auto csv = path("p.csv");
  const auto r = run("simulate " + model("hsx.yaml") + " --catenary " + model("wire-profile.yaml") +
                     " --speed 100 --unit kmh --spans 3 --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(csv));
  EXPECT_EQ(lines[0], "t,P_ay,E_ay,B_ay,l_act,y_head,F_contact");
  EXPECT_EQ(lines.size(), 3u * 400 + 2);  // 3 spans, 400 samples a span, t = 0 and the header
  EXPECT_TRUE(contains(r.out, "wire profile: 13 points")) << r.out;
  EXPECT_TRUE(contains(r.out, "contact force over the last 2 spans")) << r.out;
  EXPECT_TRUE(contains(r.out, "contact loss 0.00 %")) << r.out;
}

TEST_F(CatenaryCli, SeveralPantographsGetPrefixedColumnsAndAPointModelRefusesThem) {
  const auto csv = path("two.csv");
  const auto r = run("simulate " + model("hsx.yaml") + " --catenary " + model("wire-profile.yaml") +
                     " --speed 100 --unit kmh --spans 1 --positions 0,30 --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(csv));
  EXPECT_TRUE(contains(lines[0], ",p1.F_contact,")) << lines[0];
  EXPECT_TRUE(contains(lines[0], ",p2.F_contact")) << lines[0];
  EXPECT_TRUE(contains(r.out, "pantograph 2 (x0 = 30 m)")) << r.out;
  // The lumped catenary is a point model.
  const auto lumped = run("simulate " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") +
                          " --speed 100 --unit kmh --positions 0,200");
  EXPECT_EQ(lumped.code, 2);
  EXPECT_TRUE(contains(lumped.err, "a point model has no distance between pantographs")) << lumped.err;
  // A rigid wire refuses the bilateral contact; the periodic fast path refuses a catenary without a point model.
  const auto bilateral = run("simulate " + model("hsx.yaml") + " --catenary " + model("wire-profile.yaml") +
                             " --speed 100 --unit kmh --contact bilateral");
  EXPECT_EQ(bilateral.code, 2);
  EXPECT_TRUE(contains(bilateral.err, "needs a penalty contact")) << bilateral.err;
  const auto periodic = run("sweep " + model("hsx.yaml") + " --catenary " + model("wire-profile.yaml") +
                            " --speeds 100:50:200 --unit kmh --method periodic");
  EXPECT_EQ(periodic.code, 2);
  EXPECT_TRUE(contains(periodic.err, "use the time method")) << periodic.err;
  // --positions without a catenary is an error, not ignored.
  const auto alone = run("simulate " + model("twobar.yaml") + " --positions 0,10");
  EXPECT_NE(alone.code, 0);
  EXPECT_TRUE(contains(alone.err, "--positions")) << alone.err;
}

TEST_F(CatenaryCli, CheckReductionComparesTheModalAndDirectSolves) {
  // A short line, the whole line in one window: the table of both solves and the exit status
  // against --tolerance (0 within it; 1 beyond, with advice); a lumped catenary is refused.
  const std::string sets = " --set line.spans=3 --set solver.window_behind=-1 --set solver.cutoff=150";
  auto r = run("catenary check-reduction " + model("catenary-fe.yaml") + sets + " --speed 200 --unit kmh");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  for (const char* q : {"v = 200 km/h", "sigma N", "sigma 20 Hz N", "uplift max mm", "wall s", "direct solve", "modal solve below 150 Hz"})
    EXPECT_TRUE(contains(r.out, q)) << q << "\n" << r.out;
  r = run("catenary check-reduction " + model("catenary-fe.yaml") + " --set line.spans=3 --set solver.window_behind=-1 "
          "--set solver.cutoff=5 --speed 200 --unit kmh --tolerance 0.01");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, "raise solver.cutoff")) << r.err;
  r = run("catenary check-reduction " + model("catenary.yaml") + " --speed 200 --unit kmh");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, "needs a finite-element catenary")) << r.err;
}
}  // namespace test_apps_catenary_cli
