// `--report` of sweep and simulate and `inerta verify-report`: the page holds the verdict first, the
// numbers of the CSVs, the line's features, the provenance of every input; a re-run reproduces it,
// and a changed number or input is found.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "inerta/report/provenance.hpp"
#include "inerta/report/record.hpp"
#include "support/cli.hpp"

namespace test_apps_report_cli {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;
namespace fs = std::filesystem;

namespace {
std::string source(const std::string& rel) { return std::string(INERTA_SOURCE_DIR) + "/" + rel; }
std::string fmt_fixed4(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.4f", x);
  return b;
}
class ReportCli : public inerta::testing::CliTest {
 protected:
  // a copy of the 4-span line and the 3-mass model in the test's folder (so that an input can change)
  void SetUp() override {
    CliTest::SetUp();
    fs::copy_file(source("models/pantograph-3mass.yaml"), path("p.yaml"));
    fs::copy_file(source("models/catenary-fe.yaml"), path("line.yaml"));
  }
  std::string sweep(const std::string& extra) const {
    return "sweep " + quote(path("p.yaml").string()) + " --catenary " + quote(path("line.yaml").string()) +
           " --set line.spans=4 --speeds 200:50:250 --unit kmh --out " + quote(path("s.csv").string()) + " " + extra;
  }
  std::map<std::string, double> numbers(const std::string& file) const {
    const auto r = inerta::report::read_record(read_file(path(file)), file);
    std::map<std::string, double> m(r.numbers.begin(), r.numbers.end());
    return m;
  }
};
}  // namespace

TEST_F(ReportCli, ASweepsReportHoldsItsCsvNumbersAndItsInputsAndReproduces) {
  const auto r = run(sweep("--acceptance en50367-ac --report " + quote(path("r.html").string())));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "wrote " + path("r.html").string())) << r.out;
  const std::string html = read_file(path("r.html"));
  // self-contained: no script to run, nothing fetched
  EXPECT_FALSE(contains(html, "http://") && contains(html, "src=\"http"));
  EXPECT_FALSE(contains(html, "<script src"));
  EXPECT_FALSE(contains(html, "<link"));
  // the numbers are those of the CSV (written to 6 digits)
  std::stringstream csv(read_file(path("s.csv")));
  std::string line;
  std::getline(csv, line);
  const auto n = numbers("r.html");
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream ls(line);
    for (std::string f; std::getline(ls, f, ',');) v.push_back(std::stod(f));
    const std::string key = "v=" + std::to_string(static_cast<int>(std::lround(v[0]))) + " km/h";
    ASSERT_TRUE(n.count(key + "/raw/std")) << key;
    EXPECT_NEAR(n.at(key + "/raw/mean"), v[2], 5e-6 * std::abs(v[2]));
    EXPECT_NEAR(n.at(key + "/raw/std"), v[3], 5e-6 * std::abs(v[3]));
    EXPECT_NEAR(n.at(key + "/filtered/std"), v[10], 5e-6 * std::abs(v[10]));
    // and as the page shows them: the table cell is the CSV's text
    EXPECT_TRUE(contains(html, "<td>" + line.substr(0, line.find(',')) + "</td>"));
    ++rows;
  }
  EXPECT_EQ(rows, 2);
  // the inputs with their SHA-256, as read
  const auto rec = inerta::report::read_record(html, "r.html");
  ASSERT_EQ(rec.provenance.inputs.size(), 3u);  // criteria, model, line
  int model = 0;
  for (const auto& f : rec.provenance.inputs)
    if (f.path == path("p.yaml").string()) {
      ++model;
      EXPECT_EQ(f.sha256, inerta::report::sha256_hex(read_file(path("p.yaml"))));
    }
  EXPECT_EQ(model, 1);
  EXPECT_TRUE(contains(html, inerta::report::sha256_hex(read_file(path("line.yaml")))));
  EXPECT_TRUE(contains(html, inerta::report::build_info().commit));
  EXPECT_FALSE(rec.verdict.empty());
  // verify-report re-runs it and finds every number again
  const auto v = run("verify-report " + quote(path("r.html").string()));
  EXPECT_EQ(v.code, 0) << v.out << v.err;
  EXPECT_TRUE(contains(v.out, "reproduced: all " + std::to_string(rec.numbers.size()) + " numbers equal")) << v.out;
  EXPECT_TRUE(contains(v.out, "3 input file(s) unchanged")) << v.out;
  EXPECT_EQ(read_file(path("s.csv")).size() > 0, true);  // the original outputs are left alone
}

