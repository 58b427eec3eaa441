// The JSON files of the `inerta` program, read back with nlohmann-json: `modes --export` for a
// model whose name has double quotes, a backslash and non-ASCII characters. (results.json of
// `optimise --out` is read back in optimise_cli_test.cpp.)
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_json_cli {

namespace {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;

const std::string kAwkward = "my \"quoted\" \\ model \xc3\xa9";

class JsonCli : public inerta::testing::CliTest {};

}  // namespace

TEST_F(JsonCli, ModesExportIsValidJsonForAnAwkwardModelName) {
  // onedof.yaml renamed (a YAML single-quoted scalar keeps the backslash and the quotes).
  std::string yaml = read_file(std::string(INERTA_SOURCE_DIR) + "/models/onedof.yaml");
  const std::string from = "\nname: onedof\n";
  ASSERT_TRUE(contains(yaml, from));
  yaml.replace(yaml.find(from), from.size(), "\nname: '" + kAwkward + "'\n");
  const auto model = dir_ / "awkward.yaml", json = dir_ / "lin.json";
  std::ofstream(model) << yaml;

  const auto r = run_inerta("modes " + quote(model.string()) + " --export " + quote(json.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "wrote " + json.string() + " and ")) << r.out;
  EXPECT_TRUE(contains(r.out, "modes of " + kAwkward + " about its static equilibrium")) << r.out;
  nlohmann::ordered_json j;
  ASSERT_NO_THROW(j = nlohmann::ordered_json::parse(read_file(json))) << read_file(json);
  EXPECT_EQ(j["model"], kAwkward);
  EXPECT_EQ(j.begin().key(), "model");
  EXPECT_EQ(j["coordinates"], (std::vector<std::string>{"mass.x", "mass.y", "mass.theta"}));
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["internal_states"], 0);
  // The reduced mass m + (Lb/L0)² b = 55 kg and stiffness k (Lb/L0)² = 5000 N/m (spec/01 §1.2).
  EXPECT_NEAR(j["M"][0][0].get<double>(), 55.0, 1e-7);
  EXPECT_NEAR(j["K"][0][0].get<double>(), 5000.0, 1e-3);
  EXPECT_EQ(j["A"].size(), 2u);
  EXPECT_EQ(j["q_e"].size(), 1u);
  EXPECT_EQ(j["q_e"][0].size(), 3u);
}
}  // namespace test_apps_json_cli
