// Lumped n-mass pantograph files (docs/model-format.md#lumped-pantograph-files): the bundled DSA 380,
// its overrides, and every documented error with its file:line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/io/file_kind.hpp"
#include "inerta/io/model_file.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_lumped_pantograph_file {

using namespace inerta;

namespace {

const std::string kGood =
    "name: three\n"                             // 1
    "lumped_pantograph:\n"                      // 2
    "  masses: [7.12, 6.0, 5.8]\n"              // 3
    "  stiffness: [9430, 14100, 0.1]\n"         // 4
    "  damping: [0, 0, 70]\n"                   // 5
    "  static_uplift: 70\n"                     // 6
    "  aerodynamic: {a: 0.001, b: 0, c: 2}\n";  // 7

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (inerta::testing::temp_dir() / name).string();
  std::ofstream(path) << text;
  return path;
}

// The message of loading `text` (with overrides), or "" if it loads.
std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    io::parse_pantograph(text, "lp.yaml", sets);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LumpedPantographFile, TheBundledDsa380LoadsAsAPantographWithARig) {
  const std::string path = inerta::testing::model_path("pantograph-3mass.yaml");
  EXPECT_EQ(io::file_kind(path), io::FileKind::LumpedPantograph);
  const pantograph::LumpedPantographData d = io::load_lumped_pantograph_data(path);
  EXPECT_EQ(d.mass, (std::vector<double>{7.12, 6.0, 5.8}));
  EXPECT_EQ(d.stiffness, (std::vector<double>{9430, 14100, 0.1}));
  EXPECT_EQ(d.damping, (std::vector<double>{0, 0, 70}));
  EXPECT_EQ(d.static_uplift, 70);
  const pantograph::Pantograph p = io::load_pantograph(path);
  EXPECT_EQ(p.model.name, "DSA 380 (3 masses)");
  EXPECT_EQ(p.model.source, path);
  ASSERT_EQ(p.model.bodies.size(), 3u);
  EXPECT_EQ(p.model.bodies[0].name, "head");
  EXPECT_EQ(p.model.bodies[0].mass, 7.12);
  EXPECT_EQ(p.model.bodies[2].mass, 5.8);
  EXPECT_EQ(p.contact().body, 0);
  ASSERT_TRUE(p.has_rig());
  EXPECT_EQ(p.model.joints[static_cast<std::size_t>(p.rig_joint)].name, "rig");
  EXPECT_EQ(p.model.options.t_end, 2);
  EXPECT_FALSE(p.aero.active());  // a = b = c = 0 in the file
  // load_model and load_model_file read it too.
  EXPECT_EQ(io::load_model(path).bodies.size(), 3u);
  EXPECT_EQ(io::load_model_file(path).rig_joint, p.rig_joint);
}

TEST(LumpedPantographFile, OverridesChangeTheNamedValue) {
  const pantograph::Pantograph p =
      io::parse_pantograph(kGood, "lp.yaml",
                           {"lumped_pantograph.static_uplift=90", "lumped_pantograph.masses[0]=7.5",
                            "lumped_pantograph.stiffness[2]=12", "lumped_pantograph.damping[1]=3",
                            "lumped_pantograph.aerodynamic.b=0.25"});
  EXPECT_EQ(p.model.bodies[0].mass, 7.5);
  EXPECT_EQ(p.aero.a, 0.001);
  EXPECT_EQ(p.aero.b, 0.25);
  EXPECT_EQ(p.aero.c, 2);
  const std::string path = write("inerta_lp_overrides.yaml", kGood);
  const pantograph::LumpedPantographData d =
      io::load_lumped_pantograph_data(path, {"lumped_pantograph.static_uplift=90", "lumped_pantograph.stiffness[2]=12",
                                             "lumped_pantograph.damping[1]=3"});
  EXPECT_EQ(d.static_uplift, 90);
  EXPECT_EQ(d.stiffness[2], 12);
  EXPECT_EQ(d.damping[1], 3);
  // An aerodynamic coefficient can be set where the file has none; model_value reads values (identify --fit).
  const std::string bare = "lumped_pantograph: {masses: [1], stiffness: [100], damping: [1], static_uplift: 5}\n";
  EXPECT_TRUE(io::parse_pantograph(bare, "b.yaml", {"lumped_pantograph.aerodynamic.c=4"}).aero.active());
  EXPECT_EQ(io::model_value(kGood, "lp.yaml", "lumped_pantograph.stiffness[1]"), 14100);
  EXPECT_EQ(io::model_value(bare, "b.yaml", "lumped_pantograph.aerodynamic.a"), std::nullopt);
}

