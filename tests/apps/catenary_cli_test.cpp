// `inerta simulate --catenary` through the catenary interface: the wire profile, several
// pantographs, and what a catenary type cannot do.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

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

namespace test_apps_catenary_cli {

TEST_F(CatenaryCli, BadStitchAndIrregularityInputIsAFileErrorNamingTheKey) {
  // Issue 34 item 6 through the program: each exits 2 naming the file and the key.
  const std::string src = read_file(std::string(INERTA_SOURCE_DIR) + "/models/catenary-fe-stitched.yaml");
  write("short.csv", "x,dz\n0,0\n300,0.01\n");
  write("back.csv", "x,dz\n0,0\n400,0.01\n300,0\n700,0\n");
  struct Case {
    const char* from;
    const char* to;
    const char* key;
  };
  const Case cases[] = {
      {"  length: 18 ", "  length: 70 ", "'length'"},                        // longer than the span
      {"    x: [-5, 5]", "    x: [-5, 9.5]", "x[1]"},                          // a stitch dropper outside the stitch
      {"  x:      [17.5,", "  x:      [8.5,", "x[0]"},                        // a span dropper inside it
      {"  tension: 3500 ", "  tension: -3500 ", "'tension'"},
      {"  tension: 3500 ", "  tension: .nan ", "'tension'"},
      {"  mass_per_length: 0.31 ", "  mass_per_length: -0.31 ", "'mass_per_length'"},
      {"solver:", "irregularity:\n  dropper_length_std: -0.001\nsolver:", "'dropper_length_std'"},
      {"solver:", "irregularity:\n  height_errors: short.csv\nsolver:", "'height_errors'"},
      {"solver:", "irregularity:\n  height_errors: back.csv\nsolver:", "'height_errors'"},
      {"solver:", "irregularity:\n  point_masses: [{x: 700, mass: 2}]\nsolver:", "'point_masses[0]'"},
      {"solver:", "irregularity:\n  dropper_length_errors: [0.001, 0.002]\nsolver:", "dropper_length_errors"},
  };
  int n = 0;
  for (const Case& c : cases) {
    std::string t = src;
    const auto at = t.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    t.replace(at, std::string(c.from).size(), c.to);
    const std::string file = write(fmt::format("bad{}.yaml", n++), t);
    const auto r = run("check " + quote(file));
    EXPECT_EQ(r.code, 2) << c.to << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, file)) << r.err;
    EXPECT_TRUE(contains(r.err, c.key)) << c.key << "\n" << r.err;
  }
  // Overrides: a negative std, and a stitch key on a line that has none.
  auto r = run("check " + model("catenary-fe.yaml") + " --set irregularity.dropper_length_std=-1");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "dropper_length_std")) << r.err;
  r = run("check " + model("catenary-fe.yaml") + " --set stitch.enabled=false");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "stitch")) << r.err;
}

TEST_F(CatenaryCli, BadTensionSectionsAreAFileErrorNamingTheKey) {
  // Issue 35 item 8 through the program: sections that do not share their overlap supports, an
  // overlap longer than a section, an out-of-running wire below the running one, a section without
  // anchor data: exit 2, the file and the key named.
  const std::string src = read_file(std::string(INERTA_SOURCE_DIR) + "/models/catenary-fe-overlap.yaml");
  struct Case {
    const char* from;
    const char* to;
    const char* key;
  };
  const Case cases[] = {
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13, span: 60, anchors: pinned}", "tension_sections[1].span"},
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 6, anchors: pinned}", "tension_sections[1].spans"},
      {"0.0342, 0.02, 0.00959, 0, 0, 0]", "0.0342, -0.1, 0.00959, 0, 0, 0]", "overlap.incoming.z"},  // below the running wire at a support
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13}", "anchors"},
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13, anchors: {stiffness: .nan}}", "tension_sections[1].anchors.stiffness"},
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13, anchors: {stiffness: 1e300}}", "tension_sections[1].anchors.stiffness"},
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13, anchors: {stiffness: 1e5, mass: .inf}}", "tension_sections[1].anchors.mass"},
      {"  - {spans: 13, anchors: pinned}", "  - {spans: 13, anchors: pinned, messenger: {tension: -5}}", "tension_sections[1].messenger.tension"},
      {"  spans: 3", "  spans: 0", "overlap.spans"},
      {"0.00959, 0.02, 0.0342, 0.08627", "0.00959, .inf, 0.0342, 0.08627", "overlap.outgoing.z[4]"},
      {"    x: [0, 65, 113.75,", "    x: [0, 65, 65,", "overlap.outgoing.x[2]"},  // a profile's points out of order
  };
  int n = 0;
  for (const Case& c : cases) {
    std::string t = src;
    const auto at = t.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    t.replace(at, std::string(c.from).size(), c.to);
    const std::string file = write(fmt::format("badsec{}.yaml", n++), t);
    const auto r = run("check " + quote(file));
    EXPECT_EQ(r.code, 2) << c.to << "\n" << r.err;
    const auto at_file = r.err.find(file + ":");
    ASSERT_NE(at_file, std::string::npos) << r.err;
    EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(r.err[at_file + file.size() + 1]))) << "file:line, " << r.err;
    EXPECT_TRUE(contains(r.err, c.key)) << c.key << "\n" << r.err;
  }
  // An override that would break the line: every section takes it.
  const auto r = run("check " + model("catenary-fe-overlap.yaml") + " --set line.spans=5");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "tension sections")) << r.err;
}

}  // namespace test_apps_catenary_cli
