// Acceptance criteria files (io/acceptance_file.hpp): the presets give their documented numbers,
// every bad file is refused naming the file, line and key.
#include "inerta/io/acceptance_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
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

const std::vector<std::string> kPresets{"en50367-ac", "en50367-ac15", "en50367-dc1.5", "en50367-dc3"};

TEST(AcceptanceFile, ThePresetsGiveTheirDocumentedNumbers) {
  EXPECT_EQ(io::acceptance_presets(), kPresets);
  const auto ac = io::load_acceptance("en50367-ac");
  EXPECT_EQ(ac.name, "en50367-ac");
  EXPECT_EQ(ac.filter_cutoff, 20);
  EXPECT_EQ(ac.filter_order, 4);
  // F_m: the upper edge 0.00047 v² + 90 N up to 200 km/h, 0.00097 v² + 70 N from 200 to 320 km/h.
  ASSERT_EQ(ac.mean.size(), 2u);
  EXPECT_EQ(ac.mean[0].speeds.to, 200);
  EXPECT_NEAR(ac.mean[0].upper.at(150), 0.00047 * 150 * 150 + 90, 1e-9);
  EXPECT_EQ(ac.mean[1].speeds.from, 200);
  EXPECT_EQ(ac.mean[1].speeds.to, 320);
  EXPECT_NEAR(ac.mean[1].upper.at(300), 0.00097 * 300 * 300 + 70, 1e-9);  // 157.3 N
  EXPECT_NEAR(ac.mean[1].lower.at(300), 0.00047 * 300 * 300 + 60, 1e-9);  // 102.3 N
  EXPECT_EQ(ac.mean[1].statistics, Statistics::Filtered);
  ASSERT_EQ(ac.sigma.size(), 1u);
  EXPECT_EQ(ac.sigma[0].ratio, 0.3);
  EXPECT_EQ(ac.statistical_min[0].min, 0);
  // The maximum force on F_m + 3σ: 300 N below 200 km/h, 350 N from 200 km/h.
  ASSERT_EQ(ac.max_force.size(), 2u);
  EXPECT_EQ(ac.max_force[0].max, 300);
  EXPECT_EQ(ac.max_force[0].speeds.to, 200);
  EXPECT_EQ(ac.max_force[1].max, 350);
  for (const auto& m : ac.max_force) EXPECT_EQ(m.measure, analysis::ForceMeasure::StatisticalMax);
  ASSERT_EQ(ac.contact_loss.size(), 2u);
  EXPECT_EQ(ac.contact_loss[0].max_pct, 0.1);
  EXPECT_EQ(ac.contact_loss[0].speeds.to, 200);
  EXPECT_EQ(ac.contact_loss[1].max_pct, 0.2);
  EXPECT_EQ(ac.contact_loss[1].min_duration, 0.005);
  EXPECT_EQ(ac.support_uplift[0].clearance_factor, 2);
  EXPECT_EQ(ac.support_uplift[0].limited_clearance_factor, 1.5);
  ASSERT_TRUE(ac.has_target);
  EXPECT_NEAR(ac.target.at(300), 0.00047 * 300 * 300 + 90, 1e-9);  // 132.3 N
  EXPECT_FALSE(ac.target.covers(150));  // the upper edge's formula there: not a target
  const auto ac15 = io::load_acceptance("en50367-ac15");
  EXPECT_NEAR(ac15.mean[1].upper.at(300), ac.mean[1].upper.at(300), 1e-12);  // the TSI's one set of AC curves
  EXPECT_EQ(ac15.static_force.lower, 55);  // Bane NOR (TRV:08157): 55 … 90 N
  EXPECT_EQ(ac15.static_force.upper, 90);
  EXPECT_FALSE(ac15.static_force.assumed);
  const auto dc = io::load_acceptance("en50367-dc3");
  EXPECT_NEAR(dc.mean[0].lower.at(200), 0.00097 * 200 * 200 + 110, 1e-9);
  EXPECT_NEAR(dc.mean[0].upper.at(200), 0.00097 * 200 * 200 + 140, 1e-9);
  EXPECT_EQ(dc.mean[0].speeds.to, 250);
  EXPECT_EQ(dc.max_force[1].max, 400);
  const auto dc15 = io::load_acceptance("en50367-dc1.5");
  EXPECT_NEAR(dc15.mean[0].upper.at(100), 0.00228 * 100 * 100 + 90, 1e-9);
}