TEST_F(ReportCli, VerifyReportNamesANumberThatDiffersAndAnInputThatChanged) {
  ASSERT_EQ(run(sweep("--report " + quote(path("r.html").string()))).code, 0);
  const std::string html = read_file(path("r.html"));
  const auto rec = inerta::report::read_record(html, "r.html");
  EXPECT_TRUE(rec.verdict.empty());  // no criteria: no verdict
  EXPECT_TRUE(contains(html, "NO CRITERIA"));
  // a number edited in the page
  const std::string key = "\"v=250 km/h/raw/std\",\n";
  const auto at = html.find(key);
  ASSERT_NE(at, std::string::npos) << html.substr(html.find("inerta-record"), 400);
  std::string edited = html;
  const auto from = at + key.size(), to = edited.find('\n', from);
  edited.replace(from, to - from, "  1.5");
  std::ofstream(path("edited.html")) << edited;
  auto v = run("verify-report " + quote(path("edited.html").string()));
  EXPECT_EQ(v.code, 7) << v.out << v.err;
  EXPECT_TRUE(contains(v.out, "NOT reproduced: 1 of")) << v.out;
  EXPECT_TRUE(contains(v.out, "v=250 km/h/raw/std: reported 1.5, now")) << v.out;
  // an input changed since: named, and the numbers it moves
  std::ofstream(path("p.yaml"), std::ios::app) << "\n# edited\n";
  v = run("verify-report " + quote(path("r.html").string()));
  EXPECT_TRUE(contains(v.out, "input " + path("p.yaml").string() + " (")) << v.out;
  EXPECT_TRUE(contains(v.out, "changed since the report")) << v.out;
  EXPECT_EQ(v.code, 0) << "a comment changes no number: " << v.out;
  // not a report
  std::ofstream(path("x.html")) << "<html></html>";
  v = run("verify-report " + quote(path("x.html").string()));
  EXPECT_EQ(v.code, 2);
  EXPECT_TRUE(contains(v.err, "not an Inerta report")) << v.err;
}

TEST_F(ReportCli, ASimulationsReportMarksTheLineAndLeadsWithTheVerdict) {
  const auto r = run("simulate " + quote(path("p.yaml").string()) + " --catenary " + quote(path("line.yaml").string()) +
                     " --set line.spans=4 --speed 250 --unit kmh --acceptance en50367-ac --out " + quote(path("o.csv").string()) +
                     " --report " + quote(path("o.html").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = read_file(path("o.html"));
  const auto rec = inerta::report::read_record(html, "o.html");
  const std::string banner = "class=\"verdict " + std::string(rec.verdict == "NOT ASSESSED" ? "NA" : rec.verdict) + "\"";
  ASSERT_TRUE(contains(html, banner)) << rec.verdict;
  EXPECT_LT(html.find(banner), html.find("<h2>")) << "the verdict is the first thing on the page";
  // the acceptance CSV's rows are the report's
  std::stringstream acc(read_file(path("o.acceptance.csv")));
  std::string line;
  std::getline(acc, line);
  int rows = 0;
  const auto n = numbers("o.html");
  while (std::getline(acc, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
    const std::string key = "verdict/v=250 km/h/panto 1/" + f[3] + "/value";
    ASSERT_TRUE(n.count(key)) << key;
    if (f[5] != "nan") {
      EXPECT_NEAR(n.at(key), std::stod(f[5]), 5e-6 * std::abs(std::stod(f[5])) + 1e-12) << key;
    }
    ++rows;
  }
  EXPECT_GE(rows, 6);
  // masts (5 on 4 spans, those within the section drawn) and droppers marked along the force
  EXPECT_TRUE(contains(html, "class=\"mark mast\""));
  EXPECT_TRUE(contains(html, "class=\"mark dropper\""));
  EXPECT_TRUE(contains(html, "Contact force along the analysis section"));
}

TEST_F(ReportCli, AReportNeedsALineAndNeverReplacesAnInput) {
  auto r = run("simulate " + quote(path("p.yaml").string()) + " --t-end 0.1 --report " + quote(path("o.html").string()));
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(contains(r.err, "--report")) << r.err;
  r = run(sweep("--report " + quote(path("line.yaml").string())));
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(contains(r.err, "refusing to overwrite")) << r.err;
  EXPECT_EQ(read_file(path("line.yaml")), read_file(source("models/catenary-fe.yaml")));
  r = run(sweep("--report ''"));
  EXPECT_EQ(r.code, 105) << r.err;
}

}  // namespace test_apps_report_cli

namespace test_apps_report_cli {

// A study's report.html: the recommendation first, the ranking with its J, each network drawn with
// its values, the study file among the inputs; verify-report re-runs the study into a folder of its own.
TEST_F(ReportCli, AStudysReportRanksDrawsAndReproduces) {
  const std::string study = write("tiny.yaml", "name: tiny\nmodel: " + source("models/hsx.yaml") + "\ncatenary: " +
                                                   source("models/catenary.yaml") +
                                                   "\nspeeds: {from: 150, to: 200, step: 50, unit: kmh}\n"
                                                   "search: {starts: 1, seed: 1, min_step: 0.1}\nlayouts: [b|k]\n");
  const auto r = run("optimise " + quote(study) + " --out " + quote(path("out").string()) + " --map 0 --no-plots");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "report.html")) << r.out;
  const std::string html = read_file(path("out/report.html"));
  const auto rec = inerta::report::read_record(html, "report.html");
  EXPECT_EQ(rec.command, "optimise");
  EXPECT_LT(html.find("class=\"verdict"), html.find("<h2>"));
  EXPECT_TRUE(contains(html, "<table id=\"ranking\">"));
  EXPECT_GE(std::count(html.begin(), html.end(), '\n'), 20);
  std::size_t drawings = 0;
  for (std::size_t at = 0; (at = html.find("class=\"schematic\"", at)) != std::string::npos; ++at) ++drawings;
  EXPECT_GE(drawings, 2u) << "the default and the design";
  EXPECT_TRUE(contains(html, "kN/m"));
  bool study_input = false;
  for (const auto& f : rec.provenance.inputs) study_input = study_input || f.path == study;
  EXPECT_TRUE(study_input);
  // results.json's J of the design is the report's
  const std::string results = read_file(path("out/results.json"));
  EXPECT_TRUE(contains(results, "\"b|k\"")) << results.substr(0, 300);
  const auto v = run("verify-report " + quote(path("out/report.html").string()));
  EXPECT_EQ(v.code, 0) << v.out << v.err;
  EXPECT_TRUE(contains(v.out, "reproduced: all")) << v.out;
  // --force of the folder replaces the report too (it is the study's own file)
  EXPECT_EQ(run("optimise " + quote(study) + " --out " + quote(path("out").string()) + " --map 0 --no-plots --force").code, 0);
}

}  // namespace test_apps_report_cli

