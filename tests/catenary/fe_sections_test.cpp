// Lines of tension sections with overlaps (issue 35, docs/catenary-fe.md "Tension sections and
// overlaps"): a section away from its overlap is the single-section line; every section's static
// state is an equilibrium; with the other wire out of reach a pantograph sees only its own; the load
// passes from one wire to the other over the overlap's middle span, their sum the contact force;
// modal = direct; bad input names the file and key.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_catenary_fe_sections {

using namespace inerta;
using catenary::FeCatenaryData;
using catenary::FeLine;

const std::string kOverlap = INERTA_SOURCE_DIR "/models/catenary-fe-overlap.yaml";

// The bundled line's design on two sections of `spans` spans each (a 3-span overlap). With
// `at_supports`, the overlap of issue 35 instead of the bundled profile: heights at the supports
// alone, the out-of-running wire 0.2 m up at the support on its anchor side and 0.5 m at its anchor
// (linear between the masts: the wires cross 0.1 m up in the middle span).
FeCatenaryData two_sections(int spans, const std::vector<std::string>& sets = {}, bool at_supports = false) {
  FeCatenaryData d = io::read_fe_catenary_data(kOverlap, sets);
  d.tension_sections.resize(2);
  for (FeCatenaryData& s : d.tension_sections) s.spans = spans;
  if (at_supports) {
    d.overlap_outgoing = {0, 0, 0.2, 0.5}, d.overlap_incoming = {0.5, 0.2, 0, 0};
    d.overlap_outgoing_x.clear(), d.overlap_incoming_x.clear();
  }
  d.join_sections();
  return d;
}

TEST(FeSections, AwayFromItsOverlapASectionIsTheSingleSectionLine) {
  // Section 1 of the bundled line (12 spans, its last 3 in the overlap, raised towards its anchor)
  // against the stitched line of 12 spans with no overlap: in spans 1–5 the form-finding gives the
  // same heights, dropper tensions and lengths to round-off. (Nearer the overlap the stitch wires,
  // which carry load across each mast, pass the raised spans' influence on, ≈ 100 × weaker a span:
  // 5e-9 m in span 7, 6e-3 m in span 10.)
  const FeCatenaryData line = io::read_fe_catenary_data(kOverlap, {});
  const std::vector<catenary::FeLinkedSection> linked = catenary::link_sections(line);
  const FeCatenaryData& sec = linked.front().line;
  ASSERT_EQ(sec.spans, 12);
  EXPECT_TRUE(line.tension_sections.front().mast_height.empty());  // the data as written: the pass placed a copy
  ASSERT_EQ(sec.mast_height.back(), 0.5);
  FeCatenaryData plain = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml", {"line.spans=12"});
  const FeLine a(sec), b(plain);
  ASSERT_EQ(a.n_dofs(), b.n_dofs());
  ASSERT_EQ(a.droppers().size(), b.droppers().size());
  const double far = 5 * sec.span;
  for (double x = 0; x <= far; x += 1.3) EXPECT_NEAR(a.static_height(x), b.static_height(x), 1e-9) << x;
  int compared = 0;
  for (std::size_t k = 0; k < a.droppers().size(); ++k) {
    if (a.droppers()[k].x > far) break;
    EXPECT_NEAR(a.droppers()[k].tension, b.droppers()[k].tension, 1e-8 * b.droppers()[k].tension) << k;
    EXPECT_NEAR(a.droppers()[k].length, b.droppers()[k].length, 1e-11) << k;
    ++compared;
  }
  EXPECT_GE(compared, 5 * static_cast<int>(sec.dropper_x.size() + sec.stitch.dropper_x.size()));
  // And the overlap's masts are where the file puts them: the contact wire at its mast heights.
  for (int m = 9; m <= 12; ++m) EXPECT_NEAR(a.static_height(m * sec.span), sec.mast_height[static_cast<std::size_t>(m)], 1e-9) << m;
}