// Issue 53: every entry of every preset names its source; where a F_m band and the target both hold, lower ≤
// target ≤ upper at every speed from 0 to 400 km/h.
TEST(AcceptanceFile, EveryPresetEntryIsSourcedAndItsBandHoldsItsTarget) {
  for (const std::string& name : kPresets) {
    const analysis::AcceptanceCriteria c = io::load_acceptance(name);
    SCOPED_TRACE(name);
    auto sourced = [&](const auto& list, const char* what) {
      EXPECT_FALSE(list.empty()) << what;
      for (const auto& e : list) EXPECT_FALSE(e.source.empty()) << what;
    };
    sourced(c.mean, "mean_force");
    sourced(c.sigma, "sigma");
    sourced(c.statistical_min, "statistical_min");
    sourced(c.max_force, "max_force");
    sourced(c.contact_loss, "contact_loss");
    sourced(c.support_uplift, "support_uplift");
    ASSERT_TRUE(c.has_target);
    EXPECT_FALSE(c.target.source.empty());
    ASSERT_TRUE(c.has_static_force);
    EXPECT_FALSE(c.static_force.source.empty());
    int both = 0;
    for (double v = 0; v <= 400; v += 0.5)
      for (const auto& b : c.mean) {
        if (!(b.speeds.contains(v) || v == b.speeds.to) || !c.target.covers(v)) continue;
        ++both;
        const double t = c.target.at(v);
        EXPECT_LE(b.lower.at(v), t + 1e-9) << v;
        EXPECT_LE(t, b.upper.at(v) + 1e-9) << v;
      }
    EXPECT_GT(both, 100);
    // Every row of a verdict at every speed carries its entry's source and statistic.
    analysis::VerdictInput in;
    in.raw.mean = in.filtered.mean = 120, in.raw.std = in.filtered.std = 20, in.raw.samples = 100;
    in.has_filtered = true, in.uplift_max = 0.05, in.uplift_limit = 0.2;
    for (double v : {50.0, 150.0, 250.0}) {
      in.speed = v / 3.6;
      for (const auto& r : analysis::assess(c, in))
        if (r.assessed) {
          EXPECT_FALSE(r.source.empty() || r.statistic.empty()) << r.criterion << " at " << v;
        }
    }
  }
}

