// The JSON writer (io/json.hpp): valid JSON for any string (quotes, backslashes, control
// characters, non-ASCII, invalid UTF-8), doubles that read back bit for bit, and the table layout
// (a matrix one row per line).
#include "inerta/io/json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_json {

using inerta::io::Json;

namespace {
const std::string kAwkward = "my \"quoted\" \\ model \xc3\xa9";  // my "quoted" \ model é (UTF-8)

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST(Json, StringsAreEscapedAndReadBack) {
  Json j;
  j[kAwkward] = kAwkward;
  j["control"] = std::string("tab\there, newline\nthere, bell\a, nul ") + '\0' + " end";
  j["list"] = {kAwkward, "plain"};
  const std::string text = inerta::io::json_text(j);
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back.at(kAwkward), kAwkward);
  EXPECT_EQ(back.at("control").get<std::string>(), j["control"].get<std::string>());
  EXPECT_EQ(back.at("list").at(0), kAwkward);
  EXPECT_NE(text.find("\"my \\\"quoted\\\" \\\\ model \xc3\xa9\""), std::string::npos) << text;
  // Invalid UTF-8 (a lone continuation byte) is replaced, not written raw or thrown.
  const std::string bad = "x\x80y";
  const nlohmann::json b = nlohmann::json::parse(inerta::io::json_text(Json{{"s", bad}}));
  EXPECT_EQ(b.at("s"), "x\xef\xbf\xbdy");
}

TEST(Json, DoublesRoundTripExactly) {
  const double values[] = {0.0,
                           -0.0,
                           0.1,
                           1.0 / 3.0,
                           std::numbers::pi,
                           55.000000000000021,
                           -90.909090915891596,
                           1e-300,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::lowest(),
                           123456789.123456789};
  Json list = Json::array();
  for (double v : values) list.push_back(v);
  const nlohmann::json back = nlohmann::json::parse(inerta::io::json_text(Json{{"v", list}}));
  ASSERT_EQ(back.at("v").size(), std::size(values));
  for (std::size_t i = 0; i < std::size(values); ++i)
    EXPECT_TRUE(same_bits(back["v"][i].get<double>(), values[i])) << i << ": " << values[i];
  // Non-finite numbers have no JSON form: null.
  const nlohmann::json nf = nlohmann::json::parse(inerta::io::json_text(Json{{"nan", NAN}, {"inf", INFINITY}}));
  EXPECT_TRUE(nf.at("nan").is_null());
  EXPECT_TRUE(nf.at("inf").is_null());
}

TEST(Json, MatricesAreWrittenAsRowsOnePerLine) {
  Eigen::MatrixXd m(2, 3);
  m << 1, -2.5, 0, 1e-20, 3, 0.1;
  Json j;
  j["name"] = "a";
  j["m"] = inerta::io::json_rows(m);
  j["row"] = inerta::io::json_rows(Eigen::RowVector2d(4, 5));
  j["names"] = {"x", "y"};
  j["nested"] = {{{"k", 1}, {"v", {{"b", 2}}}}};
  j["empty"] = Json::array();
  EXPECT_EQ(inerta::io::json_text(j),
            "{\n"
            "  \"name\": \"a\",\n"
            "  \"m\": [\n"
            "    [1.0, -2.5, 0.0],\n"
            "    [1e-20, 3.0, 0.1]\n"
            "  ],\n"
            "  \"row\": [\n"
            "    [4.0, 5.0]\n"
            "  ],\n"
            "  \"names\": [\"x\", \"y\"],\n"
            "  \"nested\": [\n"
            "    {\"k\": 1, \"v\": {\"b\": 2}}\n"
            "  ],\n"
            "  \"empty\": []\n"
            "}\n");
  const nlohmann::json back = nlohmann::json::parse(inerta::io::json_text(j));
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(back["m"][r][c].get<double>(), m(r, c));
}

TEST(Json, WriteJsonReplacesTheFileOrSaysWhyNot) {
  const auto dir = std::filesystem::temp_directory_path() / ("inerta_json_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "a.json").string();
  inerta::io::write_json(path, Json{{"a", 1}, {"b", "long text that is then replaced"}});
  inerta::io::write_json(path, Json{{"a", 2}});
  EXPECT_EQ(inerta::testing::read_file(path), "{\n  \"a\": 2\n}\n");
  try {
    inerta::io::write_json((dir / "no" / "such" / "dir.json").string(), Json{{"a", 1}});
    ADD_FAILURE() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cannot write '" + (dir / "no" / "such" / "dir.json").string() + "': ", 0), 0u)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}
}  // namespace test_io_json
