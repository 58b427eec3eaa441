// The exhaustive structure search (optim/structure_search.hpp): on an objective with a known answer
// (fit a target network's admittance) it finds the target, never ranks a network worse than one it
// contains, reports reductions; on the tuned-mass-damper study it does at least as well as the best
// fixed layout optimised on its own.
#include "inerta/optim/structure_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/admittance_search.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_structure_search {

using namespace inerta;

namespace {
using cd = std::complex<double>;

// J = rms over 0.1 … 100 rad/s of |Y(jω) − Y_target(jω)| / |Y_target(jω)|: zero exactly for the
// target's admittance, and smooth (a max would stall a compass search on a ridge). Pattern search
// on log values, as the studies do.
const network::Network target = network::assign(network::parse("k-(c|b)"), {{"k", 2.0e4}, {"c", 300}, {"b", 20}});

double misfit(const network::Network& net) {
  const network::Network s = network::simplify(net);
  if (s.kind == network::Network::Kind::Open || s.kind == network::Network::Kind::Rigid) return 1e3;
  double J = 0;
  for (int i = 0; i <= 60; ++i) {
    const cd jw(0, 0.1 * std::pow(1000.0, i / 60.0));
    const cd y0 = network::admittance(target, jw);
    J += std::norm((network::admittance(s, jw) - y0) / y0) / 61;
  }
  return std::sqrt(J);
}

optim::StructureOutcome fit(const std::string& expression, const std::vector<network::Params>& warm) {
  const auto names = network::parameter_names(network::parse(expression));
  std::vector<numerics::Variable> vars;
  for (const auto& n : names) vars.push_back({n, 1e-2, 1e7, true, true});
  numerics::Options o;
  o.starts = 2, o.min_step = 1e-4, o.grid_variables = 3;  // a global look at up to three elements
  for (const auto& w : warm) {
    std::vector<double> v;
    for (const auto& n : names) v.push_back(w.at(n));
    o.initial_values.push_back(v);
  }
  auto params = [&](const std::vector<double>& v) {
    network::Params p;
    for (std::size_t i = 0; i < names.size(); ++i) p[names[i]] = v[i];
    return p;
  };
  const auto r = numerics::pattern_search(
      vars, [&](const std::vector<double>& v) { return misfit(network::assign(network::parse(expression), params(v))); }, o);
  return {params(r.values), r.cost, r.cost, true, r.evaluations};
}
}  // namespace