TEST(LumpedPantographFile, AnOverrideThatMatchesNothingIsAnError) {
  auto has = [](const std::string& msg, const std::string& part) {
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
  };
  has(error_of(kGood, {"lumped_pantograph.mass=3"}), "lp.yaml: override 'lumped_pantograph.mass=3': unknown key");
  has(error_of(kGood, {"head.mass=3"}), "override 'head.mass=3': expected lumped_pantograph.KEY");
  has(error_of(kGood, {"lumped_pantograph.masses[3]=3"}), "'masses' has 3 value(s): index 0 (the head) to 2");
  has(error_of(kGood, {"lumped_pantograph.aerodynamic.d=1"}), "unknown key");
  has(error_of(kGood, {"lumped_pantograph.static_uplift=strong"}), "'strong' is not a number");
  has(error_of(kGood, {"lumped_pantograph.static_uplift"}), "expected KEY=VALUE");
  // A value that the override makes non-physical is reported like one in the file.
  has(error_of(kGood, {"lumped_pantograph.masses[1]=-6"}), "lp.yaml:3: 'masses[1]': must be > 0 (kg), got -6");
}

TEST(LumpedPantographFile, EveryErrorNamesTheFileLineAndKey) {
  auto expect = [](const std::string& text, const std::string& part) {
    const std::string msg = error_of(text);
    EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg << "\nfile:\n" << text;
  };
  const std::string head = "lumped_pantograph:\n";
  // unknown keys: in the section, at the top level, in aerodynamic, in options
  expect(head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n  uplift: 3\n",
         "lp.yaml:6: 'uplift': unknown key in lumped_pantograph; expected one of: masses, stiffness, damping, "
         "static_uplift, aerodynamic");
  expect("bodies: []\n" + head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n",
         "lp.yaml:1: 'bodies': unknown key in a lumped pantograph file");
  expect(head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n  aerodynamic: {a: 1, d: 2}\n",
         "lp.yaml:6: 'd': unknown key in aerodynamic");
  expect(head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\noptions: {gravity: true}\n",
         "lp.yaml:6: 'gravity': unknown key in options; expected one of: t_end, sample; a lumped pantograph has no "
         "gravity");
  // a key twice
  expect(head + "  masses: [1]\n  masses: [2]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n",
         "lp.yaml:3: 'masses': duplicate key in lumped_pantograph");
  // missing keys
  expect(head + "  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n", "lp.yaml:2: 'masses': missing in lumped_pantograph");
  expect(head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n", "lp.yaml:2: 'static_uplift': missing in lumped_pantograph");
  // wrong types
  expect(head + "  masses: 7\n  stiffness: [1]\n  damping: [1]\n  static_uplift: 1\n",
         "lp.yaml:2: 'masses': expected a list of numbers (kg)");
  expect(head + "  masses: [1, heavy]\n  stiffness: [1, 1]\n  damping: [1, 1]\n  static_uplift: 1\n",
         "lp.yaml:2: 'masses': expected a number, got 'heavy'");
  expect(head + "  masses: [1]\n  stiffness: [1]\n  damping: [1]\n  static_uplift: [70]\n",
         "lp.yaml:5: 'static_uplift': expected a number");
  // list lengths that do not match
  expect(head + "  masses: [1, 2, 3]\n  stiffness: [1, 2]\n  damping: [1, 2, 3]\n  static_uplift: 1\n",
         "lp.yaml:3: 'stiffness': needs one value per mass (3)");
  expect(head + "  masses: [1, 2]\n  stiffness: [1, 2]\n  damping: [1, 2, 3]\n  static_uplift: 1\n",
         "lp.yaml:4: 'damping': needs one value per mass (2)");
  // non-physical values, at the line of the list item (named with its index, from 0)
  expect(head + "  masses:\n    - 7\n    - -6\n  stiffness: [1, 2]\n  damping: [1, 2]\n  static_uplift: 1\n",
         "lp.yaml:4: 'masses[1]': must be > 0 (kg), got -6 in lumped pantograph");
  expect(head + "  masses: [1, .nan]\n  stiffness: [1, 2]\n  damping: [1, 2]\n  static_uplift: 1\n",
         "lp.yaml:2: 'masses[1]': must be > 0 (kg), got nan");
  expect(head + "  masses: [1]\n  stiffness: [-5]\n  damping: [1]\n  static_uplift: 1\n",
         "lp.yaml:3: 'stiffness[0]': must be >= 0 (N/m), got -5");
  expect(head + "  masses: [1]\n  stiffness: [5]\n  damping: [.inf]\n  static_uplift: 1\n",
         "lp.yaml:4: 'damping[0]': must be >= 0 (N·s/m), got inf");
  expect(head + "  masses: [1]\n  stiffness: [5]\n  damping: [1]\n  static_uplift: -70\n",
         "lp.yaml:5: 'static_uplift': must be >= 0 (N, upward), got -70");
  expect(head + "  masses: [1]\n  stiffness: [5]\n  damping: [1]\n  static_uplift: 7\n  aerodynamic:\n    a: .nan\n",
         "lp.yaml:7: 'a': must be a finite number (N·s²/m²), got nan");
  expect(head + "  masses: []\n  stiffness: []\n  damping: []\n  static_uplift: 7\n", "lp.yaml:2: 'masses': expected a list");
  expect("name: x\nlumped_pantograph:\n  masses: [1]\n  stiffness: [5]\n  damping: [1]\n  static_uplift: 7\n"
         "options: {t_end: -1}\n",
         "lp.yaml:7: 't_end': must be > 0 (s)");
}
}  // namespace test_io_lumped_pantograph_file
