// Lanes (issue 50): several trains on one finite line at one speed, stepped together (run_lanes,
// sweep_lanes); each lane's result is its train's run alone, bit for bit, and a lane's failure is its own.
#include <gtest/gtest.h>

#include <cstring>
#include <exception>
#include <initializer_list>
#include <utility>
#include <string>
#include <vector>

#include "inerta/analysis/commission.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/network/network.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_lanes {

using namespace inerta;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_TRUE(a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0) << what;
}

void expect_same(const analysis::ContactStatistics& a, const analysis::ContactStatistics& b, const std::string& what) {
  for (auto [x, y] : std::initializer_list<std::pair<double, double>>{{a.mean, b.mean}, {a.std, b.std}, {a.max, b.max}, {a.min, b.min}, {a.stat_max, b.stat_max},
                      {a.stat_min, b.stat_min}, {a.loss_pct, b.loss_pct}})
    EXPECT_TRUE(same(x, y)) << what << ": " << x << " vs " << y;
  EXPECT_EQ(a.samples, b.samples) << what;
}

void expect_same(const std::vector<analysis::ContactStatistics>& a, const std::vector<analysis::ContactStatistics>& b,
                 const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) expect_same(a[i], b[i], what + "[" + std::to_string(i) + "]");
}

// Every field of two speed results, doubles bit for bit.
void expect_same(const analysis::SpeedResult& a, const analysis::SpeedResult& b, const std::string& what) {
  EXPECT_TRUE(same(a.speed, b.speed)) << what;
  expect_same(a.stats, b.stats, what + " stats");
  expect_same(a.contacts, b.contacts, what + " contacts");
  EXPECT_EQ(a.spans, b.spans) << what;
  EXPECT_TRUE(same(a.sigma_change, b.sigma_change)) << what;
  EXPECT_EQ(a.converged, b.converged) << what;
  EXPECT_TRUE(same(a.floquet, b.floquet)) << what;
  expect_same(a.t, b.t, what + " t");
  expect_same(a.F, b.F, what + " F");
  expect_same(a.support_x, b.support_x, what + " support_x");
  expect_same(a.support_uplift, b.support_uplift, what + " support_uplift");
  expect_same(a.filtered, b.filtered, what + " filtered");
  EXPECT_EQ(a.loss_runs, b.loss_runs) << what;
  EXPECT_TRUE(same(a.sample_dt, b.sample_dt)) << what;
  EXPECT_TRUE(same(a.uplift_limit, b.uplift_limit)) << what;
  EXPECT_EQ(a.uplift_limited, b.uplift_limited) << what;
  expect_same(a.overlap, b.overlap, what + " overlap");
  expect_same(a.overlap_filtered, b.overlap_filtered, what + " overlap_filtered");
}

std::string message(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  }
  return "";
}

// A short finite-element line (4 spans, modes below 30 Hz).
io::CatenaryFile short_line() { return io::load_catenary(kDir + "/models/catenary-fe.yaml", {"line.spans=4", "solver.cutoff=30"}); }

// The HSX with another suspension, relaxed where its own sits on the line (as a study relaxes designs).
pantograph::Pantograph hsx_with(const std::string& layout, const network::Params& values) {
  pantograph::Pantograph p = io::load_pantograph(kDir + "/models/hsx.yaml");
  const io::CatenaryFile c = short_line();
  p.model = pantograph::with_suspension(p.model, network::resolve(layout, values),
                                        analysis::operating_length(p, *c.catenary, c.contact));
  return p;
}

// Three designs: the HSX as it is, with a softer Maxwell suspension, and the 3-mass pantograph; `x0` each.
std::vector<std::vector<catenary::PantographOnLine>> trains(const catenary::Contact& contact, const std::vector<double>& x0) {
  const std::vector<pantograph::Pantograph> ps{io::load_pantograph(kDir + "/models/hsx.yaml"),
                                               hsx_with("k-c", {{"k", 5e4}, {"c", 3e3}}),
                                               io::load_pantograph(kDir + "/models/pantograph-3mass.yaml")};
  std::vector<std::vector<catenary::PantographOnLine>> out;
  for (const auto& p : ps) {
    out.emplace_back();
    for (double x : x0) out.back().push_back({p, x, contact});
  }
  return out;
}
}  // namespace

TEST(Lanes, EachLaneOfASweepIsItsTrainsSweepBitForBit) {
  const io::CatenaryFile c = short_line();
  const std::vector<double> speeds{180 / 3.6, 250 / 3.6};
  const analysis::RunOptions o;
  const auto t = trains(c.contact, {0.0, 40.0});  // two pantographs a train
  const std::vector<analysis::LaneSweep> got = analysis::sweep_lanes(t, *c.catenary, speeds, o);
  ASSERT_EQ(got.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    ASSERT_FALSE(got[i].error) << message(got[i].error);
    const std::vector<analysis::SpeedResult> alone = analysis::sweep(t[i], *c.catenary, speeds, o);
    ASSERT_EQ(got[i].results.size(), alone.size());
    for (std::size_t k = 0; k < alone.size(); ++k)
      expect_same(got[i].results[k], alone[k], "train " + std::to_string(i) + " at " + std::to_string(speeds[k]));
    EXPECT_EQ(got[i].results[0].contacts.size(), 2u);
  }
  // The designs differ: the lanes are not one run copied.
  EXPECT_NE(got[0].results[1].stats.std, got[1].results[1].stats.std);
}