TEST(FeSections, EverySectionsStaticStateIsAnEquilibrium) {
  const FeCatenaryData line = io::read_fe_catenary_data(kOverlap, {});
  ASSERT_EQ(line.tension_sections.size(), 3u);
  const std::vector<catenary::FeLinkedSection> linked = catenary::link_sections(line);
  for (const catenary::FeLinkedSection& ls : linked) {
    const FeCatenaryData& s = ls.line;
    const FeLine L(s);
    const FeLine::Residual r = L.equilibrium_residual();
    EXPECT_LT(r.force, 1e-8 * r.load_scale) << ls.first_span;
    EXPECT_LT(r.dropper, 1e-6) << ls.first_span;
    // Pre-sag 0: the contact wire at its height profile at every dropper and mast.
    for (const FeLine::Dropper& dr : L.droppers()) EXPECT_NEAR(L.static_height(dr.x), s.height_at(dr.x), 1e-9) << dr.x;
    for (int m = 0; m <= s.spans; ++m)
      EXPECT_NEAR(L.static_height(m * s.span), s.mast_height[static_cast<std::size_t>(m)], 1e-9) << m;
  }
  // A tensioning device at the anchors instead of pins: still an equilibrium, the ends at their heights.
  FeCatenaryData s = linked[1].line;
  s.anchor = {false, 2e5, 30};
  const FeLine L(s);
  const FeLine::Residual r = L.equilibrium_residual();
  EXPECT_LT(r.force, 1e-8 * r.load_scale);
  EXPECT_NEAR(L.static_height(0), s.mast_height.front(), 1e-9);
  EXPECT_NEAR(L.static_height(L.length()), s.mast_height.back(), 1e-9);
}

// The 3-mass on a line at 250 km/h to t_end (direct solve), histories kept.
analysis::CoupledSimulation run(const FeCatenaryData& d, double t_end) {
  const catenary::FeCatenary cat(d);
  const auto panto = io::load_pantograph(INERTA_SOURCE_DIR "/models/pantograph-3mass.yaml");
  analysis::CoupledOptions o;
  o.t_end = t_end;
  o.sample = 1e-3;
  return analysis::simulate_coupled({{panto, 0.0, {catenary::Contact::Kind::Penalty, 50e3, 0.0}}}, cat, 250 / 3.6, o);
}

std::vector<double> column(const analysis::CoupledSimulation& r, const std::string& name) {
  const auto& h = r.histories.front();
  const auto it = std::find(h.names.begin(), h.names.end(), name);
  if (it == h.names.end()) throw InvalidArgument("no column " + name);
  return h.columns[static_cast<std::size_t>(it - h.names.begin())];
}

TEST(FeSections, WithTheOtherWireOutOfReachThePantographSeesOnlyItsOwn) {
  // Two sections of 6 spans, the incoming wire raised 0.5 m and 0.2 m over the overlap's first span:
  // a run that ends before the middle span equals a run on section 1 alone (the same section as a
  // line of its own) to round-off, and the incoming wire carries nothing.
  const FeCatenaryData d = two_sections(6, {}, true);
  const double span = d.span, t_end = (4 * span - 1) / (250 / 3.6);  // the contact point short of mast 4 (o1)
  FeCatenaryData alone = catenary::link_sections(d).front().line;
  const auto both = run(d, t_end), one = run(alone, t_end);
  const auto F2 = column(both, "F_contact"), F1 = column(one, "F_contact"), w2 = column(both, "F_contact_w2");
  ASSERT_EQ(F1.size(), F2.size());
  for (std::size_t i = 0; i < F1.size(); ++i) {
    EXPECT_NEAR(F2[i], F1[i], 1e-9 * std::max(1.0, std::abs(F1[i]))) << i;
    EXPECT_EQ(w2[i], 0.0) << i;
  }
}

