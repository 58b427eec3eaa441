// The figures' data of a design study (optim/report.hpp) on a reduced HSX study.
#include "inerta/io/study_file.hpp"
#include "inerta/io/study_report.hpp"
#include "inerta/optim/report.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_report {

using namespace inerta;

namespace {
using inerta::testing::write_study;
std::string study_text(const std::string& catenaries, const std::string& speeds, const std::string& layouts) {
  return std::string("name: small\nmodel: ") + INERTA_SOURCE_DIR + "/models/hsx.yaml\ncatenary: " + INERTA_SOURCE_DIR +
         "/models/catenary.yaml\ncatenaries: " + catenaries + "\nspeeds: " + speeds +
         "\nsearch: {starts: 1, seed: 3, min_step: 0.05}\nlayouts: " + layouts + "\n";
}
const optim::Study& two_catenaries() {
  static const optim::Study s = io::load_study(
      write_study("report_study.yaml", study_text("[[catenary.kc0=5000], [catenary.kc0=10000]]",
                                                  "{from: 150, to: 250, step: 25, unit: kmh}", "[S2-default, b|k]")));
  return s;
}
std::vector<std::string> lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> v;
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}
}  // namespace

TEST(Report, SigmaCurvesCarryTheStudyCost) {
  const optim::Study& s = two_catenaries();
  const network::Network net = network::resolve("b|k", {{"b", 300}, {"k", 6e4}});
  const auto curves = optim::sigma_curves(s, net);
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[1].catenary, "catenary.kc0=10000");
  ASSERT_EQ(curves[0].sigma.size(), s.speeds.size());
  const optim::StudyCost c = optim::evaluate(s, net), w = optim::worst_of(curves);
  EXPECT_DOUBLE_EQ(w.J, c.J);  // J2 is the largest σ of the curves
  EXPECT_DOUBLE_EQ(w.speed, c.speed);
  EXPECT_EQ(w.catenary, c.catenary);
  // The two catenaries give different curves (the overrides reach the runs).
  EXPECT_GT(std::abs(curves[0].sigma[2] - curves[1].sigma[2]), 1e-3);
}

TEST(Report, CostMapEqualsEvaluateAndTheOptimumBeatsTheGrid) {
  const optim::Study& s = two_catenaries();
  const optim::LayoutResult r = optim::optimise_layout(s, "b|k");
  const double bo = r.values.at("b"), ko = r.values.at("k");
  ASSERT_TRUE(std::isfinite(bo) && std::isfinite(ko));
  std::vector<double> bs = optim::linspace(0, 1500, 4), ks = optim::linspace(0, 1e5, 4);
  bs.push_back(bo), ks.push_back(ko);
  const optim::CostMap map = optim::cost_map(s, "b|k", r.values, "b", bs, "k", ks);
  EXPECT_TRUE(map.values.empty());  // b and k are the map's axes, not fixed values
  ASSERT_EQ(map.J.size(), 25u);
  // The map at the optimum's (b, k) is the optimiser's J2 (same design, same fast path) ...
  EXPECT_NEAR(map.at(4, 4), r.cost.J, 1e-12 * r.cost.J);
  // ... any other point is evaluate() of that design (indexing: J[i·ny + j] at (xs[i], ys[j])) ...
  EXPECT_DOUBLE_EQ(map.at(2, 1), optim::evaluate(s, network::resolve("b|k", {{"b", bs[2]}, {"k", ks[1]}})).J);
  // ... and the pattern search does at least as well as the grid.
  for (double J : map.J) {
    if (std::isfinite(J)) {
      EXPECT_GE(J, r.cost.J - 1e-9);
    }
  }
  EXPECT_THROW(optim::cost_map(s, "S2-4", {}, "b", bs, "k", ks), ModelError);  // S2-4 (c|k) has no b
}

