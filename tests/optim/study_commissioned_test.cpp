// A commissioned study (issue 49, docs/studies.md "Robust design on a real line"): `trim:` commissions
// each design once on the reference line and every variant takes it (one free length per design), a
// static spring's force then follows the variant's wire height; the objective σ/F_m; the stock suspension
// competes in the final ranking and a study where nothing beats it recommends it; the file's errors.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "inerta/analysis/commission.hpp"
#include "inerta/error.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/io/study_results.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/optim/study_run.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_commissioned {

using namespace inerta;
using inerta::testing::write_study;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
// The short benchmark line, its contact wire at −10 % and +10 %, at 200 km/h; the AC set, trimmed at 200 km/h.
const std::string kHead = "name: commissioned\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                          "/models/catenary-fe.yaml\n"
                          "catenaries: [[line.spans=3, solver.cutoff=30, contact_wire.tension=18900],\n"
                          "             [line.spans=3, solver.cutoff=30, contact_wire.tension=23100]]\n"
                          "reference: [line.spans=3, solver.cutoff=30]\n"
                          "speeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                          "limits: {acceptance: en50367-ac}\n";

std::string error_of(const std::string& name, const std::string& text) { return inerta::testing::study_error(name, text); }

double reference_length(const pantograph::Pantograph& p) {
  const mbs::Model& m = p.model;
  return dynamic_cast<const mbs::NetworkStrut&>(*m.forces[static_cast<std::size_t>(pantograph::suspension_index(m))])
      .reference_length();
}
}  // namespace

TEST(StudyCommissioned, EachDesignIsRelaxedOnceForEveryCatenaryAndAStaticSpringFollowsTheWire) {
  // The lumped line at two stiffnesses: the wire sits at another height under the static force on each.
  const std::string head = "name: lumped\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                           "/models/catenary.yaml\ncatenaries: [[catenary.kc0=5000], [catenary.kc0=10000]]\n"
                           "speeds: {from: 150, to: 250, step: 50, unit: kmh}\nlayouts: [S2-5]\n";
  const optim::Study legacy = io::load_study(write_study("legacy.yaml", head));
  const optim::Study s = io::load_study(
      write_study("commissioned.yaml", head + "trim: {aerodynamic_at: {speed: 200, unit: kmh}, target: 110}\n"
                                              "objective: {type: sigma_over_mean}\n"));
  ASSERT_TRUE(s.commissioned() && s.reference);
  EXPECT_EQ(s.objective, optim::Study::Objective::SigmaOverMean);
  EXPECT_EQ(s.trim->target, 110.0);
  EXPECT_TRUE(s.trim->periodic);
  const network::Network spring = network::resolve("k1|(k-c)", {{"k1", 2e5}, {"k", 1.41e5}, {"c", 1.044e4}});
  // The thesis's procedure relaxes under each catenary: two lengths; commissioning: one, the reference's.
  const optim::DesignPantographs old = optim::design_pantographs(legacy, spring);
  EXPECT_NE(reference_length(old.pantographs[0]), reference_length(old.pantographs[1]));
  const optim::DesignPantographs d = optim::design_pantographs(s, spring);
  ASSERT_TRUE(d.commissioning.has_value());
  EXPECT_EQ(reference_length(d.pantographs[0]), reference_length(d.pantographs[1]));
  EXPECT_EQ(reference_length(d.pantographs[0]), d.commissioning->operating_length);
  EXPECT_EQ(d.pantographs[0].aero.a, d.commissioning->a);
  EXPECT_LE(std::abs(d.commissioning->mean - 110), 0.05);
  // At standstill on each variant the wire sits at another height: the spring's static force moves with
  // it — up on the softer line (the head higher, the spring pushing down less... or more: it differs) —
  // where the stock (Maxwell) suspension's equals its own on the reference.
  const optim::DesignPantographs st = optim::design_pantographs(s, optim::default_suspension(s));
  const double on_reference = analysis::commission(d.pantographs[0], nullptr, *s.reference, s.contact, {}).record.static_force;
  EXPECT_NEAR(on_reference, d.commissioning->static_force, 1e-9 * on_reference);
  for (std::size_t i = 0; i < s.catenaries.size(); ++i) {
    const double with_spring = analysis::commission(d.pantographs[i], nullptr, *s.catenaries[i], s.contact, {}).record.static_force;
    const double stock = analysis::commission(st.pantographs[i], nullptr, *s.catenaries[i], s.contact, {}).record.static_force;
    EXPECT_GT(std::abs(with_spring - stock), 0.5) << i;
  }
  // The objective: σ/F_m; the commissioning travels with the cost.
  const optim::StudyCost c = optim::evaluate(s, optim::default_suspension(s));
  ASSERT_TRUE(c.commissioning.has_value());
  EXPECT_NEAR(c.J, c.sigma / c.mean, 1e-15);
  for (const char* f : {"legacy.yaml", "commissioned.yaml"}) std::filesystem::remove(inerta::testing::temp_dir() / f);
}

