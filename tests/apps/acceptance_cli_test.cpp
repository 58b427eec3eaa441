// `--acceptance` of sweep, simulate and check-reduction, `--strict`, and `inerta pantograph aero-fit`
// on a short finite-element line.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "inerta/io/acceptance_file.hpp"
#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_acceptance_cli {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;

namespace {
std::string model(const std::string& name) { return quote(std::string(INERTA_SOURCE_DIR) + "/models/" + name); }
// A 4-span line (section: spans 2–3): a run is a fraction of a second.
const std::string kLine = model("catenary-fe.yaml") + " --set line.spans=4";
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  std::stringstream ss(text);
  std::string line;
  std::getline(ss, line);
  std::vector<std::string> head;
  {
    std::stringstream hs(line);
    for (std::string h; std::getline(hs, h, ',');) head.push_back(h);
  }
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(ss, line)) {  // a field may be quoted ("a, b"; "" for a quote): notes, statistics, sources
    std::map<std::string, std::string> row;
    std::size_t i = 0;
    std::string f;
    bool quoted = false;
    for (std::size_t k = 0; k <= line.size(); ++k) {
      const char ch = k < line.size() ? line[k] : ',';
      if (quoted && ch == '"' && k + 1 < line.size() && line[k + 1] == '"') {
        f += '"', ++k;
      } else if (ch == '"') {
        quoted = !quoted;
      } else if (ch == ',' && !quoted) {
        if (i < head.size()) row[head[i]] = f;
        ++i, f.clear();
      } else {
        f += ch;
      }
    }
    rows.push_back(row);
  }
  return rows;
}
class AcceptanceCli : public inerta::testing::CliTest {};
}  // namespace

// The verdict of a sweep equals the verdict recomputed from its own CSV statistics with the
// preset's numbers; without --strict it is a report (exit 0), with it exit 6 on a failure.
TEST_F(AcceptanceCli, TheSweepVerdictIsTheOneItsCsvStatisticsGive) {
  const auto csv = path("acc.csv");
  auto r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
               " --speeds 200:100:300 --unit kmh --acceptance en50367-ac --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "acceptance: en50367-ac")) << r.out;
  EXPECT_TRUE(contains(r.out, "verdict: FAIL")) << r.out;  // no aerodynamic uplift: F_m below the band
  const auto stats = csv_rows(read_file(csv));
  const auto verdict = csv_rows(read_file(path("acc.acceptance.csv")));
  ASSERT_EQ(stats.size(), 2u);
  const auto c = inerta::io::load_acceptance("en50367-ac");
  int checked = 0;
  for (const auto& row : verdict) {
    const double v = std::stod(row.at("v_kmh"));
    const auto& s = stats[v < 250 ? 0 : 1];
    auto num = [&](const char* k) { return std::stod(s.at(k)); };
    const std::string& crit = row.at("criterion");
    std::string expect;
    const auto& band = c.mean[v < 200 ? 0 : 1];  // the F_m band: 0 … 200 and 200 … 320 km/h
    if (crit == "mean_lower") expect = num("f_mean") >= band.lower.at(v) ? "PASS" : "FAIL";
    if (crit == "mean_upper") expect = num("f_mean") <= band.upper.at(v) ? "PASS" : "FAIL";
    if (crit == "sigma") expect = num("f_std") <= 0.3 * num("f_mean") ? "PASS" : "FAIL";
    if (crit == "statistical_min") expect = num("f_stat_min") >= 0 ? "PASS" : "FAIL";
    // The statistical maximum F_m + 3σ: 300 N below 200 km/h, 350 N from 200 km/h (issue 53).
    if (crit == "max_force") expect = num("f_stat_max") <= (v < 200 ? 300 : 350) ? "PASS" : "FAIL";
    if (crit == "contact_loss") expect = num("loss_counted_pct") <= (v < 200 ? 0.1 : 0.2) ? "PASS" : "FAIL";
    if (crit != "support_uplift") {  // the AC set's numbers are unverified
      EXPECT_EQ(row.at("assumed"), "true") << crit;
    }
    if (crit == "support_uplift") expect = "not assessed";  // catenary-fe.yaml has no registration.uplift_limit
    EXPECT_EQ(row.at("status"), expect) << crit << " at " << v;
    ++checked;
  }
  EXPECT_EQ(checked, 2 * 7);
  // The verdict says which numbers are assumed and what stands in for arcing (issue 53).
  EXPECT_TRUE(contains(r.out, "max_force [assumed]")) << r.out;
  EXPECT_TRUE(contains(r.out, "(filtered, F_m + 3σ)")) << r.out;
  EXPECT_TRUE(contains(r.out, "stands in for the measured percentage of arcing")) << r.out;
  r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
          " --speeds 200:100:300 --unit kmh --acceptance en50367-ac --strict --out " + quote(path("s.csv").string()));
  EXPECT_EQ(r.code, 6) << r.out << r.err;
}