TEST(StructureSearch, FindsATargetNetworkAndNeverRanksASupersetWorse) {
  network::EnumerationOptions eo;
  eo.max_elements = 4;
  const auto nets = network::enumerate(eo);
  std::vector<network::Params> warm_seen(nets.size());
  int progress_calls = 0;
  const auto entries = optim::structure_search(
      nets, [&](std::size_t, const std::string& e, const std::vector<network::Params>& w) { return fit(e, w); },
      [&](const optim::StructureProgress& p) {
        ++progress_calls;
        EXPECT_LE(p.done, p.total);
        EXPECT_GE(p.remaining, 0.0);
      });
  ASSERT_EQ(entries.size(), nets.size());
  EXPECT_EQ(progress_calls, static_cast<int>(nets.size()));
  std::map<std::string, std::size_t> by_structure;
  for (std::size_t i = 0; i < entries.size(); ++i) by_structure[network::structure(network::parse(entries[i].expression))] = i;
  // The target's own structure fits exactly, with the target's values.
  const auto& t = entries[by_structure.at("k-(c|b)")];
  EXPECT_LT(t.J, 1e-3);
  EXPECT_NEAR(t.values.at("k"), 2.0e4, 2.0e4 * 1e-3);
  EXPECT_NEAR(t.values.at("c"), 300, 300 * 1e-3);
  EXPECT_NEAR(t.values.at("b"), 20, 20 * 1e-3);
  // Inclusion: opening or locking one element of a network gives a sub-network; the network's
  // optimum is at least as good (it was started from the best of them).
  int checked = 0;
  for (const auto& e : entries) {
    const network::Network n = network::parse(e.expression);
    for (const auto& name : network::parameter_names(n))
      for (double v : {0.0, static_cast<double>(INFINITY)}) {
        network::Params p;
        for (const auto& m : network::parameter_names(n)) p[m] = 1;
        p[name] = v;
        const network::Network s = network::simplify(network::assign(n, p));
        if (s.kind == network::Network::Kind::Open || s.kind == network::Network::Kind::Rigid) continue;
        const auto it = by_structure.find(network::structure(s));
        ASSERT_NE(it, by_structure.end()) << network::to_string(s);
        EXPECT_LE(e.J, entries[it->second].J * (1 + 1e-12) + 1e-15) << e.expression << " vs " << entries[it->second].expression;
        ++checked;
      }
  }
  EXPECT_GT(checked, 500);
  // Every network containing the target reaches it, and reports the reduction to three elements.
  const auto order = optim::ranking(entries);
  EXPECT_LT(entries[order[0]].J, 1e-3);
  int reduce_to_target = 0;
  for (const auto& e : entries)
    if (e.J < 1e-3 && e.counts.elements == 4) {
      EXPECT_TRUE(e.reduces()) << e.expression << " → " << e.reduced;
      reduce_to_target += e.reduced_structure == "k-(c|b)" ? 1 : 0;
    }
  EXPECT_GT(reduce_to_target, 3);
  // The best point for (3 elements, 1 inerter) is the target, and it is Pareto-optimal; nothing with
  // fewer elements fits.
  for (const auto& p : optim::pareto_points(entries)) {
    if (p.elements < 3) {
      EXPECT_GT(p.J, 1e-2) << p.network;
    }
    if (p.elements == 3 && p.inerters == 1) {
      EXPECT_LT(p.J, 1e-3);
      EXPECT_TRUE(p.pareto);
    }
  }
}

TEST(StructureSearch, RefusesARepeatedElementName) {
  const optim::StructureOptimiser none = [](std::size_t, const std::string&, const std::vector<network::Params>&) {
    return optim::StructureOutcome{};
  };
  const std::vector<std::string> twice{"k|k"};
  EXPECT_THROW(optim::structure_search(twice, none), InvalidArgument);
}

TEST(StructureSearch, TunedMassDamperAtLeastAsGoodAsTheBestFixedLayout) {
  // The H∞ study of studies/tmd.yaml (fewer frequencies): every network of up to three elements
  // against the fixed layouts of the thesis-style study, each optimised on its own.
  const std::string path = inerta::testing::write_study(
      "tmd-all.yaml", "model: " + inerta::testing::model_path("tmd.yaml") +
                          "\nstrut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, points: 300}}\n"
                          "layouts: all\nnetworks: {max_elements: 3}\nsearch: {starts: 2, seed: 1, lo: 0.01, hi: 1.0e7, min_step: 0.01}\n");
  const optim::ModelStudy s = io::load_model_study(path);
  ASSERT_TRUE(s.all.has_value());
  EXPECT_EQ(s.layouts.size(), 29u);
  std::vector<optim::ModelLayoutResult> results;
  const auto entries = optim::optimise_all(s, results);
  ASSERT_EQ(results.size(), entries.size());
  const auto best = entries[optim::ranking(entries)[0]];
  double fixed = INFINITY;
  for (const char* layout : {"k|c", "k|c|b", "k|(c-b)", "c|(k-b)"}) fixed = std::min(fixed, optim::optimise_layout(s, layout).cost.J);
  EXPECT_LE(best.J, fixed * (1 + 1e-9));
  // Den Hartog's absorber (k|c) is not the best: a three-element network does better.
  EXPECT_LT(best.J, optim::optimise_layout(s, "k|c").cost.J * 0.99);
  EXPECT_EQ(best.counts.elements, 3);

  // The positive-real biquadratic (degree 2) is never worse than the best network with at most two
  // springs and inerters; it is positive real by the certificate, and its realisation has the
  // same objective.
  const optim::StructureEntry* two = nullptr;
  for (const auto& e : entries)
    if (optim::reactive_elements(network::assign(network::parse(e.expression), e.values)) <= 2 && (!two || e.cost < two->cost)) two = &e;
  ASSERT_NE(two, nullptr);
  const auto bound = optim::admittance_bound(s, 2, network::assign(network::parse(two->expression), two->values));
  EXPECT_LE(bound.J, two->J * (1 + 1e-9)) << two->expression;
  EXPECT_TRUE(bound.pr.positive_real) << bound.pr.reason;
  ASSERT_TRUE(bound.synthesis.has_value()) << bound.synthesis_error;
  EXPECT_NEAR(bound.J_realised, bound.J, 1e-6 * bound.J);
  EXPECT_LE(std::max(bound.y.num.size(), bound.y.den.size()), 3u);
}

