// Commissioning a design (issue 49, analysis/commission.hpp): the trim meets its target within 0.05 N
// for the 3-mass and the HSX; a design relaxed at standstill starts from the stock static force; a
// static spring moves the static force over the working range and fails the criterion where a Maxwell
// network passes; commissioning is reproducible bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "inerta/analysis/aero_fit.hpp"
#include "inerta/analysis/commission.hpp"
#include "inerta/error.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/network/layouts.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_commission {

using namespace inerta;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
// The benchmark line, 4 spans (a short run), and the AC set's target at 250 km/h.
io::CatenaryFile short_line(const std::vector<std::string>& sets = {}) {
  std::vector<std::string> s{"line.spans=4"};
  s.insert(s.end(), sets.begin(), sets.end());
  return io::load_catenary(kDir + "/models/catenary-fe.yaml", s);
}
analysis::Trim trim_250() {
  const analysis::AcceptanceCriteria c = io::load_acceptance("en50367-ac");
  analysis::Trim t;
  t.speed = 250 / 3.6;
  t.target = c.target.at(250);
  t.options.filter_cutoff = c.filter_cutoff, t.options.filter_order = c.filter_order;
  return t;
}
network::Network maxwell() { return network::resolve("k-c", {{"k", 1.41e5}, {"c", 1.044e4}}); }
// The stock Maxwell network with a static spring in parallel (its static stiffness k1).
network::Network with_spring(double k1) { return network::resolve("k1|(k-c)", {{"k1", k1}, {"k", 1.41e5}, {"c", 1.044e4}}); }
}  // namespace

TEST(Commission, TheTrimMeetsItsTargetWithinAFiftiethOfANewtonForThe3MassAndTheHsx) {
  const io::CatenaryFile line = short_line();
  const analysis::Trim t = trim_250();
  for (const char* model : {"pantograph-3mass.yaml", "hsx.yaml"}) {
    const pantograph::Pantograph p = io::load_pantograph(kDir + "/models/" + model);
    const analysis::Commissioned c = analysis::commission(p, nullptr, *line.catenary, line.contact, t);
    EXPECT_TRUE(c.record.reached) << model;
    EXPECT_LE(std::abs(c.record.mean - t.target), 0.05) << model << " mean " << c.record.mean;
    EXPECT_GT(c.record.a, 0) << model;
    EXPECT_LT(c.record.mean_without, t.target) << model;
    EXPECT_EQ(c.pantograph.aero.a, c.record.a) << model;
    // The commissioned pantograph runs at that mean force (the same run as the trim's last).
    const analysis::SpeedResult r = analysis::sweep(c.pantograph, *line.catenary, line.contact, {t.speed}, t.options).front();
    EXPECT_EQ(r.filtered.front().mean, c.record.mean) << model;
  }
}

TEST(Commission, ADesignRelaxedAtStandstillStartsFromTheStockStaticForce) {
  const io::CatenaryFile line = short_line();
  const pantograph::Pantograph hsx = io::load_pantograph(kDir + "/models/hsx.yaml");
  const analysis::Commissioned stock = analysis::commission(hsx, nullptr, *line.catenary, line.contact, {});
  const network::Network s = with_spring(2e5);
  const analysis::Commissioned c = analysis::commission(hsx, &s, *line.catenary, line.contact, {});
  EXPECT_NEAR(c.record.static_force, stock.record.static_force, 1e-9 * stock.record.static_force);
  EXPECT_NEAR(c.record.operating_length, analysis::operating_length(hsx, *line.catenary, line.contact), 0.0);
  EXPECT_DOUBLE_EQ(c.record.static_stiffness, 2e5 + 0.0);  // G(0): the spring alone (the Maxwell branch gives way)
  EXPECT_FALSE(c.record.trimmed);
  EXPECT_EQ(c.record.a, 0.0);
  // The static force at the head's height on the line is the rig's reaction there.
  EXPECT_DOUBLE_EQ(analysis::static_force_at(c.pantograph, c.record.head_offset), c.record.static_force);
}