TEST_F(AcceptanceCli, ASimulationJudgesEveryPantographAndAPassingSetExitsZeroWithStrict) {
  const auto lenient = write("lenient.yaml",
                             "name: lenient\nfilter: {cutoff: 20, order: 4}\n"
                             "sigma: {max_ratio: 2, statistics: filtered}\n"
                             "support_uplift: {clearance_factor: 2}\n");
  const auto csv = path("two.csv");
  auto r = run("simulate " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
               " --set registration.uplift_limit=0.5 --speed 200 --unit kmh --positions 0,30 --acceptance " +
               quote(lenient) + " --strict --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "verdict: PASS")) << r.out;
  const auto rows = csv_rows(read_file(path("two.acceptance.csv")));
  ASSERT_EQ(rows.size(), 4u);  // 2 pantographs × (sigma, support_uplift)
  EXPECT_EQ(rows[0].at("pantograph"), "1");
  EXPECT_EQ(rows[2].at("pantograph"), "2");
  EXPECT_EQ(rows[1].at("criterion"), "support_uplift");
  EXPECT_EQ(rows[1].at("limit"), "0.25");  // 0.5 m / clearance factor 2
  // Errors: an unknown preset (exit 2, before any run), --acceptance without a catenary.
  r = run("simulate " + model("pantograph-3mass.yaml") + " --catenary " + kLine + " --speed 200 --unit kmh --acceptance nope");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "unknown preset 'nope'")) << r.err;
  r = run("simulate " + model("tmd.yaml") + " --acceptance en50367-ac");
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(contains(r.err, "--acceptance")) << r.err;
}

// Issue 52: nothing assessed is no PASS; a partial verdict names what it left out; --strict and
// --acceptance are not silently ignored.
TEST_F(AcceptanceCli, NothingAssessedIsNotAPassAndAPartialVerdictSaysWhatItLeftOut) {
  // The wire profile gives no 20 Hz statistics and no loss events: every row not assessed.
  auto r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + model("wire-profile.yaml") +
               " --speeds 300:1:300 --unit kmh --acceptance en50367-ac --strict --out " + quote(path("w.csv").string()));
  EXPECT_EQ(r.code, 6) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "verdict: NOT ASSESSED")) << r.out;
  EXPECT_FALSE(contains(r.out, "verdict: PASS")) << r.out;
  r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + model("wire-profile.yaml") +
          " --speeds 300:1:300 --unit kmh --acceptance en50367-ac --out " + quote(path("w.csv").string()));
  EXPECT_EQ(r.code, 0) << r.err;  // without --strict: a report
  EXPECT_TRUE(contains(r.out, "verdict: NOT ASSESSED")) << r.out;
  // The FE line without registration.uplift_limit: the support uplift is not assessed, the rest is.
  const auto lenient = write("lenient.yaml",
                             "name: lenient\nfilter: {cutoff: 20, order: 4}\n"
                             "sigma: {max_ratio: 2, statistics: filtered}\n"
                             "support_uplift: {clearance_factor: 2}\n");
  r = run("simulate " + model("pantograph-3mass.yaml") + " --catenary " + kLine + " --speed 200 --unit kmh --acceptance " +
          quote(lenient) + " --strict --out " + quote(path("p.csv").string()));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "verdict: PASS (every assessed criterion at every speed); not assessed: support_uplift")) << r.out;
  // --strict needs --acceptance; an empty --acceptance is no criteria set.
  r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + model("wire-profile.yaml") +
          " --speeds 300:1:300 --unit kmh --strict");
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(contains(r.err, "--strict requires --acceptance")) << r.err;
  r = run("sweep " + model("pantograph-3mass.yaml") + " --catenary " + model("wire-profile.yaml") +
          " --speeds 300:1:300 --unit kmh --acceptance ''");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--acceptance: an empty name")) << r.err;
}