TEST(StudyCommissioned, WhenNothingBeatsTheStockSuspensionTheStudyRecommendsIt) {
  // Every network of one element, each bounded far from anything useful (a stiff spring breaks the static
  // force over the working range; a near-rigid damper or a 1000 kg inerter locks the frame): the stock
  // suspension, ranked with the refined networks, stays the recommendation.
  // Trimmed at 250 km/h (at 200 km/h the AC set's target equals its upper edge: a trim there sits on it).
  const std::string text = kHead + "trim: {aerodynamic_at: {speed: 250, unit: kmh}}\nobjective: {type: sigma_over_mean}\n" +
                           "bounds: {inerter: [999, 1000], spring: [5.0e5, 1.0e6], damper: [9.9e4, 1.0e5]}\n"
                           "layouts: all\nnetworks: {max_elements: 1}\n"
                           "coarse:\n"
                           "  catenary: " + kDir + "/models/catenary-fe-lumped.yaml\n"
                           "  catenaries: [[catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]]\n"
                           "  reference: [catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]\n"
                           "  speeds: {from: 150, to: 250, step: 50, unit: kmh}\n"
                           "  search: {starts: 1, seed: 1, min_step: 0.1}\n"
                           "refine: {best_networks: 3, initial_step: 0.3, min_step: 0.1, max_evaluations: 3}\n";
  const optim::Study s = io::load_study(write_study("stock.yaml", text));
  ASSERT_TRUE(s.coarse && s.coarse->commissioned() && s.coarse->static_criteria);
  optim::StudyOptions opts;
  opts.report = true;
  opts.report_options.frf_f = {1.0, 2.0};
  const optim::StudyOutcome o = optim::run_study(s, opts);
  ASSERT_EQ(o.results.size(), o.refinements.size());
  // The report's margins carry the static force rows of both designs, at standstill on the reference line.
  ASSERT_TRUE(o.report.has_value());
  int statics = 0;
  for (const auto& m : o.report->margins)
    if (m.result.criterion.rfind("static_force_", 0) == 0) {
      ++statics;
      EXPECT_EQ(m.catenary, "reference line at standstill");
      EXPECT_TRUE(m.result.assessed && m.result.passed) << m.design;
    }
  EXPECT_EQ(statics, 4);
  int stock = 0;
  for (std::size_t k = 0; k < o.results.size(); ++k) stock += o.results[k].stock ? 1 : 0;
  EXPECT_EQ(stock, 1);
  EXPECT_TRUE(o.default_cost.feasible) << o.default_cost.violation;
  EXPECT_TRUE(o.stock_best);
  EXPECT_TRUE(o.results[o.best.index].stock);
  EXPECT_EQ(o.best.index, 0u);
  EXPECT_EQ(o.results.front().cost.J, o.default_cost.J);
  for (std::size_t k = 1; k < o.results.size(); ++k)
    EXPECT_GE(o.results[k].cost.penalised(), o.results.front().cost.penalised()) << o.results[k].expression;
  EXPECT_NE(o.refined_csv().find(",default,sigma/F_m,"), std::string::npos) << o.refined_csv();
  // results.csv: what commissioning set for each design, the stock row marked.
  const auto files = io::write_study_results((inerta::testing::temp_dir() / "stock-out").string(), s.name, o.default_cost, o.results);
  std::ifstream in(files.front());
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(csv.find(",stock,sigma_N,a,static_stiffness,static_force,static_force_min,static_force_max\n"), std::string::npos) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(o.results.size()) + 1);
  std::filesystem::remove_all(inerta::testing::temp_dir() / "stock-out");
  std::filesystem::remove(inerta::testing::temp_dir() / "stock.yaml");
}

TEST(StudyCommissioned, BadTrimAndWorkingRangeAreFileErrorsNamingTheKey) {
  EXPECT_NE(error_of("t1.yaml", kHead + "trim: {aerodynamic_at: {speed: -5, unit: kmh}}\nlayouts: [S2-5]\n")
                .find("trim.aerodynamic_at.speed"),
            std::string::npos);
  EXPECT_NE(error_of("t2.yaml", kHead + "trim: {at: 250}\nlayouts: [S2-5]\n").find("trim"), std::string::npos);
  EXPECT_NE(error_of("t3.yaml", kHead + "working_range: {below: -1}\nlayouts: [S2-5]\n").find("working_range.below"),
            std::string::npos);
  EXPECT_NE(error_of("t4.yaml", kHead + "working_range: {below: 0, above: 0}\nlayouts: [S2-5]\n").find("working_range"),
            std::string::npos);
  EXPECT_NE(error_of("t5.yaml", kHead + "objective: {type: sigma}\nlayouts: [S2-5]\n").find("objective"), std::string::npos);
  EXPECT_NE(error_of("t6.yaml", kHead + "reference: [line.spanz=3]\nlayouts: [S2-5]\n").find("reference"), std::string::npos);
  const std::string no_target = "name: x\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                                "/models/catenary.yaml\nspeeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                                "trim: {aerodynamic_at: {speed: 250, unit: kmh}}\nlayouts: [S2-5]\n";
  EXPECT_NE(error_of("t7.yaml", no_target).find("acceptance"), std::string::npos);
  for (int k = 1; k <= 7; ++k) std::filesystem::remove(inerta::testing::temp_dir() / fmt::format("t{}.yaml", k));
}

}  // namespace test_optim_study_commissioned
