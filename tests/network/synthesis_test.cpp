// Synthesis of networks from PR admittances (docs/synthesis.md): the returned network's own
// admittance, evaluated on its tree, must equal the target at many frequencies.
#include "inerta/network/synthesis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "inerta/network/enumeration.hpp"
#include "inerta/network/positive_real.hpp"
#include "network_random.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_network_synthesis {

using namespace inerta::network;
using cd = std::complex<double>;

namespace {
// Max relative error of the synthesised admittance over 120 log-spaced frequencies, with the
// structural checks: positive finite values, unique names, to_string/parse round trip.
double check(const Rational& y, const Synthesis& s, double wlo = 1e-3, double whi = 1e3) {
  double err = 0;
  for (double w : log_grid(wlo, whi, 120)) {
    const cd target = y(cd(0, w));
    err = std::max(err, std::abs(admittance(s.network, cd(0, w)) - target) / std::abs(target));
  }
  Params values;
  auto walk = [&](auto&& self, const Network& n) -> void {
    if (n.is_element()) {
      EXPECT_TRUE(n.value > 0 && std::isfinite(n.value)) << n.name << " = " << n.value;
      EXPECT_TRUE(values.emplace(n.name, n.value).second) << "duplicate name " << n.name;
    }
    for (const auto& c : n.children) self(self, c);
  };
  walk(walk, s.network);
  const Network back = assign(parse(to_string(s.network)), values);
  for (double w : {0.0123, 1.234, 123.4}) EXPECT_EQ(admittance(back, cd(0, w)), admittance(s.network, cd(0, w)));
  const ElementCounts c = count_elements(s.network);
  EXPECT_EQ(s.elements, c.elements);
  EXPECT_EQ(s.reactive, c.springs + c.inerters);
  EXPECT_GE(s.reactive, s.degree);  // the McMillan degree bounds the reactive elements
  EXPECT_EQ(s.minimal_reactive, s.reactive == s.degree);
  return err;
}
}  // namespace

TEST(Synthesis, SingleElementsAndFoster) {
  struct Case {
    Rational y;
    int elements;
  };
  const std::vector<Case> cases = {
      {{{3.0}, {0.0, 1.0}}, 1},                 // k/s
      {{{2.5}, {1.0}}, 1},                      // c
      {{{0.0, 4.0}, {1.0}}, 1},                 // b s
      {{{2.0, 1.0, 2.0}, {1.0, 0.0, 1.0}}, 3},  // 2 + s/(s² + 1): c | (k − b)
      {{{3.0, 2.0, 1.0}, {0.0, 1.0}}, 3},       // k/s + c + b s
      {{{0.0, 2.0, 0.0, 1.0}, {1.0, 0.0, 1.0}}, 3},  // lossless Foster s(s² + 2)/(s² + 1)
  };
  for (const auto& c : cases) {
    const Synthesis s = synthesise(c.y);
    EXPECT_LT(check(c.y, s), 1e-9) << to_string(s.network, true);
    EXPECT_EQ(s.elements, c.elements) << to_string(s.network, true);
    EXPECT_FALSE(s.bott_duffin);
    EXPECT_TRUE(s.minimal_reactive);
    EXPECT_EQ(s.method, "Foster/ladder");
  }
}

