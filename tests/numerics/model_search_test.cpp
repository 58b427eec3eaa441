// NLopt's BOBYQA and COBYLA as the refinement of issue 36 (numerics/model_search.hpp): known optima
// of a smooth objective (Rosenbrock in bounds) and of a constrained one, the limits 0 and ∞ by the
// limit check, the budget, the batch hook and errors.
#include "inerta/numerics/model_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_numerics_model_search {

using namespace inerta::numerics;

namespace {
// Rosenbrock in the decades u = log10 x: minimum 0 at u = (1, 1), x = (10, 10).
Evaluation rosenbrock(const std::vector<double>& x) {
  const double a = std::log10(x[0]), b = std::log10(x[1]);
  return {(1 - a) * (1 - a) + 100 * (b - a * a) * (b - a * a), 0};
}
std::vector<Variable> box() { return {{"x", 1e-2, 1e4, false, false}, {"y", 1e-2, 1e4, false, false}}; }
Options from(std::vector<double> start, int budget, double min_step) {
  Options o;
  o.initial_values = {std::move(start)};
  o.initial_step = 0.5, o.min_step = min_step, o.max_evaluations = budget;
  return o;
}
}  // namespace

TEST(ModelSearch, BobyqaAndCobylaFindRosenbrocksMinimumInBounds) {
  for (Optimiser which : {Optimiser::Bobyqa, Optimiser::Cobyla}) {
    const Result r = model_search(box(), rosenbrock, from({0.1, 1.0}, 20000, 1e-7), which);
    SCOPED_TRACE(optimiser_name(which));
    EXPECT_NEAR(std::log10(r.values[0]), 1.0, 1e-2);
    EXPECT_NEAR(std::log10(r.values[1]), 1.0, 2e-2);
    EXPECT_LT(r.cost, 1e-4);
    EXPECT_FALSE(r.exhausted);
    EXPECT_LE(r.evaluations, 20000);  // COBYLA's linear models need ≈ 17 000 here, BOBYQA ≈ 170
    ASSERT_EQ(r.ends.size(), 1u);
    EXPECT_EQ(r.ends[0].cost, r.cost);
  }
}

TEST(ModelSearch, AConstrainedOptimumOnItsConstraint) {
  // min (u−2)² + (v−2)² subject to u + v ≤ 2 (u, v decades): the optimum (1, 1), cost 2, on the
  // constraint. COBYLA takes it as a constraint and finds it; BOBYQA sees an exact penalty, whose kink
  // along the constraint its quadratic models cannot follow: it stops on the constraint, feasible,
  // short of the optimum (docs/studies.md: COBYLA where a limit is active).
  auto f = [](const std::vector<double>& x) {
    const double u = std::log10(x[0]), v = std::log10(x[1]);
    return Evaluation{(u - 2) * (u - 2) + (v - 2) * (v - 2), u + v - 2};
  };
  const Result r = model_search(box(), f, from({1.0, 1.0}, 2000, 1e-6), Optimiser::Cobyla);
  const double u = std::log10(r.values[0]), v = std::log10(r.values[1]);
  EXPECT_NEAR(u, 1.0, 1e-3);
  EXPECT_NEAR(v, 1.0, 1e-3);
  EXPECT_LE(u + v - 2, 0.0);  // the best point is feasible
  EXPECT_NEAR(r.cost, 2.0, 1e-3);
  EXPECT_FALSE(r.exhausted);
  const Result b = model_search(box(), f, from({1.0, 1.0}, 2000, 1e-6), Optimiser::Bobyqa);
  EXPECT_LE(std::log10(b.values[0]) + std::log10(b.values[1]) - 2, 0.0);
  EXPECT_LT(b.cost, 2.2);  // from 8 at the start
  EXPECT_EQ(ranked({3.0, 0.0}), 3.0);
  EXPECT_GT(ranked({1e-3, 0.5}), ranked({1e9, 0.0}));   // any infeasible point after every feasible one
  EXPECT_LT(ranked({1e9, 0.1}), ranked({0.0, 0.2}));    // the smaller violation first
}