// Issue 52: on a point model of the line the fit reads the raw mean and says so (no "20 Hz statistics").
TEST_F(AcceptanceCli, AeroFitOnALumpedLineSaysItsStatisticsAreRaw) {
  const auto r = run("pantograph aero-fit " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") +
                     " --acceptance en50367-ac --speed 250 --unit kmh");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "(raw statistics: a point model of the line has no 20 Hz ones)")) << r.out;
  EXPECT_FALSE(contains(r.out, "20 Hz statistics")) << r.out;
}

TEST_F(AcceptanceCli, CheckReductionSaysWhetherBothSolvesReachTheSameVerdict) {
  const auto r = run("catenary check-reduction " + model("catenary-fe.yaml") +
                     " --set line.spans=3 --set solver.window_behind=-1 --speed 200 --unit kmh --tolerance 100 "
                     "--acceptance en50367-ac");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "acceptance en50367-ac: direct ")) << r.out;
  // The minimum force differs in N, the contact loss in percentage points (not a relative % of a share).
  EXPECT_TRUE(contains(r.out, " N\n  min 20 Hz N")) << r.out;
  EXPECT_TRUE(contains(r.out, " pp\n  uplift max mm")) << r.out;
}

TEST_F(AcceptanceCli, AeroFitBringsTheMeanForceToTheTarget) {
  auto r = run("pantograph aero-fit " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
               " --acceptance en50367-ac --speed 300 --unit kmh");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  // Target 0.00047 · 300² + 90 = 132.3 N.
  EXPECT_TRUE(contains(r.out, "132.30 N")) << r.out;
  const auto at = r.out.find("mean contact force ", r.out.find("a = "));
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(r.out.substr(at + 19)), 132.3, 0.05) << r.out;
  // Already above the target without uplift: no a >= 0 reaches it.
  r = run("pantograph aero-fit " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
          " --set lumped_pantograph.static_uplift=200 --acceptance en50367-ac --speed 300 --unit kmh");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, "already above")) << r.err;
  // A set without a target curve.
  const auto f = write("notarget.yaml", "name: n\nfilter: {cutoff: 20, order: 4}\nsigma: {max_ratio: 0.3, statistics: raw}\n");
  r = run("pantograph aero-fit " + model("pantograph-3mass.yaml") + " --catenary " + kLine + " --acceptance " +
          quote(f) + " --speed 300 --unit kmh");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "no mean-force 'target' curve")) << r.err;
  // Commissioning's options (issue 49): a working range that is not two decimal heights of 0 … 2 m, a
  // --param without --suspension, an unknown layout: usage errors naming the option.
  for (const char* w : {"nan:0.1", "0x1:1", "inf:1", "1e300:0.1", "0:0", "-0.1:0.1", "0.1"}) {
    r = run("pantograph aero-fit " + model("hsx.yaml") + " --catenary " + kLine +
            " --acceptance en50367-ac --speed 300 --unit kmh --working-range " + w);
    EXPECT_EQ(r.code, 105) << w << r.err;
    EXPECT_TRUE(contains(r.err, "--working-range")) << w << r.err;
  }
  r = run("pantograph aero-fit " + model("hsx.yaml") + " --catenary " + kLine + " --acceptance en50367-ac --speed 300 --unit kmh --param k=1");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--param")) << r.err;
  r = run("pantograph aero-fit " + model("hsx.yaml") + " --catenary " + kLine +
          " --acceptance en50367-ac --speed 300 --unit kmh --suspension 'k-q'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "--suspension 'k-q'")) << r.err;
  // Outside the speeds its source gives the target for (issue 53): refused, naming them.
  r = run("pantograph aero-fit " + model("pantograph-3mass.yaml") + " --catenary " + kLine +
          " --acceptance en50367-ac --speed 150 --unit kmh");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "not assessed; its source gives it from 200 to 320 km/h only")) << r.err;
}

}  // namespace test_apps_acceptance_cli