TEST(FeSections, TheLoadPassesFromOneWireToTheOtherOverTheMiddleSpan) {
  // Through the whole overlap of two 6-span sections (issue 35's heights at the supports): before its
  // middle span only wire 1 carries the pantograph, after it only wire 2; in the middle span both,
  // over a stretch, their sum the contact force, the share of wire 2 growing from 0 to 1.
  const FeCatenaryData d = two_sections(6, {}, true);
  const double span = d.span;
  const auto r = run(d, (8 * span) / (250 / 3.6));
  const auto F = column(r, "F_contact"), f1 = column(r, "F_contact_w1"), f2 = column(r, "F_contact_w2"), x = column(r, "x_contact");
  const double o1 = 4 * span, o2 = 5 * span;  // the middle span of the overlap (masts 3…6)
  int both = 0;
  double first_both = INFINITY, last_both = -INFINITY, max_jump = 0;
  for (std::size_t i = 0; i < F.size(); ++i) {
    EXPECT_NEAR(f1[i] + f2[i], F[i], 1e-9 * std::max(1.0, std::abs(F[i]))) << x[i];
    if (x[i] < o1) {
      EXPECT_EQ(f2[i], 0.0) << x[i];
    }
    if (x[i] > o2) {
      EXPECT_EQ(f1[i], 0.0) << x[i];
    }
    if (f1[i] > 0 && f2[i] > 0) ++both, first_both = std::min(first_both, x[i]), last_both = std::max(last_both, x[i]);
    if (i > 0) max_jump = std::max(max_jump, std::abs(F[i] - F[i - 1]));
  }
  std::fprintf(stderr, "both wires loaded over %.2f … %.2f m (%d samples); largest change of F in a sample %.2f N\n",
               first_both, last_both, both, max_jump);
  EXPECT_GT(both, 20);
  EXPECT_GT(first_both, o1);
  EXPECT_LT(last_both, o2);
  // Continuous: no sample-to-sample change of the total beyond what the plain spans show.
  double plain_jump = 0;
  for (std::size_t i = 1; i < F.size(); ++i)
    if (x[i] < 3 * span && x[i] > span) plain_jump = std::max(plain_jump, std::abs(F[i] - F[i - 1]));
  EXPECT_LT(max_jump, 3 * plain_jump + 5);
}

