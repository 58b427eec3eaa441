// Issue 38: the cost guard (analysis/cost_guard.hpp, catenary::estimate_cost) and the speed rules of
// every run (analysis::check_run_speed). No timing: the estimate's inputs and its decisions.
#include <gtest/gtest.h>

#include <limits>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "support/fe_line.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_cost_guard {

using namespace inerta;

TEST(CostGuard, TheMeshIsCountedFromTheDataAsTheLineBuildsIt) {
  // mesh_unknowns is FeLine::n_dofs() without building the line (what the estimate is made of).
  for (const double h : {0.25, 0.4, 0.1}) {
    for (const int spans : {2, 5}) {
      catenary::FeCatenaryData d = inerta::testing::fe_benchmark_line(spans);
      d.element_length = h;
      EXPECT_EQ(catenary::mesh_unknowns(d), catenary::FeLine(d).n_dofs()) << "h = " << h << ", spans = " << spans;
    }
  }
  // From the mesh of the first spans (issue 51: the compiled mesh, not a formula of its own): exact for a
  // stitched line (stitch wires at the interior masts only) and for anchors on tensioning devices.
  catenary::FeCatenaryData st = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml");
  for (const int spans : {1, 2, 3, 4, 7}) {
    st.spans = spans;
    EXPECT_EQ(catenary::mesh_unknowns(st), catenary::FeLine(st).n_dofs()) << "stitched, spans = " << spans;
    catenary::FeCatenaryData dev = inerta::testing::fe_benchmark_line(spans);
    dev.anchor.pinned = false, dev.anchor.stiffness = 1e5;
    EXPECT_EQ(catenary::mesh_unknowns(dev), catenary::FeLine(dev).n_dofs()) << "tensioning devices, spans = " << spans;
  }
}

TEST(CostGuard, AFeCatenaryIsBuiltOnlyWhenFirstUsedSoItsEstimateComesFirst) {
  // A million-unknown line: constructing the catenary checks its data and builds nothing, so the
  // estimate (setup included) is known at once; the estimate grows with the line.
  catenary::FeCatenaryData d = inerta::testing::fe_benchmark_line(1000);
  d.solver = catenary::FeCatenaryData::Solver::Modal;
  const catenary::FeCatenary big(d);
  EXPECT_EQ(big.line_length(), 55000);
  EXPECT_EQ(big.span(), 55);
  const catenary::FeCostEstimate e = catenary::estimate_cost(d, {0.0}, 250 / 3.6, -1);
  EXPECT_GT(e.setup, 0);
  EXPECT_GT(e.modes, 0);
  EXPECT_GT(e.run, 0);
  // (estimated_seconds needs a pantograph; estimate_cost is what it returns, as from the data.)
  const catenary::FeCostEstimate small = catenary::estimate_cost(inerta::testing::fe_benchmark_line(10), {0.0}, 250 / 3.6, -1);
  EXPECT_GT(e.setup, 50 * small.setup);
  // A finer mesh: more unknowns, more of everything; refused by a low limit, passed by a high one.
  d.spans = 10;
  d.element_length = 0.001;
  const catenary::FeCostEstimate fine = catenary::estimate_cost(d, {0.0}, 250 / 3.6, -1);
  EXPECT_GT(fine.unknowns, 200 * small.unknowns);
  EXPECT_GT(fine.total(), analysis::cost_note_seconds);
  EXPECT_THROW(analysis::check_cost(fine.total(), 60, "this run", "give --max-seconds", ""), analysis::CostLimitError);
  EXPECT_NO_THROW(analysis::check_cost(fine.total(), 1e9, "this run", "give --max-seconds", ""));
  // Invalid data is refused by the constructor, as before the line was built lazily.
  d.element_length = -1;
  EXPECT_THROW(catenary::FeCatenary{d}, InvalidArgument);
}

TEST(CostGuard, TheNoteAndTheRefusalSayWhatAndHow) {
  EXPECT_EQ(analysis::cost_note(9.9, "this run"), "");
  const std::string note = analysis::cost_note(125, "this run");
  EXPECT_NE(note.find("note: this run is estimated at about 2 min on a 2-core machine"), std::string::npos) << note;
  try {
    analysis::check_cost(4000, 600, "this sweep of 3 speeds", "give --max-seconds", "fewer spans");
    FAIL() << "not refused";
  } catch (const analysis::CostLimitError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("this sweep of 3 speeds is estimated at about 67 min on a 2-core machine, above the limit of 600 s; "
                     "give --max-seconds 6000 to run it anyway, or make it cheaper (fewer spans)"),
              std::string::npos)
        << m;
  }
  EXPECT_NO_THROW(analysis::check_cost(599, 600, "x", "y", ""));
  EXPECT_EQ(analysis::format_duration(3 * 86400), "about 3 days");
  EXPECT_NO_THROW(analysis::check_memory(1e6, "x", "y"));
  EXPECT_THROW(analysis::check_memory(1e18, "x", "y"), analysis::CostLimitError);
}

TEST(CostGuard, EveryRunsSpeedEndsInTimeAndIsOneATrainCanHave) {
  const catenary::Lumped lumped{catenary::LumpedCatenary{}};
  EXPECT_NO_THROW(analysis::check_run_speed(lumped, 250 / 3.6, 40, false));
  // 1e-9 km/h: 40 spans would last ~1e14 s; 1e300 and 1e7 km/h: no train.
  EXPECT_THROW(analysis::check_run_speed(lumped, 1e-9 / 3.6, 40, false), ModelError);
  EXPECT_THROW(analysis::check_run_speed(lumped, 1e300, 40, false), ModelError);
  EXPECT_THROW(analysis::check_run_speed(lumped, 1e7 / 3.6, 40, false), ModelError);
  EXPECT_THROW(analysis::check_run_speed(lumped, std::numeric_limits<double>::quiet_NaN(), 40, false), ModelError);
  // A given t_end (spans 0): only the speed itself.
  EXPECT_NO_THROW(analysis::check_run_speed(lumped, 1e-9, 0, false));
  // The FE line: refused above the contact wire's wave speed unless allowed; warned from 70 %.
  const catenary::FeCatenary fe(inerta::testing::fe_benchmark_line(10));
  const double c = fe.wave_speed();
  EXPECT_NEAR(c * 3.6, 459.6, 0.05);
  EXPECT_THROW(analysis::check_run_speed(fe, 600 / 3.6, 40, false), ModelError);
  EXPECT_NO_THROW(analysis::check_run_speed(fe, 600 / 3.6, 40, true));
  EXPECT_EQ(analysis::speed_warning(fe, 0.69 * c), "");
  EXPECT_NE(analysis::speed_warning(fe, 0.71 * c).find("71 % of the contact wire's wave speed"), std::string::npos);
  EXPECT_EQ(analysis::speed_warning(lumped, 1000), "");
}

}  // namespace test_analysis_cost_guard
