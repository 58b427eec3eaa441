// Acceptance criteria files (io/acceptance_file.hpp): the presets give their documented numbers,
// every bad file is refused naming the file, line and key.
#include "inerta/io/acceptance_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "inerta/error.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_acceptance_file {

using namespace inerta;
using analysis::Statistics;

namespace {
std::string write(const std::string& name, const std::string& text) {
  const auto p = (inerta::testing::temp_dir() / name).string();
  std::ofstream(p) << text;
  return p;
}
std::string error_of(const std::string& which) {
  try {
    io::load_acceptance(which);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
const std::string kHead = "name: t\nfilter: {cutoff: 20, order: 4}\n";
}  // namespace

TEST(AcceptanceFile, ThePresetsGiveTheirDocumentedNumbers) {
  EXPECT_EQ(io::acceptance_presets(), (std::vector<std::string>{"en50367-ac", "en50367-dc3"}));
  const auto ac = io::load_acceptance("en50367-ac");
  EXPECT_EQ(ac.name, "en50367-ac");
  EXPECT_EQ(ac.filter_cutoff, 20);
  EXPECT_EQ(ac.filter_order, 4);
  ASSERT_EQ(ac.mean.size(), 1u);
  EXPECT_NEAR(ac.mean[0].upper.at(300), 0.00097 * 300 * 300 + 70, 1e-9);  // 157.3 N
  EXPECT_NEAR(ac.mean[0].lower.at(300), 0.00047 * 300 * 300 + 60, 1e-9);  // 102.3 N
  EXPECT_EQ(ac.mean[0].statistics, Statistics::Filtered);
  ASSERT_EQ(ac.sigma.size(), 1u);
  EXPECT_EQ(ac.sigma[0].ratio, 0.3);
  EXPECT_EQ(ac.statistical_min[0].min, 0);
  EXPECT_EQ(ac.max_force[0].max, 350);
  ASSERT_EQ(ac.contact_loss.size(), 2u);
  EXPECT_EQ(ac.contact_loss[0].max_pct, 0.1);
  EXPECT_EQ(ac.contact_loss[0].speeds.to, 250);
  EXPECT_EQ(ac.contact_loss[1].max_pct, 0.2);
  EXPECT_EQ(ac.contact_loss[1].min_duration, 0.005);
  EXPECT_EQ(ac.support_uplift[0].clearance_factor, 2);
  ASSERT_TRUE(ac.has_target);
  EXPECT_NEAR(ac.target.at(300), 0.00047 * 300 * 300 + 90, 1e-9);  // 132.3 N
  const auto dc = io::load_acceptance("en50367-dc3");
  EXPECT_NEAR(dc.target.at(200), 0.00097 * 200 * 200 + 110, 1e-9);
  EXPECT_NEAR(dc.mean[0].lower.at(200), 0.9 * dc.target.at(200), 1e-9);
  EXPECT_NEAR(dc.mean[0].upper.at(200), 1.1 * dc.target.at(200), 1e-9);
}

TEST(AcceptanceFile, AFileWithSpeedBandsIsRead) {
  const auto f = write("bands.yaml", kHead +
                                         "contact_loss:\n"
                                         "  - {max_pct: 0.1, min_duration: 0, speeds: [0, 250]}\n"
                                         "  - {max_pct: 0.2, min_duration: 0.005, speeds: [250, .inf]}\n");
  const auto c = io::load_acceptance(f);
  ASSERT_EQ(c.contact_loss.size(), 2u);
  EXPECT_TRUE(std::isinf(c.contact_loss[1].speeds.to));
  EXPECT_FALSE(c.has_target);
}

TEST(AcceptanceFile, BadFilesAreRefusedNamingFileLineAndKey) {
  EXPECT_TRUE(contains(error_of("en50367-xx"), "unknown preset 'en50367-xx'")) << error_of("en50367-xx");
  EXPECT_TRUE(contains(error_of("en50367-xx"), "en50367-ac, en50367-dc3"));
  const auto missing = write("missing.yaml", kHead + "sigma: {statistics: filtered}\n");
  EXPECT_TRUE(contains(error_of(missing), missing + ":3: 'sigma.max_ratio': missing")) << error_of(missing);
  const auto nan = write("nan.yaml", kHead + "max_force: {max: .nan, statistics: raw}\n");
  EXPECT_TRUE(contains(error_of(nan), nan + ":3: 'max_force.max'")) << error_of(nan);
  EXPECT_TRUE(contains(error_of(nan), "not a finite number")) << error_of(nan);
  const auto band = write("band.yaml", kHead +
                                           "mean_force:\n  lower: {v2: 0.001, v1: 0, v0: 60}\n"
                                           "  upper: {v2: 0.0005, v1: 0, v0: 70}\n  statistics: filtered\n");
  // 0.001 v² + 60 > 0.0005 v² + 70 from v = 141 km/h: checked over the band's speeds (to 1000 km/h).
  EXPECT_TRUE(contains(error_of(band), band + ":4: 'mean_force': the lower edge")) << error_of(band);
  const auto stats = write("stats.yaml", kHead + "sigma: {max_ratio: 0.3, statistics: smoothed}\n");
  EXPECT_TRUE(contains(error_of(stats), "'sigma.statistics': 'smoothed'; expected raw or filtered")) << error_of(stats);
  const auto unknown = write("unknown.yaml", kHead + "sigma: {max_ratio: 0.3, statistics: raw, ratio: 1}\n");
  EXPECT_TRUE(contains(error_of(unknown), "'sigma.ratio': unknown key")) << error_of(unknown);
  const auto overlap = write("overlap.yaml", kHead +
                                                 "contact_loss:\n  - {max_pct: 0.1, min_duration: 0, speeds: [0, 260]}\n"
                                                 "  - {max_pct: 0.2, min_duration: 0, speeds: [250, .inf]}\n");
  EXPECT_TRUE(contains(error_of(overlap), "'contact_loss': entries 0 and 1 overlap in speed")) << error_of(overlap);
  const auto huge = write("huge.yaml", kHead + "mean_force:\n  lower: {v2: 0, v1: 0, v0: -1e300}\n"
                                               "  upper: {v2: 0, v1: 0, v0: 1e300}\n  statistics: raw\n");
  EXPECT_TRUE(contains(error_of(huge), "'mean_force.lower': -1e+300 N at 0 km/h; expected a force within ±1e6 N")) << error_of(huge);
  const auto none = write("none.yaml", kHead);
  EXPECT_TRUE(contains(error_of(none), "no criterion")) << error_of(none);
  const auto nofilter = write("nofilter.yaml", "name: t\nsigma: {max_ratio: 0.3, statistics: raw}\n");
  EXPECT_TRUE(contains(error_of(nofilter), "'filter': missing")) << error_of(nofilter);
  EXPECT_TRUE(contains(error_of("/nonexistent/criteria.yaml"), "/nonexistent/criteria.yaml")) << error_of("/nonexistent/criteria.yaml");
}

}  // namespace test_io_acceptance_file