TEST(Lanes, ALaneThatFailsStopsAloneAndTheOthersGiveTheirRunsWithHistories) {
  const io::CatenaryFile c = short_line();
  const analysis::RunOptions o;
  const double v = 220 / 3.6;
  std::vector<std::vector<catenary::PantographOnLine>> t = trains(c.contact, {0.0});
  // A fourth train whose run fails (an almost rigid link in series with a vanishing damper: singular).
  t.push_back({{hsx_with("k-c", {{"k", 1e9}, {"c", 1e-3}}), 0.0, c.contact}});
  std::string alone_failure;
  try {
    analysis::run_speed(*c.catenary->couple(t[3], v), o);
  } catch (const NumericalError& e) {
    alone_failure = e.what();
  }
  ASSERT_FALSE(alone_failure.empty()) << "the fourth train should fail alone";
  auto lanes = c.catenary->couple_lanes(t, v);
  ASSERT_EQ(lanes->lanes(), 4);
  lanes->fail(1, std::make_exception_ptr(NumericalError("lane 1 stopped by hand")));
  const std::vector<analysis::LaneResult> r = analysis::run_lanes(*lanes, o);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(message(r[1].error), "lane 1 stopped by hand");
  EXPECT_EQ(message(r[3].error), alone_failure);
  for (std::size_t i : {0u, 2u}) {
    ASSERT_FALSE(r[i].error) << message(r[i].error);
    expect_same(r[i].result, analysis::run_speed(*c.catenary->couple(t[i], v), o), "lane " + std::to_string(i));
    EXPECT_FALSE(r[i].result.F.empty());  // run_speed keeps the leading contact's history; so does a lane
  }
  // sweep_lanes: the failing train has sweep's exception, the others their sweeps.
  const std::vector<analysis::LaneSweep> s = analysis::sweep_lanes(t, *c.catenary, {v}, o);
  EXPECT_EQ(message(s[3].error), alone_failure);
  for (std::size_t i : {0u, 1u, 2u}) {
    ASSERT_FALSE(s[i].error) << message(s[i].error);
    expect_same(s[i].results.at(0), analysis::sweep(t[i], *c.catenary, {v}, o).at(0), "train " + std::to_string(i));
  }
}

TEST(Lanes, TrainsThatCannotShareLanesAndPeriodicLinesRunAsTheirOwnSweeps) {
  // Different positions: couple_lanes refuses them together; each train then runs alone, as sweep runs it.
  const io::CatenaryFile c = short_line();
  const analysis::RunOptions o;
  std::vector<std::vector<catenary::PantographOnLine>> t = trains(c.contact, {0.0});
  t[2].front().x0 = 10;
  EXPECT_THROW(c.catenary->couple_lanes(t, 200 / 3.6), InvalidArgument);
  const std::vector<analysis::LaneSweep> s = analysis::sweep_lanes(t, *c.catenary, {200 / 3.6}, o);
  for (std::size_t i = 0; i < t.size(); ++i) {
    ASSERT_FALSE(s[i].error) << message(s[i].error);
    expect_same(s[i].results.at(0), analysis::sweep(t[i], *c.catenary, {200 / 3.6}, o).at(0), "train " + std::to_string(i));
  }
  // A periodic (lumped) line: no lanes; each train's sweep (σ settles span by span).
  const io::CatenaryFile lumped = io::load_catenary(kDir + "/models/catenary.yaml");
  const std::vector<double> speeds{150 / 3.6, 250 / 3.6};
  const auto tl = trains(lumped.contact, {0.0});
  const std::vector<analysis::LaneSweep> p = analysis::sweep_lanes(tl, *lumped.catenary, speeds, o);
  for (std::size_t i = 0; i < tl.size(); ++i) {
    ASSERT_FALSE(p[i].error) << message(p[i].error);
    const auto alone = analysis::sweep(tl[i], *lumped.catenary, speeds, o);
    for (std::size_t k = 0; k < speeds.size(); ++k) expect_same(p[i].results.at(k), alone[k], "lumped train " + std::to_string(i));
  }
  auto lanes = lumped.catenary->couple_lanes(tl, 200 / 3.6);
  EXPECT_THROW(analysis::run_lanes(*lanes, o), InvalidArgument);
  // sweep's checks before any run: every train's exception.
  const std::vector<analysis::LaneSweep> bad = analysis::sweep_lanes(t, *c.catenary, {-1.0}, o);
  for (const auto& b : bad) EXPECT_NE(message(b.error).find("speeds"), std::string::npos) << message(b.error);
}

}  // namespace test_analysis_lanes
