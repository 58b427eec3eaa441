// Network expressions, 0/∞ simplification, admittances of the named layouts against hand-derived
// formulas (spec/03 §3.2), and the state-space realisation against the admittance.
#include "inerta/network/network.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "inerta/network/layouts.hpp"
#include "inerta/network/realisation.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_network_network {

using namespace inerta::network;
using cd = std::complex<double>;

TEST(NetworkParse, StructureAndNames) {
  Network n = parse(" b - ( k1 | c ) ");
  ASSERT_EQ(n.kind, Network::Kind::Series);
  ASSERT_EQ(n.children.size(), 2u);
  EXPECT_EQ(n.children[0].kind, Network::Kind::Inerter);
  EXPECT_EQ(n.children[1].kind, Network::Kind::Parallel);
  EXPECT_EQ(parameter_names(n), (std::vector<std::string>{"b", "k1", "c"}));
  EXPECT_EQ(to_string(n), "b-(k1|c)");
  EXPECT_EQ(to_string(parse("b|c|k")), "b|c|k");
}

TEST(NetworkParse, ErrorsGiveTheColumn) {
  auto column = [](const std::string& text) {
    try {
      parse(text);
    } catch (const NetworkError& e) {
      return e.column;
    }
    return -1;
  };
  EXPECT_EQ(column("b-k|c"), 4);    // mixed operators
  EXPECT_EQ(column("b-(k|c"), 3);   // the unclosed (
  EXPECT_EQ(column("b-x"), 3);      // not an element
  EXPECT_EQ(column("b-"), 3);       // ends after an operator
  EXPECT_EQ(column("b c"), 3);      // two elements without an operator
  EXPECT_EQ(column(""), 1);
  try {
    parse("b-k|c");
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("without parentheses"), std::string::npos) << e.what();
  }
}

TEST(NetworkBind, MissingUnknownAndNegativeParameters) {
  Network n = parse("b-(k|c)");
  EXPECT_THROW(assign(n, {{"b", 1}, {"k", 2}}), NetworkError);                        // c missing
  EXPECT_THROW(assign(n, {{"b", 1}, {"k", 2}, {"c", 3}, {"k2", 4}}), NetworkError);   // k2 unknown
  EXPECT_THROW(assign(n, {{"b", 1}, {"k", -2}, {"c", 3}}), NetworkError);             // negative
  EXPECT_THROW(resolve("S2-1*", {{"b", 1}, {"k", 2}, {"c", 3}}), NetworkError);     // c is fixed
  EXPECT_NO_THROW(resolve("S2-1*", {{"b", 1}, {"k", 2}}));
}

TEST(NetworkSimplify, OpenAndRigidLimits) {
  auto simp = [](const std::string& e, const Params& p) { return to_string(simplify(assign(parse(e), p))); };
  const double inf = INFINITY;
  EXPECT_EQ(simp("b|c", {{"b", 5}, {"c", 0}}), "b");             // parallel open member drops out
  EXPECT_EQ(simp("k-c", {{"k", 5}, {"c", inf}}), "k");           // series rigid member drops out
  EXPECT_EQ(simp("k-c", {{"k", 0}, {"c", 3}}), "open");          // series with an open member
  EXPECT_EQ(simp("b|c|k", {{"b", 1}, {"c", inf}, {"k", 2}}), "rigid");
  EXPECT_EQ(simp("b-(k|c)", {{"b", 1}, {"k", inf}, {"c", 3}}), "b");
  EXPECT_EQ(simp("(b|c)|k", {{"b", 1}, {"c", 2}, {"k", 3}}), "b|c|k");  // flattened
}

