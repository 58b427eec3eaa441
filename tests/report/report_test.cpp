// Reports (report/*.hpp): the numbers record survives the HTML exactly, differences are found,
// SHA-256 against its published test vector, SVG plots and escaping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "inerta/error.hpp"
#include "inerta/report/html.hpp"
#include "inerta/report/record.hpp"
#include "inerta/report/svg_plot.hpp"

namespace test_report {

using namespace inerta::report;

Record sample() {
  Record r;
  r.command = "sweep";
  r.verdict = "FAIL";
  r.provenance.argv = {"inerta", "sweep", "m.yaml", "--report", "a b.html"};
  r.provenance.cwd = "/tmp";
  r.provenance.date = "2026-12-07T12:00:00Z";
  r.provenance.inputs = {{"m.yaml", "model file", std::string(64, 'a'), 12}};
  r.provenance.settings = {{"overrides", "line.note=</script><b>"}};
  r.add("a", 1.0 / 3.0);
  r.add("b", std::numeric_limits<double>::quiet_NaN());
  r.add("c", -std::numeric_limits<double>::infinity());
  r.add("d", 6.02214076e23);
  r.add("e", 5e-324);  // the smallest subnormal: 17 digits are needed and enough
  return r;
}

TEST(Report, TheRecordComesBackFromThePageBitForBit) {
  const Record r = sample();
  Document doc("t");
  doc.provenance(r.provenance);
  const std::string html = doc.html(r);
  EXPECT_EQ(html.find("</script><b>"), std::string::npos) << "a setting closed the record's block";
  const Record back = read_record(html, "x.html");
  EXPECT_EQ(back.command, "sweep");
  EXPECT_EQ(back.verdict, "FAIL");
  EXPECT_EQ(back.provenance.argv, r.provenance.argv);
  EXPECT_EQ(back.provenance.settings, r.provenance.settings);
  ASSERT_EQ(back.provenance.inputs.size(), 1u);
  EXPECT_EQ(back.provenance.inputs[0].sha256, r.provenance.inputs[0].sha256);
  ASSERT_EQ(back.numbers.size(), r.numbers.size());
  for (std::size_t i = 0; i < r.numbers.size(); ++i) {
    EXPECT_EQ(back.numbers[i].first, r.numbers[i].first);
    const double a = r.numbers[i].second, b = back.numbers[i].second;
    EXPECT_TRUE((std::isnan(a) && std::isnan(b)) || a == b) << r.numbers[i].first << ": " << a << " vs " << b;
  }
  EXPECT_TRUE(compare(r, back).empty());
}

TEST(Report, ADifferenceIsNamedWithBothValues) {
  const Record a = sample();
  Record b = a;
  b.numbers[0].second = 0.3334;
  b.numbers.pop_back();
  b.add("new", 2);
  const auto d = compare(a, b);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].key, "a");
  EXPECT_DOUBLE_EQ(d[0].reported, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(d[0].now, 0.3334);
  EXPECT_EQ(d[1].key, "e");
  EXPECT_EQ(d[1].missing, "not in the re-run");
  EXPECT_EQ(d[2].key, "new");
  EXPECT_EQ(d[2].missing, "not in the report");
  // within a relative tolerance the changed number is equal
  b = a;
  b.numbers[0].second = (1.0 / 3.0) * (1 + 1e-12);
  EXPECT_EQ(compare(a, b).size(), 1u);
  EXPECT_TRUE(compare(a, b, 1e-9).empty());
}

TEST(Report, ADamagedOrForeignPageIsAnErrorNamingTheFile) {
  try {
    read_record("<html><body>hello</body></html>", "page.html");
    FAIL();
  } catch (const inerta::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("page.html: not an Inerta report"), std::string::npos) << e.what();
  }
  std::string html = Document("t").html(sample());
  html.replace(html.find("\"numbers\""), 9, "\"numbrs\"");
  try {
    read_record(html, "bad.html");
    FAIL();
  } catch (const inerta::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.html: the inerta-record block is damaged"), std::string::npos) << e.what();
  }
  std::string cut = Document("t").html(sample());
  cut.resize(cut.find("\"numbers\""));
  EXPECT_THROW(read_record(cut, "cut.html"), inerta::ModelError);
}

// FIPS 180-2, appendix B: the digests of "abc" and of the empty message.
TEST(Report, Sha256GivesThePublishedDigests) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Report, ShellQuotingKeepsEachArgumentOne) {
  EXPECT_EQ(shell_quoted({"inerta", "networks", "draw", "k1|(k2-c-b)", "--param", "k1=5e5", "it's"}),
            "inerta networks draw 'k1|(k2-c-b)' --param k1=5e5 'it'\\''s'");
}