TEST(Commission, AStaticSpringFailsTheWorkingRangeWhereAMaxwellNetworkPasses) {
  const io::CatenaryFile line = short_line();
  const pantograph::Pantograph hsx = io::load_pantograph(kDir + "/models/hsx.yaml");
  const analysis::AcceptanceCriteria ac = io::load_acceptance("en50367-ac");
  ASSERT_TRUE(ac.has_static_force);
  const analysis::WorkingRange range;  // ±0.1 m
  const network::Network m = maxwell(), s = with_spring(2e5), soft = with_spring(100);
  const auto rows = [&](const network::Network& n) {
    const analysis::Commissioned c = analysis::commission(hsx, &n, *line.catenary, line.contact, {}, &range);
    EXPECT_EQ(c.record.range_force.size(), 5u);
    return std::pair{c.record, analysis::assess_static(ac, c.record)};
  };
  const auto [cm, rm] = rows(m);
  ASSERT_EQ(rm.size(), 2u);
  for (const auto& r : rm) EXPECT_TRUE(r.assessed && r.passed) << r.criterion << " " << r.value << " vs " << r.limit;
  for (double f : cm.range_force) EXPECT_NEAR(f, cm.static_force, 1e-9 * cm.static_force);  // G(0) = 0 adds nothing
  const auto [cs, rs] = rows(s);
  EXPECT_FALSE(rs[0].passed && rs[1].passed) << cs.range_min() << " … " << cs.range_max();
  // The spring pushes back: more force with the wire lowered, less with it raised, and about linear.
  EXPECT_GT(cs.range_force.front(), cs.static_force);
  EXPECT_LT(cs.range_force.back(), cs.static_force);
  const double down = cs.range_force.front() - cs.static_force, up = cs.static_force - cs.range_force.back();
  EXPECT_NEAR(down, up, 0.1 * up);
  // A soft spring moves it in proportion to its stiffness (twice as stiff, twice the change), and passes.
  const auto [cw, rw] = rows(soft);
  const auto [cw2, rw2] = rows(with_spring(200));
  const double d1 = cw.range_force.front() - cw.static_force, d2 = cw2.range_force.front() - cw2.static_force;
  EXPECT_GT(d1, 0);
  EXPECT_NEAR(d2, 2 * d1, 0.01 * d2);
  for (const auto& r : rw) EXPECT_TRUE(r.passed) << r.criterion;
}

TEST(Commission, IsReproducibleBitForBit) {
  const io::CatenaryFile line = short_line();
  const pantograph::Pantograph hsx = io::load_pantograph(kDir + "/models/hsx.yaml");
  const network::Network s = with_spring(5e4);
  const analysis::WorkingRange range;
  const analysis::Commissioning a = analysis::commission(hsx, &s, *line.catenary, line.contact, trim_250(), &range).record;
  const analysis::Commissioning b = analysis::commission(hsx, &s, *line.catenary, line.contact, trim_250(), &range).record;
  EXPECT_EQ(a.operating_length, b.operating_length);
  EXPECT_EQ(a.static_force, b.static_force);
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.mean, b.mean);
  EXPECT_EQ(a.runs, b.runs);
  EXPECT_EQ(a.range_force, b.range_force);
}

TEST(Commission, BadInputIsNamed) {
  const io::CatenaryFile line = short_line();
  const pantograph::Pantograph hsx = io::load_pantograph(kDir + "/models/hsx.yaml");
  analysis::WorkingRange bad;
  bad.below = bad.above = 0;
  EXPECT_THROW(analysis::commission(hsx, nullptr, *line.catenary, line.contact, {}, &bad), InvalidArgument);
  EXPECT_THROW(analysis::static_force_at(hsx, NAN), InvalidArgument);
  pantograph::Pantograph no_rig = hsx;
  no_rig.rig_joint = -1;
  EXPECT_THROW(analysis::static_force_at(no_rig, 0.0), ModelError);
  // A mean force that is not a number (a design without a steady state) is a numerical failure, never a fit.
  EXPECT_THROW(analysis::fit_aerodynamic([](double) { return NAN; }, 70.0, 100.0), NumericalError);
  EXPECT_THROW(analysis::fit_aerodynamic([](double a) { return a > 0 ? NAN : 50.0; }, 70.0, 100.0), NumericalError);
  analysis::Trim t = trim_250();
  t.target = NAN;
  EXPECT_THROW(analysis::commission(hsx, nullptr, *line.catenary, line.contact, t), InvalidArgument);
}

}  // namespace test_analysis_commission