TEST(Report, CentripetalOptionReachesTheInerterOnly) {
  const optim::Study s = io::load_study(
      write_study("report_study_c.yaml",
                  study_text("[[catenary.kc0=7000]]", "{from: 150, to: 200, step: 50, unit: kmh}", "[b|k]")));
  const network::Network with_b = network::resolve("b|k", {{"b", 800}, {"k", 6e4}}),
                         spring = network::resolve("b|k", {{"b", 0}, {"k", 6e4}});
  EXPECT_TRUE(optim::has_inerter(with_b));
  EXPECT_FALSE(optim::has_inerter(spring));
  EXPECT_FALSE(optim::has_inerter(network::resolve("b-(k|c)", {{"b", INFINITY}, {"k", 1e4}, {"c", 10}})));
  const auto on = optim::sigma_curves_time(s, with_b, true), off = optim::sigma_curves_time(s, with_b, false);
  ASSERT_EQ(on[0].sigma.size(), 2u);
  double change = 0;  // largest relative change of σ
  for (std::size_t k = 0; k < 2; ++k)
    change = std::max(change, std::abs(on[0].sigma[k] - off[0].sigma[k]) / on[0].sigma[k]);
  EXPECT_GT(change, 1e-9) << "the option must reach the inerter";
  EXPECT_LT(change, 1e-3) << "small for the HSX: its actuator barely rotates (thesis A.9)";
  // Without an inerter the switch has nothing to act on: bit-identical runs.
  const auto s_on = optim::sigma_curves_time(s, spring, true), s_off = optim::sigma_curves_time(s, spring, false);
  EXPECT_EQ(s_on[0].sigma, s_off[0].sigma);
  // The time-domain curves with the correction are the reference re-check of evaluate_time.
  EXPECT_DOUBLE_EQ(optim::worst_of(on).J, optim::evaluate_time(s, with_b).J);
}

TEST(Report, TheReportedDesignCanBeChosen) {
  // `optimise` reports the best time-domain re-check when the fast path ranks another design first
  // (issue 24 item 4): ReportOptions::best picks it; an index beyond the results is an error.
  const optim::Study s = io::load_study(write_study(
      "report_study_best.yaml", study_text("[[catenary.kc0=7000]]", "{from: 150, to: 250, step: 50, unit: kmh}", "[k, b|k]")));
  std::vector<optim::LayoutResult> results{optim::optimise_layout(s, "k"), optim::optimise_layout(s, "b|k")};
  const int worse = results[0].cost.J < results[1].cost.J ? 1 : 0;
  optim::ReportOptions o;
  o.map_size = 0;
  o.frf_f = {1.0};
  o.best = worse;
  const optim::Report r = optim::make_report(s, results, o);
  EXPECT_EQ(r.best.layout, results[static_cast<std::size_t>(worse)].layout);
  EXPECT_DOUBLE_EQ(r.best_cost.J, results[static_cast<std::size_t>(worse)].cost.J);
  o.best = 2;
  EXPECT_THROW(
      try { optim::make_report(s, results, o); } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "make_report: best = 2 but there are 2 layout results");
        throw;
      },
      std::invalid_argument);
}

TEST(Report, ADefaultThatBeatsEveryCandidateIsReportedWithItsFixedValues) {
  // S2-default fixes c = 10440 N·s/m: its result lists c, and resolving the layout with every listed
  // value would refuse it ("layout S2-default fixes c"). A study whose default wins (here against an
  // open network, a spring of 1 N/m) reports it with the layout's own network.
  const optim::Study s = io::load_study(write_study(
      "report_default_wins.yaml", study_text("[[catenary.kc0=7000]]", "{from: 150, to: 250, step: 50, unit: kmh}", "[S2-default, k]")));
  optim::LayoutResult def = optim::optimise_layout(s, "S2-default");
  ASSERT_TRUE(def.values.count("c"));
  optim::LayoutResult weak = def;
  weak.layout = weak.expression = "k";
  weak.values = {{"k", 1.0}};
  weak.cost = optim::evaluate(s, network::resolve("k", weak.values));
  ASSERT_GT(weak.cost.penalised(), def.cost.penalised());
  optim::ReportOptions o;
  o.map_size = 0;
  o.frf_f = {1.0};
  const optim::Report r = optim::make_report(s, {def, weak}, o);
  EXPECT_EQ(r.best.layout, "S2-default");
  EXPECT_EQ(network::to_string(r.best.net, true), network::to_string(optim::default_suspension(s), true));
  EXPECT_DOUBLE_EQ(r.best_cost.J, def.cost.J);
  EXPECT_THROW(network::resolve("S2-default", def.values), network::NetworkError);  // the old path
}

