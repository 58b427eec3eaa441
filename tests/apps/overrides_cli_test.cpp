// --set NAME.KEY=VALUE on every command that reads a model (issue 13, part 2), run as a separate
// process: the override takes effect without a catenary, a joint's motion keys are overridable,
// and an override that matches nothing exits with code 2 naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_overrides_cli {

namespace {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;
using inerta::testing::Result;

std::string model_path(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

// Last row of a CSV as numbers.
std::vector<double> last_row(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::vector<double> v;
  std::istringstream fs(last);
  for (std::string f; std::getline(fs, f, ',');) v.push_back(std::stod(f));
  return v;
}

// The first mode's frequency printed by `inerta modes` ("    1     f  zeta ...").
double first_frequency(const std::string& out) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    int k = 0;
    double f = 0;
    if (ls >> k >> f && k == 1) return f;
  }
  return NAN;
}

class Overrides : public inerta::testing::CliTest {};

TEST_F(Overrides, SimulateWithoutACatenaryUsesTheOverride) {
  // The override equals editing the file.
  std::string text = read_file(model_path("onedof.yaml"));
  const std::string edited = write("edited.yaml", text.replace(text.find("k: 10000"), 8, "k: 40000"));
  const std::string a = (dir_ / "a.csv").string(), b = (dir_ / "b.csv").string(), c = (dir_ / "c.csv").string();
  Result r = run("simulate " + quote(model_path("onedof.yaml")) + " --t-end 1 --set k.k=40000 --out " + quote(a));
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(run("simulate " + quote(edited) + " --t-end 1 --out " + quote(b)).code, 0);
  ASSERT_EQ(run("simulate " + quote(model_path("onedof.yaml")) + " --t-end 1 --out " + quote(c)).code, 0);
  EXPECT_EQ(read_file(a), read_file(b));
  EXPECT_NE(read_file(a), read_file(c));
}

TEST_F(Overrides, ModesWithoutACatenaryUsesTheOverride) {
  // onedof: the spring is unstressed at the equilibrium, so K ∝ k and f ∝ sqrt(k): ×4 k → ×2 f.
  Result r1 = run("modes " + quote(model_path("onedof.yaml")));
  Result r4 = run("modes " + quote(model_path("onedof.yaml")) + " --set k.k=40000");
  ASSERT_EQ(r1.code, 0) << r1.err;
  ASSERT_EQ(r4.code, 0) << r4.err;
  EXPECT_NEAR(first_frequency(r4.out) / first_frequency(r1.out), 2.0, 1e-3) << r1.out << r4.out;
}

TEST_F(Overrides, CheckUsesTheOverride) {
  Result r = run("check " + quote(model_path("onedof.yaml")) + " --set mass.mass=7.5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "m = 7.5 ")) << r.out;
}

TEST_F(Overrides, OverrideThatMatchesNothingExitsTwo) {
  for (const char* cmd : {"simulate", "modes", "check"}) {
    Result r = run(std::string(cmd) + " " + quote(model_path("onedof.yaml")) + " --set k_s.k=12000");
    EXPECT_EQ(r.code, 2) << cmd << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "override 'k_s.k=12000': no force element, body or joint named 'k_s'")) << r.err;
    r = run(std::string(cmd) + " " + quote(model_path("onedof.yaml")) + " --set k.stiffness=1");
    EXPECT_EQ(r.code, 2) << cmd;
    EXPECT_TRUE(contains(r.err, "'k' has no value 'stiffness'; its values: k")) << r.err;
  }
}

const char* kDriven = R"(name: driven
options: {gravity: false, t_end: 1, sample: 0.5}
ground:
  markers: {P: [0, 0]}
bodies:
  - {name: s, mass: 1, inertia: 0.1, position: [0, 0]}
joints:
  - {name: drive, type: driving, body: s, coordinate: y, motion: {type: ramp, slope: 0.1}}
  - name: wobble
    type: driving
    body: s
    coordinate: theta
    motion: {type: sum_of_sines, amplitudes: [0.0, 0.0], frequencies: [0.5, 0.25]}
outputs:
  - {name: y, type: coordinate, body: s, component: y}
  - {name: th, type: coordinate, body: s, component: theta}
)";

TEST_F(Overrides, JointMotionKeysAreOverridable) {
  const std::string m = write("driven.yaml", kDriven);
  // drive.slope is drive.motion.slope; wobble.amplitudes[1] the second amplitude.
  Result r = run("simulate " + quote(m) + " --set drive.slope=0.5 --set wobble.amplitudes[1]=0.2");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<double> row = last_row(r.out);  // t = 1
  ASSERT_EQ(row.size(), 3u);
  EXPECT_NEAR(row[1], 0.5, 1e-6);
  EXPECT_NEAR(row[2], 0.2 * std::sin(2 * M_PI * 0.25 * 1.0), 1e-6);  // 0.2
  r = run("simulate " + quote(m) + " --set drive.motion.slope=0.5");
  EXPECT_EQ(r.code, 0) << r.err;
  r = run("simulate " + quote(m) + " --set wobble.amplitudes[5]=1");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "'amplitudes' is not a list of numbers with an item 5 (it has 2)")) << r.err;
  r = run("simulate " + quote(m) + " --set drive.speed=20");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "'motion' has no value 'speed'; its values: slope")) << r.err;
}

TEST(SplitOverrides, ModelNamesGoToTheModelTheRestToTheCatenary) {
  const auto [model, catenary] =
      inerta::io::split_overrides(model_path("hsx.yaml"), {"catenary.kc0=5000", "head.mass=5", "contact.type=penalty"});
  EXPECT_EQ(model, std::vector<std::string>{"head.mass=5"});
  // hsx.yaml's rig joint is named `contact`; contact.type stays the catenary's (the joint's motion has no `type`).
  EXPECT_EQ(catenary, (std::vector<std::string>{"catenary.kc0=5000", "contact.type=penalty"}));
  const auto [lumped, rest] =
      inerta::io::split_overrides(model_path("pantograph-3mass.yaml"), {"lumped_pantograph.static_uplift=90"});
  EXPECT_EQ(lumped.size(), 1u);
  EXPECT_TRUE(rest.empty());
  EXPECT_THROW(inerta::io::split_overrides("/nonexistent.yaml", {"a.b=1"}), inerta::ModelError);
}

}  // namespace
}  // namespace test_apps_overrides_cli