TEST(AcceptanceFile, SourcesMeasuresAndLimitedUpliftAreRead) {
  const auto f = write("sourced.yaml", kHead +
                                           "max_force: {max: 300, statistics: filtered, measure: statistical_max, "
                                           "source: \"EN 50119, https://example.org\", assumed: false}\n"
                                           "support_uplift: {clearance_factor: 2, limited_clearance_factor: 1.5}\n"
                                           "mean_force: {lower: {v2: 0, v1: 0, v0: 60}, upper: {v2: 0, v1: 0, v0: 120}, "
                                           "statistics: filtered, speeds: [100, 300]}\n"
                                           "target: {v2: 0, v1: 0, v0: 90, speeds: [100, 300]}\n");
  const auto c = io::load_acceptance(f);
  EXPECT_EQ(c.max_force[0].measure, analysis::ForceMeasure::StatisticalMax);
  EXPECT_EQ(c.max_force[0].source, "EN 50119, https://example.org");
  EXPECT_FALSE(c.max_force[0].assumed);
  EXPECT_TRUE(c.support_uplift[0].assumed);  // no source: assumed
  EXPECT_EQ(c.support_uplift[0].factor(true), 1.5);
  EXPECT_EQ(c.support_uplift[0].factor(false), 2);
  EXPECT_EQ(c.target.speeds.from, 100);
  EXPECT_EQ(c.target.speeds.to, 300);
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

// Issue 53: the line says whether a stop limits its registrations' uplift (registration.uplift_limited).
TEST(AcceptanceFile, TheLineSaysWhetherAStopLimitsItsUplift) {
  const std::string line = std::string(INERTA_SOURCE_DIR) + "/models/catenary-fe.yaml";
  EXPECT_FALSE(io::load_catenary(line).catenary->uplift_limited());
  EXPECT_TRUE(io::load_catenary(line, {"registration.uplift_limited=true"}).catenary->uplift_limited());
  std::string text;
  {
    std::ifstream in(line);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string at = "  mass: 0                 # kg\nmesh:";
  ASSERT_NE(text.find(at), std::string::npos);
  const auto write_line = [&](const std::string& name, const std::string& value) {
    std::string t = text;
    t.replace(t.find(at), at.size(), "  mass: 0\n  uplift_limited: " + value + "\nmesh:");
    return write(name, t);
  };
  EXPECT_TRUE(io::load_catenary(write_line("limited.yaml", "true")).catenary->uplift_limited());
  const std::string bad = write_line("limited_bad.yaml", "2");
  try {
    io::load_catenary(bad);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_TRUE(contains(e.what(), bad + ":37: 'uplift_limited'")) << e.what();
  }
  try {
    io::load_catenary(line, {"registration.uplift_limited=1"});
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_TRUE(contains(e.what(), "expected registration.uplift_limited=true or false")) << e.what();
  }
}

TEST(AcceptanceFile, BadFilesAreRefusedNamingFileLineAndKey) {
  EXPECT_TRUE(contains(error_of("en50367-xx"), "unknown preset 'en50367-xx'")) << error_of("en50367-xx");
  EXPECT_TRUE(contains(error_of("en50367-xx"), "en50367-ac, en50367-ac15, en50367-dc1.5, en50367-dc3"));
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
  // Issue 53's keys: a measure, assumed, source, the limited factor, a target outside its band.
  const auto measure = write("measure.yaml", kHead + "max_force: {max: 300, statistics: raw, measure: peak}\n");
  EXPECT_TRUE(contains(error_of(measure), measure + ":3: 'max_force.measure': 'peak'; expected largest")) << error_of(measure);
  const auto assumed = write("assumed.yaml", kHead + "sigma: {max_ratio: 0.3, statistics: raw, assumed: maybe}\n");
  EXPECT_TRUE(contains(error_of(assumed), assumed + ":3: 'sigma.assumed': 'maybe'; expected true")) << error_of(assumed);
  const auto source = write("source.yaml", kHead + "sigma: {max_ratio: 0.3, statistics: raw, source: [a, b]}\n");
  EXPECT_TRUE(contains(error_of(source), "'sigma.source': expected a text")) << error_of(source);
  const auto limited = write("limited.yaml", kHead + "support_uplift: {clearance_factor: 1.5, limited_clearance_factor: 2}\n");
  EXPECT_TRUE(contains(error_of(limited), limited + ":3: 'support_uplift.limited_clearance_factor': 2 is above clearance_factor"))
      << error_of(limited);
  const auto typo = write("typo.yaml", kHead + "support_uplift: {clearance_factor: 2, limited_factor: 1.5}\n");
  EXPECT_TRUE(contains(error_of(typo), typo + ":3: 'support_uplift.limited_factor': unknown key")) << error_of(typo);
  const auto above = write("above.yaml", kHead +
                                             "mean_force: {lower: {v2: 0.00047, v1: 0, v0: 60}, upper: {v2: 0.00097, v1: 0, v0: 70}, "
                                             "statistics: filtered}\n"
                                             "target: {v2: 0.00047, v1: 0, v0: 90}\n");
  // Unbounded, the AC target lies above the upper edge below 200 km/h (at 0 km/h: 90 N against 70 N).
  EXPECT_TRUE(contains(error_of(above), above + ":4: 'target': 90 N at 0 km/h is above mean_force's upper edge 70 N"))
      << error_of(above);
  const auto tspeeds = write("tspeeds.yaml", kHead + "sigma: {max_ratio: 0.3, statistics: raw}\ntarget: {v2: 0, v1: 0, v0: 90, speeds: [300, 200]}\n");
  EXPECT_TRUE(contains(error_of(tspeeds), "'target.speeds': expected 0 <= from < to")) << error_of(tspeeds);
  const auto none = write("none.yaml", kHead);
  EXPECT_TRUE(contains(error_of(none), "no criterion")) << error_of(none);
  const auto nofilter = write("nofilter.yaml", "name: t\nsigma: {max_ratio: 0.3, statistics: raw}\n");
  EXPECT_TRUE(contains(error_of(nofilter), "'filter': missing")) << error_of(nofilter);
  EXPECT_TRUE(contains(error_of("/nonexistent/criteria.yaml"), "/nonexistent/criteria.yaml")) << error_of("/nonexistent/criteria.yaml");
}

}  // namespace test_io_acceptance_file