TEST(FeSections, TheBundledOverlapLineIsTheStitchedLine) {
  // Issue 48: every section of the bundled overlap line is the calibrated stitched line: the two
  // files' text from `line:` on is the same, but for the stitched file's number of spans.
  auto text = [](const std::string& path) {
    std::ifstream in(path);
    std::string t((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return t.substr(t.find("\nline:"));
  };
  std::string stitched = text(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml");
  const std::string spans = "  spans: 10               # [assumed]\n";
  const auto at = stitched.find(spans);
  ASSERT_NE(at, std::string::npos);
  stitched.erase(at, spans.size());
  EXPECT_EQ(text(kOverlap), stitched);
}

TEST(FeSections, TheBundledOverlapHasBothWiresAtTheRunningHeightOverHalfItsMiddleSpan) {
  // Issue 48: the bundled profile (Adif NAE 116's rule: both wires at the running height over 50 … 100 %
  // of the middle span): at every dropper of the middle 50 % both wires are at 0; the out-of-running
  // wire above the running one elsewhere in the overlap, and every dropper in tension (the rise
  // within what gravity lets a wire that droppers only pull take).
  const FeCatenaryData line = io::read_fe_catenary_data(kOverlap, {});
  const std::vector<catenary::FeLinkedSection> linked = catenary::link_sections(line);
  const FeCatenaryData &out = linked[0].line, &in = linked[1].line;
  const double span = line.span, o0 = (out.spans - 3) * span;  // the overlap's first support, along the line
  const FeLine a(out), b(in);
  int common = 0;
  for (const FeLine* l : {&a, &b}) {
    const double shift = l == &a ? 0.0 : o0;  // section 2 starts at the overlap's first support
    for (const FeLine::Dropper& dr : l->droppers()) {
      const double s = dr.x + shift - o0;  // from the overlap's first support
      if (s < 0 || s > 3 * span) continue;
      EXPECT_GT(dr.tension, 10.0) << s;
      if (s >= 1.25 * span && s <= 1.75 * span) {
        EXPECT_NEAR(l->static_height(dr.x), 0.0, 1e-9) << s;
        ++common;
      }
    }
  }
  EXPECT_EQ(common, 2 * 5);  // the five span droppers of the middle span, on each wire
  for (double s = 0; s <= 3 * span; s += 2.5) {
    const double za = a.static_height(o0 + s), zb = b.static_height(s);
    if (s < 1.25 * span) {
      EXPECT_GT(zb, za - 1e-9) << s;  // the incoming wire out of running before
    }
    if (s > 1.75 * span) {
      EXPECT_GT(za, zb - 1e-9) << s;  // the outgoing one after
    }
  }
  // Through the overlap (two 6-span sections, the 3-mass at 250 km/h, direct solve): the force passes
  // from wire 1 to wire 2 with both loaded over the whole common stretch, their sum the force.
  const FeCatenaryData d = two_sections(6);
  const auto r = run(d, 8 * span / (250 / 3.6));
  const auto F = column(r, "F_contact"), f1 = column(r, "F_contact_w1"), f2 = column(r, "F_contact_w2"), x = column(r, "x_contact");
  double first_both = INFINITY, last_both = -INFINITY;
  for (std::size_t i = 0; i < F.size(); ++i) {
    EXPECT_NEAR(f1[i] + f2[i], F[i], 1e-9 * std::max(1.0, std::abs(F[i]))) << x[i];
    if (x[i] < 3 * span) {
      EXPECT_EQ(f2[i], 0.0) << x[i];
    }
    if (x[i] > 6 * span) {
      EXPECT_EQ(f1[i], 0.0) << x[i];
    }
    if (f1[i] > 0 && f2[i] > 0) first_both = std::min(first_both, x[i]), last_both = std::max(last_both, x[i]);
  }
  std::fprintf(stderr, "bundled overlap: both wires loaded over %.2f … %.2f m (common stretch %.2f … %.2f m)\n", first_both,
               last_both, 4.25 * span, 4.75 * span);
  EXPECT_LE(first_both, 4.25 * span);
  EXPECT_GE(last_both, 4.75 * span);
}

TEST(FeSections, ModalIsTheDirectSolveWithinTwoPercentInTheOverlapsToo) {
  // Two sections of 7 spans (11 spans, one overlap), the 3-mass at 250 km/h and the HSX at 300 km/h
  // (issue 52: the test suite's budget, one direct solve a speed): σ raw and after the 20 Hz low-pass,
  // over the section and over the overlap spans alone.
  FeCatenaryData modal = two_sections(7), direct = modal;
  direct.solver = FeCatenaryData::Solver::Direct;
  for (FeCatenaryData& s : direct.tension_sections) s.solver = FeCatenaryData::Solver::Direct;
  ASSERT_EQ(modal.solver, FeCatenaryData::Solver::Modal);
  const catenary::FeCatenary dc(direct), mc(modal);
  for (const char* model : {"pantograph-3mass.yaml", "hsx.yaml"}) {
    const auto panto = io::load_pantograph(std::string(INERTA_SOURCE_DIR "/models/") + model);
    const std::vector<double> speeds = model == std::string("hsx.yaml") ? std::vector<double>{300 / 3.6}
                                                                         : std::vector<double>{250 / 3.6};
    const auto rows = analysis::compare({{panto, 0.0, {catenary::Contact::Kind::Penalty, 50e3, 0.0}}}, dc, mc, speeds, {});
    for (const auto& r : rows) {
      const auto& a = r.reference;
      const auto& b = r.candidate;
      ASSERT_EQ(a.overlap.size(), 1u);
      std::fprintf(stderr, "%s %.0f km/h: sigma %.3f / %.3f, 20 Hz %.3f / %.3f, overlap %.3f / %.3f, 20 Hz %.3f / %.3f N\n",
                   model, r.speed * 3.6, a.stats.std, b.stats.std, a.filtered[0].std, b.filtered[0].std, a.overlap[0].std,
                   b.overlap[0].std, a.overlap_filtered[0].std, b.overlap_filtered[0].std);
      EXPECT_NEAR(b.stats.std, a.stats.std, 0.02 * a.stats.std) << model << r.speed;
      EXPECT_NEAR(b.filtered[0].std, a.filtered[0].std, 0.02 * a.filtered[0].std) << model << r.speed;
      EXPECT_NEAR(b.overlap[0].std, a.overlap[0].std, 0.02 * a.overlap[0].std) << model << r.speed;
      EXPECT_NEAR(b.overlap_filtered[0].std, a.overlap_filtered[0].std, 0.02 * a.overlap_filtered[0].std) << model << r.speed;
    }
  }
}

TEST(FeSectionsErrors, NameTheFileAndKey) {
  // Each case edits one line of the bundled file's text.
  struct Case {
    const char* name;
    const char* from;
    const char* to;
    const char* key;
  };
  const Case cases[] = {
      {"shared", "  - {spans: 13, anchors: pinned}", "  - {spans: 13, span: 60, anchors: pinned}", "tension_sections[1].span"},
      {"longer", "  - {spans: 13, anchors: pinned}", "  - {spans: 6, anchors: pinned}", "tension_sections[1].spans"},
      {"endlonger", "  - {spans: 12, anchors: pinned}   # [assumed]\n  - {spans: 13", "  - {spans: 3, anchors: pinned}\n  - {spans: 13", "tension_sections[0].spans"},
      {"below", "  incoming: [0.5, 0.2, 0, 0]", "  incoming: [0.5, -0.1, 0, 0]", "overlap.incoming[1]"},
      {"outbelow", "  outgoing: [0, 0, 0.2, 0.5]", "  outgoing: [0, 0, 0.2, -0.1]", "overlap.outgoing[3]"},
      {"count", "  outgoing: [0, 0, 0.2, 0.5]", "  outgoing: [0, 0.2, 0.5]", "overlap.outgoing"},
      {"anchor", "  - {spans: 13, anchors: pinned}", "  - {spans: 13}", "anchors"},
      {"anchorkind", "  - {spans: 13, anchors: pinned}", "  - {spans: 13, anchors: welded}", "anchors"},
      {"nooverlap", "overlap:", "overlapx:", "overlap"},
  };
  // The bundled file with issue 35's overlap heights at the supports (a list each), and as it is (a
  // profile each: {x, z}).
  std::ifstream in(kOverlap);
  const std::string bundled((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto o = bundled.find("  outgoing:"), l = bundled.find("\nline:");
  ASSERT_NE(o, std::string::npos);
  ASSERT_NE(l, std::string::npos);
  const std::string lists = bundled.substr(0, o) + "  outgoing: [0, 0, 0.2, 0.5]\n  incoming: [0.5, 0.2, 0, 0]" + bundled.substr(l);
  const Case profile_cases[] = {
      {"pbelow", "0.0342, 0.02, 0.00959, 0, 0, 0]", "0.0342, -0.02, 0.00959, 0, 0, 0]", "overlap.incoming.z"},
      {"porder", "113.75, 125,", "125, 113.75,", "overlap.outgoing.x[3]"},
      {"pend", "177.5, 190, 195]", "177.5, 190, 200]", "overlap.outgoing.x"},
      {"pcount", "0.44036, 0.5]", "0.44036]", "overlap.outgoing.z"},
      {"pkey", "    x: [0, 65, 113.75", "    xs: [0, 65, 113.75", "overlap.outgoing"},
  };
  for (const auto& [text, list] : {std::pair{lists, std::span<const Case>(cases)}, std::pair{bundled, std::span<const Case>(profile_cases)}}) {
    for (const Case& c : list) {
      SCOPED_TRACE(c.name);
      const auto at = text.find(c.from);
      ASSERT_NE(at, std::string::npos) << c.from;
      std::string t = text;
      t.replace(at, std::string(c.from).size(), c.to);
      const std::filesystem::path dir = std::filesystem::temp_directory_path() / fmt::format("inerta-badsec-{}-{}", c.name, ::getpid());
      std::filesystem::create_directories(dir);
      const std::string path = (dir / "bad.yaml").string();
      std::ofstream(path) << t;
      try {
        (void)io::read_fe_catenary_data(path, {});
        ADD_FAILURE() << "no error";
      } catch (const ModelError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path + ":"), std::string::npos) << what;
        EXPECT_NE(what.find(c.key), std::string::npos) << what;
        if (list.data() == profile_cases) {  // at the line edited
          EXPECT_NE(what.find(fmt::format("{}:{}:", path, 1 + std::count(t.begin(), t.begin() + static_cast<long>(at), '\n'))),
                    std::string::npos)
              << what;
        }
      }
      std::filesystem::remove_all(dir);
    }
  }
}

}  // namespace test_catenary_fe_sections
