// mbs::check_model: what `inerta check` reports, as a library call (the Python module's Model.check).
#include "inerta/mbs/model_check.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_model_check {

using namespace inerta;

namespace {
std::string twobar_text() {
  std::ifstream in(inerta::testing::model_path("twobar.yaml"));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST(ModelCheck, TwoBarHasTwoDegreesOfFreedom) {
  const mbs::Model m = io::load_model(inerta::testing::model_path("twobar.yaml"));
  const mbs::ModelCheck c = mbs::check_model(m);
  EXPECT_EQ(c.rank, 4);  // two revolute joints
  EXPECT_EQ(c.dof, 2);
  EXPECT_EQ(c.redundant, 0);
  EXPECT_LT(c.assembly.residual, 1e-10);
  EXPECT_EQ(c.state.q.size(), 6);
}

TEST(ModelCheck, RedundantJointIsCountedAndTheSingularSystemRefused) {
  std::string text = twobar_text();
  const std::string joint = "  - {name: B, type: revolute, markers: [bar1.b, bar2.a]}\n";
  const auto at = text.find(joint);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + joint.size(), "  - {name: B2, type: revolute, markers: [bar1.b, bar2.a]}\n");
  const mbs::Model m = io::parse_model(text, "twobar-redundant.yaml");
  EXPECT_EQ(m.n_constraints(), 6);
  EXPECT_EQ(m.dof(), 0);  // counting equations
  EXPECT_THROW(mbs::check_model(m), NumericalError);  // eq. 4.12 is singular, as `inerta check` reports
}
}  // namespace test_mbs_model_check