namespace {
// Hand-derived admittances of spec/03 §3.2 (s = iω).
struct Case {
  std::string layout;
  Params p;
  std::function<cd(cd)> Y;
};
std::vector<Case> cases() {
  const double b = 250, c = 3000, k = 8e4;
  return {
      {"S1-default", {}, [](cd) { return cd(600); }},
      {"S1-0", {{"b", b}}, [=](cd s) { return b * s; }},
      {"S1-1", {{"b", b}, {"c", c}}, [=](cd s) { return b * s + c; }},
      {"S1-2", {{"b", b}, {"c", c}}, [=](cd s) { return b * c * s / (c + b * s); }},
      {"S1-3", {{"b", b}, {"k", k}, {"c", c}}, [=](cd s) { return b * s * (k + c * s) / (k + c * s + b * s * s); }},
      {"S1-1*", {{"b", b}}, [=](cd s) { return b * s + 600.0; }},
      {"S2-default", {}, [](cd s) { return 141e3 * 10.44e3 / (141e3 + 10.44e3 * s); }},
      {"S2-1", {{"b", b}, {"c", c}, {"k", k}}, [=](cd s) { return b * s + c + k / s; }},
      {"S2-2", {{"k", k}, {"b", b}, {"c", c}}, [=](cd s) { return k * (b * s + c) / (b * s * s + c * s + k); }},
      {"S2-3", {{"b", b}, {"c", c}}, [=](cd s) { return b * s + c; }},
      {"S2-4", {{"c", c}, {"k", k}}, [=](cd s) { return c + k / s; }},
      {"S2-5", {{"k", k}}, [=](cd s) { return k / s; }},
      {"S2-1*", {{"b", b}, {"k", k}}, [=](cd s) { return b * s + 10.44e3 + k / s; }},
  };
}
}  // namespace

TEST(Admittance, EveryNamedLayoutMatchesHandFormula) {
  ASSERT_EQ(cases().size(), layouts().size());
  for (const auto& cs : cases()) {
    SCOPED_TRACE(cs.layout);
    Network net = simplify(resolve(cs.layout, cs.p));
    Rational R = rational_admittance(net);
    Realisation S = realise(net);
    for (double f : {0.1, 0.7, 2.5, 9.0, 40.0}) {
      cd s(0, 2 * M_PI * f), Y = cs.Y(s);
      EXPECT_LT(std::abs(admittance(net, s) - Y), 1e-12 * std::abs(Y)) << "tree, f = " << f;
      EXPECT_LT(std::abs(R(s) - Y), 1e-10 * std::abs(Y)) << "rational, f = " << f;
      EXPECT_LT(std::abs(S.dynamic_stiffness(s) / s - Y), 1e-9 * std::abs(Y)) << "state space, f = " << f;
    }
  }
}

TEST(Realisation, StatesAndDirectTerms) {
  // k|c|b: purely direct (no internal state); the Maxwell element k-c: one state, d0 = k.
  Realisation p = realise(simplify(assign(parse("k|c|b"), {{"k", 100}, {"c", 10}, {"b", 2}})));
  EXPECT_EQ(p.n_states(), 0);
  EXPECT_DOUBLE_EQ(p.d0, 100);
  EXPECT_DOUBLE_EQ(p.d1, 10);
  EXPECT_DOUBLE_EQ(p.d2, 2);
  Realisation m = realise(simplify(resolve("S2-default", {})));
  EXPECT_EQ(m.n_states(), 1);
  EXPECT_NEAR(m.d0, 141e3, 1e-6);
  EXPECT_NEAR(m.static_stiffness(), 0.0, 1e-6);  // a Maxwell element has no static stiffness
  EXPECT_NEAR(m.steady_state(0.01)[0], 0.01, 1e-12);  // scaled state → u at steady state
  // b-(k|c) (TID): two states, no direct terms.
  Realisation t = realise(simplify(assign(parse("b-(k|c)"), {{"b", 10}, {"k", 100}, {"c", 100}})));
  EXPECT_EQ(t.n_states(), 2);
  EXPECT_NEAR(t.static_stiffness(), 0.0, 1e-9);
  // Eigenvalues of A are the network's internal poles: roots of b s² + c s + k.
  Eigen::VectorXcd ev = t.A.eigenvalues();
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(std::abs(10.0 * ev[i] * ev[i] + 100.0 * ev[i] + 100.0), 0.0, 1e-9);
}
}  // namespace test_network_network