TEST(StructureSearch, PruneRemovesElementsThatDoNotMatter) {
  // Fitting a single spring: a tiny damper in parallel and a huge inerter in series do not matter.
  const network::Network spring = network::assign(network::parse("k"), {{"k", 1000}});
  auto cost = [&](const network::Params& p) {
    const network::Network n = network::simplify(network::assign(network::parse("(k|c)-b"), p));
    double J = 0;
    for (double w : {0.5, 5.0, 50.0}) {
      const cd s(0, w);
      J = std::max(J, std::abs(network::admittance(n, s) - network::admittance(spring, s)) / std::abs(network::admittance(spring, s)));
    }
    return J + 1e-3;  // a floor, so that the tolerance is relative to something
  };
  const auto p = optim::prune("(k|c)-b", {{"k", 1000}, {"c", 1e-6}, {"b", 1e12}}, cost, 1e-4);
  EXPECT_EQ(p.at("c"), 0.0);
  EXPECT_TRUE(std::isinf(p.at("b")));
  EXPECT_EQ(p.at("k"), 1000.0);
  // An element that matters stays: fitting k|c, the damper stays and the inerter goes.
  const network::Network kc = network::assign(network::parse("k|c"), {{"k", 1000}, {"c", 100}});
  auto cost2 = [&](const network::Params& p) {
    const network::Network n = network::simplify(network::assign(network::parse("(k|c)-b"), p));
    double J = 0;
    for (double w : {0.5, 5.0, 50.0}) {
      const cd s(0, w);
      J = std::max(J, std::abs(network::admittance(n, s) - network::admittance(kc, s)) / std::abs(network::admittance(kc, s)));
    }
    return J + 1e-3;
  };
  const auto q = optim::prune("(k|c)-b", {{"k", 1000}, {"c", 100}, {"b", 1e12}}, cost2, 1e-4);
  EXPECT_EQ(q.at("c"), 100.0);
  EXPECT_TRUE(std::isinf(q.at("b")));
}

TEST(StructureSearch, AnIllConditionedNetworkIsRefusedNotEvaluated) {
  // A damper of 1e9 N·s/m in series with a 1 kg inerter: a pole at 1e9 rad/s, whose realisation's
  // direct terms (d0 = −c²/b) would swamp the result; the limit c → ∞ (the inerter alone) is
  // evaluated instead, and a moderate damper still is.
  const optim::ModelStudy s = io::load_model_study(inerta::testing::write_study(
      "tmd-ill.yaml", "model: " + inerta::testing::model_path("tmd.yaml") +
                          "\nstrut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, points: 50}}\n"
                          "layouts: [\"k|(c-b)\"]\n"));
  try {
    optim::evaluate(s, network::resolve("k|(c-b)", {{"k", 4500}, {"c", 1e9}, {"b", 1}}));
    ADD_FAILURE() << "evaluated";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("pole at 1e+09 rad/s"), std::string::npos) << e.what();
  }
  const double rigid = optim::evaluate(s, network::resolve("k|(c-b)", {{"k", 4500}, {"c", INFINITY}, {"b", 1}})).J;
  const double stiff = optim::evaluate(s, network::resolve("k|(c-b)", {{"k", 4500}, {"c", 1e5}, {"b", 1}})).J;
  EXPECT_NEAR(stiff, rigid, 1e-3 * rigid);
}
}  // namespace test_optim_structure_search
