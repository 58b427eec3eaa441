// A network drawn as a schematic (issue 53): one drawn element per element of the network, of its kind
// and with its value in the unit an engineer reads; parallel branches stacked, series side by side.
#include "inerta/network/schematic.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "inerta/network/enumeration.hpp"
#include "inerta/network/layouts.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_network_schematic {

using namespace inerta::network;

namespace {
int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}
double attribute(const std::string& svg, const std::string& name) {
  std::smatch m;
  const std::regex re(name + "=\"([0-9.]+)\"");
  if (!std::regex_search(svg, m, re)) return -1;
  return std::stod(m[1]);
}
}  // namespace

TEST(Schematic, EveryElementIsDrawnOnceWithItsKindAndValue) {
  const Network n = resolve("k1|(k2-c-b)", {{"k1", 5.285e5}, {"k2", 1.671e5}, {"c", 6.19e4}, {"b", 526.5}});
  const std::string svg = schematic_svg(n);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u) << svg.substr(0, 80);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"element spring\""), 2);
  EXPECT_EQ(count(svg, "class=\"element damper\""), 1);
  EXPECT_EQ(count(svg, "class=\"element inerter\""), 1);
  for (const char* label : {"k1 = 528 kN/m", "k2 = 167 kN/m", "c = 61.9 kN·s/m", "b = 526 kg"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_NE(svg.find("<title>k1|(k2-c-b)</title>"), std::string::npos);
  EXPECT_EQ(count(svg, "<g "), count(svg, "</g>"));
}

TEST(Schematic, ParallelStacksAndSeriesLinesUp) {
  // Three elements in series are three times as wide as one (and gaps), as high; in parallel as wide
  // (and the bars' leads), about three times as high.
  auto size = [](const std::string& e) {
    const std::string svg = schematic_svg(parse(e));
    return std::pair{attribute(svg, "width"), attribute(svg, "height")};
  };
  const auto one = size("k"), series = size("k-c-b"), parallel = size("k|c|b");
  EXPECT_GT(series.first, 2.5 * (one.first - 60));
  EXPECT_EQ(series.second, one.second);
  EXPECT_LT(parallel.first, one.first + 40);
  EXPECT_GT(parallel.second - 62, 2.5 * (one.second - 62));
}

TEST(Schematic, EveryNetworkOfUpToFourElementsDraws) {
  // Names only (values not assigned), each element once, the tags balanced, for all 119 networks.
  EnumerationOptions o;
  o.max_elements = 4;
  const auto all = enumerate(o);
  ASSERT_GT(all.size(), 100u);
  for (const std::string& e : all) {
    const Network n = parse(e);
    const std::string svg = schematic_svg(n);
    const auto c = count_elements(n);
    EXPECT_EQ(count(svg, "class=\"element "), c.elements) << e;
    EXPECT_EQ(count(svg, "<g "), count(svg, "</g>")) << e;
    EXPECT_EQ(svg.find(" = "), std::string::npos) << e;  // no value where none was assigned
  }
}

TEST(Schematic, OpenRigidAndEscapedTitles) {
  const Network open = simplify(resolve("k-c", {{"k", 0}, {"c", 1}}));
  EXPECT_NE(schematic_svg(open).find(">open<"), std::string::npos);
  const std::string svg = schematic_svg(parse("k"), {.values = true, .title = "a <b> & c"});
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
}

}  // namespace test_network_schematic