TEST(Report, TextIsEscapedAndTheVerdictLeads) {
  EXPECT_EQ(escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  Document doc("Title <x>");
  doc.paragraph("body");
  doc.verdict("FAIL", {"Failed: sigma"});
  const std::string html = doc.html(sample());
  EXPECT_NE(html.find("<h1>Title &lt;x&gt;</h1>"), std::string::npos);
  // the banner comes right after the title, before the body, whatever order it was given in
  const auto banner = html.find("class=\"verdict FAIL\""), body = html.find("<p>body</p>");
  ASSERT_NE(banner, std::string::npos);
  EXPECT_LT(banner, body);
  EXPECT_LT(html.find("<h1>"), banner);
}

TEST(Report, TicksAreRoundAndCoverTheRange) {
  EXPECT_EQ(nice_ticks(0, 10, 6), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(nice_ticks(196, 304, 6), (std::vector<double>{200, 225, 250, 275, 300}));
  const auto t = nice_ticks(-0.013, 0.052, 6);
  ASSERT_FALSE(t.empty());
  EXPECT_GE(t.front(), -0.013);
  EXPECT_LE(t.back(), 0.052);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_NEAR(t[i] - t[i - 1], 0.02, 1e-12);  // a range of 0.065 in about 6 ticks
}

TEST(Report, APlotDrawsEachSeriesBandAndMark) {
  Plot p("F & σ", "v, km/h", "N");
  PlotSeries s("F_m", "#123456", false, true);
  s.x = {200, 250, 300};
  s.y = {100, NAN, 120};  // a gap: two pieces of one path
  p.series.push_back(s);
  PlotBand b;
  b.name = "band";
  b.x = {200, 300}, b.lower = {80, 90}, b.upper = {110, 130};
  p.bands.push_back(b);
  p.marks.push_back({250, "mast"});
  p.marks.push_back({1000, "mast"});  // outside the axes: not drawn
  p.ranges.push_back({220, 240, "overlap", "overlap"});
  const std::string svg = svg_plot(p);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("F &amp; σ"), std::string::npos);
  EXPECT_NE(svg.find("data-name=\"F_m\" d=\"M"), std::string::npos);
  const auto path = svg.substr(svg.find("data-name=\"F_m\""));
  EXPECT_EQ(std::count(path.begin(), path.begin() + static_cast<long>(path.find("/>")), 'M'), 2);
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') > 5, true);
  std::size_t masts = 0;
  for (std::size_t at = 0; (at = svg.find("class=\"mark mast\"", at)) != std::string::npos; ++at) ++masts;
  EXPECT_EQ(masts, 1u);
  EXPECT_NE(svg.find("class=\"range overlap\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"band\""), std::string::npos);
  EXPECT_NE(svg_plot(Plot("empty")).find("no data"), std::string::npos);
}

}  // namespace test_report

#include "inerta/network/network.hpp"
#include "inerta/report/study_report.hpp"

namespace test_report {

// A study's page: the recommended design's acceptance over its margins — a PASS names the criteria it could
// not assess; a failing margin makes it FAIL; every ranked design is drawn as built.
TEST(Report, AStudysVerdictNamesWhatItCouldNotAssess) {
  using namespace inerta;
  optim::StudyOutcome o;
  o.study = optim::Study{};
  o.study->name = "synthetic";
  o.baseline = network::parse("k-c");
  o.default_cost.J = 10;
  optim::LayoutResult r;
  r.layout = r.expression = "k|c";
  r.values = {{"k", 1e5}, {"c", 0}};
  r.cost.J = 8;
  o.results = {r};
  o.best.layout = o.best.expression = "k|c";
  o.best.J = 8;
  o.report = optim::Report{};
  o.report->best.label = "best (k|c)";
  o.report->acceptance = "en50367-ac";
  auto row = [](const char* criterion, bool assessed, bool passed) {
    optim::MarginRow m;
    m.design = "best (k|c)";
    m.catenary = "line";
    m.speed = 250 / 3.6;
    m.result.criterion = criterion;
    m.result.assessed = assessed, m.result.passed = passed;
    m.result.value = 1, m.result.limit = 2, m.result.margin = 1;
    return m;
  };
  o.report->margins = {row("sigma", true, true), row("support_uplift", false, false)};
  Record rec;
  std::string html = study_report({}, o, rec);
  EXPECT_EQ(rec.verdict, "PASS");
  EXPECT_NE(html.find("PASS; not assessed: support_uplift."), std::string::npos);
  EXPECT_NE(html.find("k = 100 kN/m"), std::string::npos) << "drawn with its value";
  EXPECT_EQ(html.find("data-name=\"c\""), std::string::npos) << "c = 0 is open: left out of the drawing as built";
  o.report->margins.push_back(row("max_force", true, false));
  html = study_report({}, o, rec = Record{});
  EXPECT_EQ(rec.verdict, "FAIL");
  EXPECT_NE(html.find("FAIL (max_force); not assessed: support_uplift."), std::string::npos);
  o.report->margins = {row("support_uplift", false, false)};
  study_report({}, o, rec = Record{});
  EXPECT_EQ(rec.verdict, "NOT ASSESSED");
}

}  // namespace test_report