TEST(Report, ReportDataAndCsvFiles) {
  const optim::Study s = io::load_study(write_study(
      "report_study_r.yaml",
      study_text("[[catenary.kc0=7000]]", "{from: 150, to: 250, step: 50, unit: kmh}", "[S2-default, b|k]")));
  std::vector<optim::LayoutResult> results{optim::optimise_layout(s, "S2-default"), optim::optimise_layout(s, "b|k")};
  optim::ReportOptions o;
  o.map_size = 3;
  o.frf_f = {1.0, 2.0, 5.0};
  std::vector<int> steps_started;
  const optim::Report r = optim::make_report(s, results, o, [&](int step, int, const std::string& what, int, int) {
    if (!what.empty()) steps_started.push_back(step);
  });
  EXPECT_EQ(steps_started, (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(r.best.layout, results[1].cost.J < results[0].cost.J ? "b|k" : "S2-default");
  EXPECT_DOUBLE_EQ(r.default_cost.J, optim::evaluate(s, optim::default_suspension(s)).J);
  EXPECT_DOUBLE_EQ(r.best_cost.J, std::min(results[0].cost.J, results[1].cost.J));
  // The default Maxwell suspension carries no static load whatever its reference length, so its rig
  // model is the pantograph's own: the same FRF as frf_linear of the study's model.
  const analysis::Frf own = analysis::frf_linear(s.pantograph, {"P_ay"}, o.frf_f);
  for (std::size_t k = 0; k < o.frf_f.size(); ++k)
    EXPECT_NEAR(std::abs(r.frf_default.H[0][k] - own.H[0][k]), 0, 1e-9 * std::abs(own.H[0][k]));
  // The histories are the analysed window: its statistics, two spans at 180 km/h.
  ASSERT_EQ(r.history_best.size(), 1u);
  const auto& h = r.history_best[0];
  EXPECT_NEAR(analysis::statistics(h.F).std, h.stats.std, 1e-12);
  const double span_time = s.catenaries[0]->span() / (180 / 3.6);
  EXPECT_NEAR(h.t.back() - h.t.front(), 2 * span_time, 1.01 * span_time / 400);
  ASSERT_TRUE(r.map.has_value());
  EXPECT_EQ(r.map->layout, "b|k");
  EXPECT_DOUBLE_EQ(r.map->ys.back(), std::max(1e5, 1.25 * r.map_opt_y));
  EXPECT_DOUBLE_EQ(r.time_check.J, optim::evaluate_time(s, r.best.net).J);

  const auto dir = inerta::testing::temp_dir() / "inerta_report_test";
  std::filesystem::remove_all(dir);
  const auto files = io::write_study_report(r, dir.string());
  EXPECT_EQ(files.size(), 6u);
  auto sigma = lines(dir / "sigma.csv");
  ASSERT_FALSE(sigma.empty());
  EXPECT_EQ(sigma[0], "design,catenary,v_kmh,sigma_N,mean_N");
  EXPECT_EQ(sigma.size(), 1 + 2 * s.speeds.size());
  EXPECT_EQ(sigma[1].rfind("default,catenary.kc0=7000,150,", 0), 0u) << sigma[1];
  EXPECT_EQ(lines(dir / "frf.csv")[0], "design,f_hz,mag,phase_deg");
  EXPECT_EQ(lines(dir / "frf.csv").size(), 1 + 2 * o.frf_f.size());
  EXPECT_EQ(lines(dir / "contact.csv")[0], "design,catenary,t_s,F_N");
  auto map = lines(dir / "j2_map.csv");
  EXPECT_EQ(map[0], "b,k,J2_N");
  EXPECT_EQ(map.size(), 10u);
  auto cen = lines(dir / "centripetal.csv");
  EXPECT_EQ(cen[0], "design,centripetal,catenary,v_kmh,sigma_N,mean_N");
  std::size_t rows = 1;
  for (const auto& c : r.centripetal) {
    EXPECT_EQ(c.off_simulated, optim::has_inerter(c.design.net));
    rows += (c.off_simulated ? 2 : 1) * s.speeds.size();
  }
  EXPECT_EQ(cen.size(), rows);
  std::stringstream json;
  json << std::ifstream(dir / "report.json").rdbuf();
  const auto j = nlohmann::json::parse(json.str());
  EXPECT_EQ(j["map"]["layout"], "b|k") << json.str();
  EXPECT_EQ(j["best_cost"]["J2"].get<double>(), r.best_cost.J);  // full precision
  EXPECT_EQ(j["catenaries"].size(), r.catenaries.size());
}
}  // namespace test_optim_report
