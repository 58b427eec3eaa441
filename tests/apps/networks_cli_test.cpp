// `inerta networks` (the enumeration) and `inerta optimise` of a study with `layouts: all`
// (apps/inerta/networks.cpp): the list and its counts, the ranked table, structure.csv/json and
// pareto.csv, and the option errors.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "inerta/network/enumeration.hpp"
#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_networks_cli {

namespace {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;

class NetworksCli : public inerta::testing::CliTest {};

}  // namespace

TEST_F(NetworksCli, ListsEveryNetworkOnceAndCountsThem) {
  const auto out = dir_ / "n3.txt";
  const auto r = run_inerta("networks --max-elements 3 --out " + quote(out.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "29 networks (3 with 1, 6 with 2, 20 with 3); wrote")) << r.out;
  // The file is the library's enumeration, one expression per line, each parsing.
  inerta::network::EnumerationOptions o;
  o.max_elements = 3;
  std::string expected;
  for (const auto& e : inerta::network::enumerate(o)) expected += e + "\n";
  EXPECT_EQ(read_file(out), expected);
  const auto s = run_inerta("networks --max-elements 2 --elements kc --static-load required");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(s.out, "k\nk|c\n");
  EXPECT_TRUE(contains(s.err, "2 networks (1 with 1, 1 with 2)")) << s.err;
}

TEST_F(NetworksCli, OptionErrorsNameTheOption) {
  auto expect = [&](const std::string& args, const std::string& part) {
    const auto r = run_inerta(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_TRUE(contains(r.err, part)) << args << "\n" << r.err;
  };
  expect("networks --max-elements 0", "max_elements must be 1 … 7, not 0");
  expect("networks --max-elements 8", "max_elements must be 1 … 7, not 8");
  expect("networks --elements kx", "'x' is not an element type");
  expect("networks --static-load yes", "expected any, required or excluded, got 'yes'");
  expect("networks --max-inerters -3", "a type limit must be ≥ 0");
}

TEST_F(NetworksCli, AStudyOverAllNetworksWritesTheRankingAndTheParetoFront) {
  const auto study = dir_ / "tmd-all.yaml", out = dir_ / "out";
  std::ofstream(study) << "model: " << std::string(INERTA_SOURCE_DIR) << "/models/tmd.yaml\nstrut: absorber\n"
                       << "objective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, points: 100}}\n"
                       << "layouts: all\nnetworks: {max_elements: 2}\nsearch: {starts: 1, min_step: 0.05, lo: 0.01, hi: 1.0e7}\n";
  const auto r = run_inerta("optimise " + quote(study.string()) + " --no-plots --out " + quote(out.string()));
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_TRUE(contains(r.out, "every network of up to 2 elements (9 networks)")) << r.out;
  EXPECT_TRUE(contains(r.out, "[9/9]")) << r.out;
  EXPECT_TRUE(contains(r.out, "best by complexity")) << r.out;
  const std::string csv = read_file(out / "structure.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "rank,network,elements,springs,dampers,inerters,J,vs_default_pct,feasible,reduced,reduced_elements,reduced_inerters,"
            "values,evaluations,seconds,warm_from,unstable");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10) << csv;
  // Ranked: J never decreases down the file.
  const auto j = nlohmann::json::parse(read_file(out / "structure.json"));
  ASSERT_EQ(j["networks"].size(), 9u);
  for (std::size_t i = 1; i < 9; ++i) EXPECT_LE(j["networks"][i - 1]["J"].get<double>(), j["networks"][i]["J"].get<double>());
  EXPECT_EQ(j["objective"], "hinf");
  const std::string pareto = read_file(out / "pareto.csv");
  EXPECT_TRUE(contains(pareto, "elements,inerters,J,vs_default_pct,pareto,network\n")) << pareto;
  EXPECT_TRUE(contains(read_file(out / "results.csv"), "layout,expression,J")) << read_file(out / "results.csv");
}
}  // namespace test_apps_networks_cli
