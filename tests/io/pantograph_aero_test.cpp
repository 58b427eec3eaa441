// The aerodynamic uplift of a multibody pantograph model: `pantograph: {aerodynamic: {a, b, c}}`
// and its overrides (docs/model-format.md#pantograph).
#include <gtest/gtest.h>

#include <string>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/pantograph/pantograph.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_pantograph_aero {

using namespace inerta;

namespace {
const std::string kHsx = INERTA_SOURCE_DIR "/models/hsx.yaml";
std::string error_of(const std::vector<std::string>& sets) {
  try {
    io::load_pantograph(kHsx, sets);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(PantographAero, AnOverrideGivesTheUpliftOnTheContactMarkersBody) {
  const pantograph::Pantograph none = io::load_pantograph(kHsx);
  EXPECT_FALSE(none.aero.active());  // the bundled HSX has none
  const pantograph::Pantograph p = io::load_pantograph(kHsx, {"pantograph.aerodynamic.a=0.01", "pantograph.aerodynamic.c=5"});
  ASSERT_TRUE(p.aero.active());
  EXPECT_EQ(p.aero.body, p.contact().body);
  EXPECT_EQ(p.aero.a, 0.01);
  EXPECT_EQ(p.aero.b, 0);
  EXPECT_EQ(p.aero.c, 5);
  EXPECT_DOUBLE_EQ(p.aero.force(80), 0.01 * 80 * 80 + 5);
  // at_speed adds it once as a force element and clears it.
  const pantograph::Pantograph at = pantograph::at_speed(p, 80);
  EXPECT_FALSE(at.aero.active());
  EXPECT_EQ(at.model.forces.size(), p.model.forces.size() + 1);
}

TEST(PantographAero, BadOverridesNameTheKey) {
  EXPECT_NE(error_of({"pantograph.aerodynamic.d=1"}).find("expected pantograph.aerodynamic.a, .b or .c"), std::string::npos)
      << error_of({"pantograph.aerodynamic.d=1"});
  EXPECT_NE(error_of({"pantograph.aerodynamic.a=x"}).find("not a number"), std::string::npos);
  EXPECT_NE(error_of({"pantograph.contact=1"}).find("expected pantograph.aerodynamic"), std::string::npos);
}

}  // namespace test_io_pantograph_aero
