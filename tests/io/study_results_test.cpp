// results.csv and results.json of a design study (io/study_results.hpp), from hand-made layout
// results: valid JSON for awkward names, element values 0 → 0, ∞ → "inf", numbers bit for bit,
// and the CSV columns as documented.
#include "inerta/io/study_results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_study_results {

using namespace inerta;

TEST(StudyResults, JsonAndCsvForAwkwardNames) {
  const std::string study = "my \"quoted\" \\ study \xc3\xa9";
  optim::StudyCost def;
  def.J = 12.345678901234567;
  std::vector<optim::LayoutResult> results(2);
  results[0].layout = "S2-\"1\"\\";
  results[0].expression = "b-(k|c)";
  results[0].values = {{"b", 0.0}, {"c", INFINITY}, {"k", 7130.123456789012}};
  results[0].cost.J = 10.000000000000002, results[0].cost.speed = 180 / 3.6, results[0].cost.mean = 120.5;
  results[0].evaluations = 321;
  results[1].layout = "k|c, \xc3\xa9";
  results[1].expression = "k|c";
  results[1].values = {{"c", 1.0 / 3.0}, {"k", 5e4}};
  results[1].cost.J = 13.5, results[1].cost.speed = 250 / 3.6, results[1].cost.mean = 119.25;
  results[1].evaluations = 1;

  const auto dir = std::filesystem::temp_directory_path() / ("inerta_study_results_" + std::to_string(::getpid())) /
                   "nested";
  const auto files = io::write_study_results(dir.string(), study, def, results);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0], (dir / "results.csv").string());
  EXPECT_EQ(files[1], (dir / "results.json").string());

  std::ifstream in(files[1]);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);  // keeps the key order
  EXPECT_EQ(j["study"], study);
  EXPECT_EQ(j["default_J2"].get<double>(), def.J);
  ASSERT_EQ(j["layouts"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& l = j["layouts"][i];
    const auto& r = results[i];
    EXPECT_EQ(l["layout"], r.layout);
    EXPECT_EQ(l["network"], r.expression);
    EXPECT_EQ(l["J2"].get<double>(), r.cost.J);
    EXPECT_EQ(l["v_kmh"].get<double>(), r.cost.speed * 3.6);
    EXPECT_EQ(l["mean_N"].get<double>(), r.cost.mean);
    EXPECT_EQ(l["evaluations"], r.evaluations);
    ASSERT_EQ(l["values"].size(), r.values.size());
    for (const auto& [k, v] : r.values) {
      const auto& jv = l["values"][k];
      if (v == 0) {
        EXPECT_TRUE(jv.is_number_integer()) << k;
        EXPECT_EQ(jv, 0) << k;
      } else if (std::isinf(v)) {
        EXPECT_EQ(jv, "inf") << k;
      } else {
        EXPECT_EQ(jv.get<double>(), v) << k;
      }
    }
  }
  // Keys in the documented order.
  std::vector<std::string> keys;
  for (auto it = j["layouts"][0].begin(); it != j["layouts"][0].end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"layout", "network", "values", "J2", "v_kmh", "mean_N", "evaluations"}));

  EXPECT_EQ(inerta::testing::read_file(files[0]),
            "layout,network,b,c,k,J2,reduction_pct,v_kmh,mean_N,evaluations\n"
            "\"S2-\"\"1\"\"\\\",b-(k|c),open,rigid,7130,10,-19,180,120.5,321\n"  // quoted, quotes doubled (RFC 4180)
            "\"k|c, \xc3\xa9\",k|c,-,0.3333,5e+04,13.5,9.35,250,119.25,1\n");
  std::filesystem::remove_all(dir.parent_path());
}
}  // namespace test_io_study_results