namespace test_apps_report_cli {

// check-reduction --report: both solves side by side (the printed numbers), both verdicts; reproduced.
TEST_F(ReportCli, TheReductionChecksReportSetsBothSolvesSideBySide) {
  const auto r = run("catenary check-reduction " + quote(path("line.yaml").string()) + " --model " + quote(path("p.yaml").string()) +
                     " --set line.spans=4 --speed 250 --unit kmh --acceptance en50367-ac --report " + quote(path("c.html").string()));
  ASSERT_LE(r.code, 1) << r.err;  // 1: beyond the σ tolerance (the report is written either way)
  const std::string html = read_file(path("c.html"));
  const auto n = numbers("c.html");
  // the printed table's σ of each solve is the report's (4 decimals)
  for (const char* solve : {"direct", "modal"}) {
    const std::string key = std::string("v=250 km/h/") + solve + "/σ, N";
    ASSERT_TRUE(n.count(key)) << key;
    EXPECT_TRUE(contains(r.out, fmt_fixed4(n.at(key)))) << key << " " << r.out;
  }
  EXPECT_TRUE(contains(html, "<table id=\"comparison\">"));
  EXPECT_TRUE(contains(html, "<table id=\"verdicts\">"));
  EXPECT_TRUE(contains(html, r.code == 0 ? "<span class=\"status\">AGREE</span>" : "<span class=\"status\">DIFFER</span>"));
  const auto v = run("verify-report " + quote(path("c.html").string()));
  EXPECT_EQ(v.code, 0) << v.out << v.err;
}

}  // namespace test_apps_report_cli

namespace test_apps_report_cli {

// A run with --suspension draws that network in its report, with its values.
TEST_F(ReportCli, ARunsSuspensionIsDrawnInItsReport) {
  fs::copy_file(source("models/hsx.yaml"), path("hsx.yaml"));
  const auto r = run("sweep " + quote(path("hsx.yaml").string()) + " --catenary " + quote(path("line.yaml").string()) +
                     " --set line.spans=3 --speeds 200:1:200 --unit kmh --suspension 'k|c' --param k=1.4e5 --param c=1e4 --report " +
                     quote(path("r.html").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = read_file(path("r.html"));
  EXPECT_TRUE(contains(html, "class=\"schematic\""));
  EXPECT_TRUE(contains(html, "k = 140 kN/m")) << html.substr(0, 2000);
  EXPECT_TRUE(contains(html, "c = 10 kN·s/m"));
}

}  // namespace test_apps_report_cli

namespace test_apps_report_cli {

// Hostile options: a NaN or out-of-range tolerance, a hexadecimal element value, a report that is a device.
TEST_F(ReportCli, HostileOptionsAreUsageErrorsThatSayWhatIsExpected) {
  for (const char* rtol : {"nan", "-1", "2", "inf"}) {
    const auto r = run(std::string("verify-report x.html --rtol ") + rtol);
    EXPECT_EQ(r.code, 105) << rtol << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "a relative difference in [0, 1]")) << r.err;
  }
  auto r = run("networks draw 'k|c' --param k=0x10 --param c=1");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "hexadecimal")) << r.err;
  r = run("admittance 'k|c' --param k=0X1p4 --param c=1 --freq 1:1:2");
  EXPECT_EQ(r.code, 105) << r.err;
  r = run("verify-report /dev/zero");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "not a regular file")) << r.err;
}

}  // namespace test_apps_report_cli
