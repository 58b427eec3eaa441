// The enumeration of series–parallel networks (docs/networks.md) against an independent brute
// force: every labelled binary tree of series/parallel joins over element types, reduced by
// canonical(), counted per number of elements.
#include "inerta/network/enumeration.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_network_enumeration {

using namespace inerta::network;
using K = Network::Kind;

namespace {
// All binary trees with exactly n leaves drawn from `types`, internal nodes series or parallel.
std::vector<Network> binary_trees(int n, const std::vector<K>& types) {
  std::vector<Network> out;
  if (n == 1) {
    for (K t : types) out.push_back(Network{t, "x", 1.0, {}, 0});
    return out;
  }
  for (int a = 1; a < n; ++a)
    for (const auto& l : binary_trees(a, types))
      for (const auto& r : binary_trees(n - a, types))
        for (K j : {K::Series, K::Parallel}) out.push_back(Network{j, "", 0, {l, r}, 0});
  return out;
}

// structure → element count, over all trees with up to n leaves (merging can only shrink them).
std::map<std::string, ElementCounts> brute_force(int n, const std::vector<K>& types) {
  std::map<std::string, ElementCounts> seen;
  for (int m = 1; m <= n; ++m)
    for (const auto& t : binary_trees(m, types)) seen.emplace(structure(t), count_elements(canonical(t)));
  return seen;
}

std::map<int, int> per_size(const std::vector<std::string>& expressions) {
  std::map<int, int> c;
  for (const auto& e : expressions) ++c[count_elements(parse(e)).elements];
  return c;
}
}  // namespace

TEST(Enumeration, CountsEqualTheBruteForceOverLabelledTrees) {
  const auto brute = brute_force(5, {K::Spring, K::Damper, K::Inerter});
  std::map<int, int> expected;
  for (const auto& [s, c] : brute) ++expected[c.elements];
  EnumerationOptions o;
  o.max_elements = 5;
  const auto nets = enumerate(o);
  EXPECT_EQ(per_size(nets), expected);
  // By hand: 3 single elements; 3 pairs of distinct types, each in series or in parallel.
  EXPECT_EQ(expected[1], 3);
  EXPECT_EQ(expected[2], 6);
  // The same set of structures, each once.
  std::set<std::string> mine;
  for (const auto& e : nets) EXPECT_TRUE(mine.insert(structure(parse(e))).second) << e;
  std::set<std::string> theirs;
  for (const auto& [s, c] : brute) theirs.insert(s);
  EXPECT_EQ(mine, theirs);
}

TEST(Enumeration, EveryExpressionParsesRoundTripsAndIsCanonical) {
  EnumerationOptions o;
  o.max_elements = 5;
  for (const auto& e : enumerate(o)) {
    const Network n = parse(e);
    EXPECT_EQ(to_string(n), e);
    const auto names = parameter_names(n);
    EXPECT_EQ(static_cast<int>(names.size()), count_elements(n).elements) << e;  // names unique
    EXPECT_EQ(count_elements(canonical(n)).elements, count_elements(n).elements) << e;  // nothing to merge
    EXPECT_EQ(to_string(canonical(n)), e);  // already in canonical order
  }
}

TEST(Enumeration, OptionsFilterAsTheBruteForceDoes) {
  // Springs and dampers only.
  {
    const auto brute = brute_force(5, {K::Spring, K::Damper});
    std::map<int, int> expected;
    for (const auto& [s, c] : brute) ++expected[c.elements];
    EnumerationOptions o;
    o.max_elements = 5, o.inerters = false;
    EXPECT_EQ(per_size(enumerate(o)), expected);
  }
  const auto brute = brute_force(5, {K::Spring, K::Damper, K::Inerter});
  auto expect = [&](const EnumerationOptions& o, const std::function<bool(const std::string&, const ElementCounts&)>& keep) {
    std::map<int, int> expected;
    for (const auto& [s, c] : brute)
      if (keep(s, c)) ++expected[c.elements];
    EXPECT_EQ(per_size(enumerate(o)), expected);
  };
  EnumerationOptions o;
  o.max_elements = 5, o.max_inerters = 1;
  expect(o, [](const std::string&, const ElementCounts& c) { return c.inerters <= 1; });
  o.max_inerters = -1, o.max_dampers = 1, o.max_springs = 2;
  expect(o, [](const std::string&, const ElementCounts& c) { return c.dampers <= 1 && c.springs <= 2; });
  o = EnumerationOptions{};
  o.max_elements = 5, o.static_load = StaticLoad::Required;
  expect(o, [](const std::string& s, const ElementCounts&) { return static_path(parse(s)); });
}

TEST(Enumeration, StaticPath) {
  EXPECT_TRUE(static_path(parse("k")));
  EXPECT_FALSE(static_path(parse("k-c")));
  EXPECT_TRUE(static_path(parse("k|c")));
  EXPECT_TRUE(static_path(parse("(k-k1)|b")));
  EXPECT_FALSE(static_path(parse("(k|b)-c")));
  EnumerationOptions o;
  o.max_elements = 4, o.static_load = StaticLoad::Excluded;
  for (const auto& e : enumerate(o)) EXPECT_FALSE(static_path(parse(e))) << e;
}

TEST(Canonical, MergesValuesAndKeepsTheAdmittance) {
  // k1|k2 = one spring of k1 + k2; c1-c2 one damper of c1c2/(c1+c2); members reordered.
  const Network n = assign(parse("(b|k1|k2)-c1-c2"), {{"k1", 1000}, {"k2", 3000}, {"c1", 200}, {"c2", 300}, {"b", 5}});
  const Network c = canonical(n);
  EXPECT_EQ(to_string(renamed(c)), "c-(k|b)");
  EXPECT_EQ(count_elements(c).elements, 3);
  EXPECT_DOUBLE_EQ(c.children[0].value, 200.0 * 300 / 500);
  EXPECT_DOUBLE_EQ(c.children[1].children[0].value, 4000.0);
  for (double w : {0.1, 1.0, 7.0, 60.0}) {
    const std::complex<double> s(0, w);
    EXPECT_NEAR(std::abs(admittance(c, s) - admittance(n, s)), 0.0, 1e-12 * std::abs(admittance(n, s)));
  }
  EXPECT_EQ(structure(parse("c|(b-k)|k1")), structure(parse("k|(k1-b)|c")));
  EXPECT_NE(structure(parse("k-(k1|c)")), structure(parse("k|(k1-c)")));
  EXPECT_EQ(to_string(renamed(parse("k9-(c|k3)"))), "k1-(c|k2)");
  EXPECT_THROW(canonical(simplify(assign(parse("k-c"), {{"k", 0}, {"c", 1}}))), NetworkError);
}

TEST(Enumeration, RefusesOptionsOutOfRange) {
  EnumerationOptions o;
  o.max_elements = 0;
  EXPECT_THROW(enumerate(o), NetworkError);
  o.max_elements = max_enumerated_elements + 1;
  EXPECT_THROW(enumerate(o), NetworkError);
  o.max_elements = 3, o.springs = o.dampers = o.inerters = false;
  EXPECT_THROW(enumerate(o), NetworkError);
  o = EnumerationOptions{};
  o.max_inerters = -2;
  EXPECT_THROW(enumerate(o), NetworkError);
}
}  // namespace test_network_enumeration