TEST(ModelSearch, TheLimitCheckReachesOpenAndRigid) {
  // As the pattern search's test: cost falls as c → 0 and as k → ∞; the optimum is c open, k rigid.
  const std::vector<Variable> v = {{"c", 1, 1e9}, {"k", 1, 1e9}};
  auto f = [](const std::vector<double>& x) { return Evaluation{x[0] / (1 + x[0]) + 1 / (1 + x[1]), 0}; };
  for (Optimiser which : {Optimiser::Bobyqa, Optimiser::Cobyla}) {
    const Result r = model_search(v, f, from({10.0, 10.0}, 200, 0.01), which);
    SCOPED_TRACE(optimiser_name(which));
    EXPECT_EQ(r.values[0], 0.0);
    EXPECT_TRUE(std::isinf(r.values[1]));
    EXPECT_EQ(r.cost, 0.0);
    // A start at a limit stays there for the model; the check tries the finite end next to it.
    const Result s = model_search(v, f, from({0.0, INFINITY}, 50, 0.01), which);
    EXPECT_EQ(s.values[0], 0.0);
    EXPECT_TRUE(std::isinf(s.values[1]));
    EXPECT_EQ(s.evaluations, 3);  // the start and the two finite ends
  }
  // Without the limits: the bounds.
  std::vector<Variable> w = v;
  w[0].can_open = w[1].can_rigid = false;
  const Result b = model_search(w, f, from({10.0, 10.0}, 200, 0.01), Optimiser::Bobyqa);
  EXPECT_NEAR(b.values[0], 1.0, 1e-9);
  EXPECT_NEAR(b.values[1], 1e9, 1e-9 * 1e9);
}

TEST(ModelSearch, TheBudgetTheBatchAndDeterminism) {
  // A small budget stops the model before its steps reach min_step: exhausted, within the budget.
  const Result small = model_search(box(), rosenbrock, from({0.1, 1.0}, 12, 1e-7), Optimiser::Bobyqa);
  EXPECT_TRUE(small.exhausted);
  EXPECT_LE(small.evaluations, 12);
  EXPECT_LT(small.cost, rosenbrock({0.1, 1.0}).f);  // never worse than the start
  // Through a batch (one-point batches for the model): the same run.
  int calls = 0;
  const ConstrainedBatch batch = [&](const std::vector<std::vector<double>>& pts) {
    ++calls;
    std::vector<Evaluation> e;
    for (const auto& p : pts) e.push_back(rosenbrock(p));
    return e;
  };
  for (Optimiser which : {Optimiser::Bobyqa, Optimiser::Cobyla}) {
    const Result a = model_search(box(), rosenbrock, from({0.1, 1.0}, 60, 1e-4), which);
    calls = 0;
    const Result b = model_search(box(), rosenbrock, from({0.1, 1.0}, 60, 1e-4), which, {}, batch);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(calls, b.evaluations);  // no limit moves here: every batch is one point
  }
  // Each design once: the start too (its values are not recomputed from their logarithms).
  std::vector<std::vector<double>> seen;
  auto recording = [&](const std::vector<double>& x) {
    seen.push_back(x);
    return rosenbrock(x);
  };
  const Result once = model_search(box(), recording, from({0.3, 3.0}, 60, 1e-4), Optimiser::Cobyla);
  EXPECT_EQ(static_cast<int>(seen.size()), once.evaluations);
  for (std::size_t i = 0; i < seen.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_FALSE(std::abs(seen[i][0] / seen[j][0] - 1) < 1e-12 && std::abs(seen[i][1] / seen[j][1] - 1) < 1e-12) << i << " " << j;
  // Two starts: one end each, the best kept; evaluations add up.
  Options two = from({0.1, 1.0}, 40, 1e-4);
  two.initial_values.push_back({5.0, 20.0});
  const Result t = model_search(box(), rosenbrock, two, Optimiser::Bobyqa);
  ASSERT_EQ(t.ends.size(), 2u);
  EXPECT_EQ(t.cost, std::min(t.ends[0].cost, t.ends[1].cost));
  EXPECT_LE(t.evaluations, 80);
}

TEST(ModelSearch, PatternDelegatesAndErrorsPropagate) {
  const Options o = from({0.1, 1.0}, 100, 0.01);
  const Result p = model_search(box(), rosenbrock, o, Optimiser::Pattern);
  const Result q = pattern_search(box(), [](const std::vector<double>& x) { return rosenbrock(x).f; }, o);
  EXPECT_EQ(p.values, q.values);
  EXPECT_EQ(p.evaluations, q.evaluations);
  auto bad = [](const std::vector<double>&) -> Evaluation { throw std::logic_error("a bug"); };
  EXPECT_THROW(model_search(box(), bad, o, Optimiser::Bobyqa), std::logic_error);
  EXPECT_THROW(model_search(box(), rosenbrock, Options{}, Optimiser::Cobyla), std::invalid_argument);  // no start
  EXPECT_EQ(parse_optimiser("bobyqa"), Optimiser::Bobyqa);
  EXPECT_EQ(parse_optimiser("cobyla"), Optimiser::Cobyla);
  EXPECT_EQ(parse_optimiser("pattern"), Optimiser::Pattern);
  EXPECT_FALSE(parse_optimiser("BOBYQA").has_value());
}

}  // namespace test_numerics_model_search