TEST(Synthesis, BiquadraticClasses) {
  struct Case {
    const char* what;
    Rational y;
    double omega_min;  // where min Re Y(jω) is: 0, inf or finite (-1)
    bool bott_duffin;
  };
  const double inf = INFINITY;
  auto net = [](const char* text, Params p) { return rational_admittance(simplify(assign(parse(text), p))); };
  const std::vector<Case> cases = {
      {"min Re at ω = ∞ (two Maxwell branches)", net("c1|(k1-c2)|(k2-c3)", {{"c1", 1}, {"k1", 2}, {"c2", 3}, {"k2", 5}, {"c3", 0.7}}), inf, false},
      {"min Re at ω = 0", net("c1|(b1-c2)|(b2-c3)", {{"c1", 1}, {"b1", 2}, {"c2", 3}, {"b2", 5}, {"c3", 0.7}}), 0, false},
      {"pole at 0", {{3.0, 2.0, 1.0}, {0.0, 2.0, 1.0}}, -2, false},
      {"zero at ∞", net("k1-(c1|b1)", {{"k1", 2}, {"c1", 0.5}, {"b1", 3}}), -2, false},
      {"minimum function, X > 0", {{1.0, 1.0, 1.0}, {4.0, 1.0, 1.0}}, -1, true},
      {"minimum function, X < 0", {{4.0, 1.0, 1.0}, {1.0, 1.0, 1.0}}, -1, true},
      {"min Re > 0 at finite ω, X > 0", {{3.0, 1.5, 1.5}, {4.0, 1.0, 1.0}}, -1, true},
      {"min Re > 0 at finite ω, X < 0", {{4.2, 1.2, 1.2}, {1.0, 1.0, 1.0}}, -1, true},
  };
  for (const auto& c : cases) {
    const PrTest t = positive_real(c.y);
    ASSERT_TRUE(t.positive_real) << c.what;
    if (c.omega_min >= 0) {
      EXPECT_EQ(t.omega_min, c.omega_min) << c.what;
    }
    if (c.omega_min == -1) {
      EXPECT_TRUE(t.omega_min > 0 && std::isfinite(t.omega_min)) << c.what;
    }
    const Synthesis s = synthesise(c.y);
    const double err = check(c.y, s);
    EXPECT_LT(err, 1e-9) << c.what << ": " << to_string(s.network, true);
    EXPECT_EQ(s.bott_duffin, c.bott_duffin) << c.what;
    EXPECT_EQ(s.degree, 2) << c.what;
    const ElementCounts n = count_elements(s.network);
    std::cout << c.what << ": " << s.method << ", " << s.elements << " elements (" << n.springs << " k, " << n.dampers
              << " c, " << n.inerters << " b), rel. error " << err << "\n    " << to_string(s.network, true) << "\n";
    if (!c.bott_duffin) {
      EXPECT_TRUE(s.minimal_reactive) << c.what;
    } else {
      EXPECT_EQ(s.reactive, 6) << c.what;  // Bott–Duffin on a biquadratic: 6 reactive elements
      EXPECT_EQ(n.dampers, t.re_min > 1e-9 ? 3 : 2) << c.what;
    }
  }
}

TEST(Synthesis, RandomNetworkAdmittances) {
  std::mt19937 rng(7);
  int bd = 0, tested = 0;
  double worst = 0;
  std::map<int, int> per_degree;
  for (int i = 0; i < 400; ++i) {
    const RandomNetwork r = random_network(rng, 1 + i % 6);
    const Rational y = rational_admittance(r.net);
    const Synthesis s = synthesise(y);
    if (s.degree > 4) continue;
    const double err = check(y, s);
    EXPECT_LT(err, 1e-9) << r.text << " → " << to_string(s.network, true);
    worst = std::max(worst, err);
    bd += s.bott_duffin;
    ++per_degree[s.degree];
    ++tested;
  }
  std::cout << tested << " random networks, worst relative error " << worst << ", " << bd << " needed Bott–Duffin;";
  for (auto [d, n] : per_degree) std::cout << " degree " << d << ": " << n;
  std::cout << "\n";
  EXPECT_GT(per_degree[3] + per_degree[4], 50);
}

TEST(Synthesis, NonPositiveRealThrows) {
  EXPECT_THROW(synthesise({{1.0}, {-1.0, 1.0}}), NetworkError);
  EXPECT_THROW(synthesise({{1.0, 1.0, 1.0}, {1.0}}), NetworkError);
  try {
    synthesise({{-2.0}, {1.0}});
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_EQ(e.column, 0);
    EXPECT_NE(std::string(e.what()).find("not positive real"), std::string::npos);
  }
}
}  // namespace test_network_synthesis
