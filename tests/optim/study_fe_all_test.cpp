// Every network on the finite-element line (issue 37): `layouts: all` with a coarse study searches
// every network on the coarse study, then refines the best distinct reduced networks on the fine
// line and ranks them there; catenary variants as a product (irregularity seeds × tensions),
// reproducible bit for bit; model overrides (`set:`) in a J2 study; the file's errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/report.hpp"
#include "inerta/optim/structure_search.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/optim/study_run.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_study_fe_all {

using namespace inerta;
using inerta::testing::write_study;

namespace {
const std::string kDir = INERTA_SOURCE_DIR;
// A short FE line (3 spans, modes below 30 Hz) at one speed, one variant; every network of up to two
// elements searched on the FE-fitted lumped line, the best three distinct reduced networks refined.
const std::string kAll = "name: small FE all\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                         "/models/catenary-fe.yaml\n"
                         "catenaries: [[line.spans=3, solver.cutoff=30]]\n"
                         "speeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                         "limits: {contact_loss: 0}\n"
                         "bounds: {inerter: [0.1, 1000], spring: [1, 1.0e6], damper: [1, 1.0e5]}\n"
                         "layouts: all\n"
                         "networks: {max_elements: 2}\n"
                         "coarse:\n"
                         "  catenary: " + kDir + "/models/catenary-fe-lumped.yaml\n"
                         "  catenaries: [[catenary.mc1=0, catenary.mc2=0, catenary.mc3=0]]\n"
                         "  speeds: {from: 150, to: 250, step: 50, unit: kmh}\n"
                         "  search: {starts: 1, seed: 1, min_step: 0.1}\n"
                         "refine: {best_networks: 3, initial_step: 0.3, min_step: 0.1, max_evaluations: 5}\n";

// The same short line with dropper-length errors: seeds × tensions as a product.
const std::string kHead = "name: seeds\nmodel: " + kDir + "/models/hsx.yaml\ncatenary: " + kDir +
                          "/models/catenary-fe.yaml\n"
                          "speeds: {from: 200, to: 200, step: 10, unit: kmh}\n"
                          "layouts: [S2-5]\n";
const std::string kProduct =
    kHead +
    "catenaries:\n"
    "  product:\n"
    "    - [[line.spans=3, solver.cutoff=30, irregularity.dropper_length_std=0.01, irregularity.seed=1],\n"
    "       [line.spans=3, solver.cutoff=30, irregularity.dropper_length_std=0.01, irregularity.seed=2]]\n"
    "    - [[], [contact_wire.tension=24200]]\n";

std::string error_of(const std::string& name, const std::string& text) { return inerta::testing::study_error(name, text); }
}  // namespace

TEST(StudyFeAll, TheRefinedRankingEqualsABruteForceEvaluationOfTheSameCandidates) {
  const optim::Study s = io::load_study(write_study("fe_all.yaml", kAll));
  ASSERT_TRUE(s.all && s.coarse);
  EXPECT_EQ(s.refine_networks, 3);
  EXPECT_EQ(s.method, optim::Study::Method::Time);
  const optim::StudyOutcome o = optim::run_study(s);

  // Brute force, call by call: the exhaustive search on the coarse study alone ...
  std::vector<optim::LayoutResult> coarse_results;
  const std::vector<optim::StructureEntry> entries = optim::optimise_all(*s.coarse, coarse_results);
  ASSERT_EQ(entries.size(), o.entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(entries[i].expression, o.entries[i].expression);
    EXPECT_EQ(entries[i].J, o.entries[i].J) << entries[i].expression;
  }
  // ... its best three distinct reduced networks with a design (the candidates) ...
  std::vector<std::string> structures;
  std::vector<std::pair<std::string, network::Params>> candidates;
  for (std::size_t i : optim::ranking(entries)) {
    if (candidates.size() == 3) break;
    const auto d = optim::reduced_design(entries[i]);
    if (!std::isfinite(entries[i].J) || !d ||
        std::find(structures.begin(), structures.end(), entries[i].reduced_structure) != structures.end())
      continue;
    structures.push_back(entries[i].reduced_structure);
    candidates.push_back(*d);
  }
  ASSERT_EQ(candidates.size(), 3u);
  ASSERT_EQ(o.results.size(), 3u);
  ASSERT_EQ(o.refinements.size(), 3u);
  // ... each refined on the FE line from its coarse optimum, one after another, and every final design
  // evaluated there again (run_study refines the three side by side, their evaluations gathered into
  // lanes by a LaneBatcher: issue 50 — the same paths, bit for bit).
  struct Row {
    std::string expression;
    double J, penalised;
    network::Params values;
  };
  std::vector<Row> brute;
  for (const auto& [expression, values] : candidates) {
    optim::LayoutResult start;
    start.layout = start.expression = expression;
    start.values = values;
    const optim::LayoutResult r = optim::refine_layout(s, expression, start);
    const optim::StudyCost again = optim::evaluate(s, optim::design_network(expression, r.values));
    EXPECT_EQ(again.J, r.cost.J) << expression;  // the same line, the same runs: bit for bit
    EXPECT_LE(r.cost.penalised(), r.coarse_here.penalised()) << expression;  // never worse than its start
    brute.push_back({expression, r.cost.J, r.cost.penalised(), r.values});
  }
  std::stable_sort(brute.begin(), brute.end(), [](const Row& a, const Row& b) { return a.penalised < b.penalised; });
  for (std::size_t k = 0; k < brute.size(); ++k) {
    EXPECT_EQ(o.results[k].expression, brute[k].expression) << "rank " << k + 1;
    EXPECT_EQ(o.results[k].cost.J, brute[k].J) << "rank " << k + 1;
    EXPECT_EQ(o.results[k].values, brute[k].values) << "rank " << k + 1;
    EXPECT_EQ(o.entries[o.refinements[k].entry].reduced_structure,
              structures[static_cast<std::size_t>(o.refinements[k].coarse_rank - 1)]);
  }
  // The recommendation is the first of the FE line's ranking, its J2 the FE line's.
  EXPECT_EQ(o.best.index, 0u);
  EXPECT_EQ(o.best.J, brute.front().J);
  EXPECT_EQ(o.time_check.J, brute.front().J);
  // refined.csv: one row per refined network, in rank order.
  const std::string csv = o.refined_csv();
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_NE(csv.find("1,\"" + brute.front().expression + "\""), std::string::npos);
}

TEST(StudyFeAll, TheScreenRefinesTheBestOfTheCoarseCandidatesByTheFineStage) {
  // The best four distinct reduced networks of the coarse search, each evaluated on the FE line at its
  // coarse optimum; the best two by that refined (issue 49: the fine stage chooses what it refines).
  std::string text = kAll;
  const std::string old_refine = "refine: {best_networks: 3, initial_step: 0.3, min_step: 0.1, max_evaluations: 5}\n";
  text.replace(text.find(old_refine), old_refine.size(),
               "refine: {best_networks: 2, screen: 4, initial_step: 0.3, min_step: 0.1, max_evaluations: 2}\n");
  // Two speeds: the early stops run the faster first and may stop a candidate after it (issue 50).
  text.replace(text.find("speeds: {from: 200, to: 200, step: 10"), 37, "speeds: {from: 200, to: 250, step: 50");
  const optim::Study s = io::load_study(write_study("fe_screen.yaml", text));
  ASSERT_EQ(s.refine_screen, 4);
  const optim::StudyOutcome o = optim::run_study(s);
  // The candidates, as the coarse search ranks them; each evaluated here by hand.
  std::vector<std::string> structures;
  std::vector<std::pair<std::size_t, std::pair<std::string, network::Params>>> candidates;
  for (std::size_t i : o.order) {
    if (candidates.size() == 4) break;
    const auto d = optim::reduced_design(o.entries[i]);
    if (!std::isfinite(o.entries[i].J) || !d ||
        std::find(structures.begin(), structures.end(), o.entries[i].reduced_structure) != structures.end())
      continue;
    structures.push_back(o.entries[i].reduced_structure);
    candidates.push_back({i, *d});
  }
  ASSERT_EQ(candidates.size(), 4u);
  ASSERT_EQ(o.screened.size(), 4u);
  // Each candidate evaluated here in full, by hand: the screen without early stops (issue 50). The first two by
  // the coarse rank run in full; a later one stops once it is worse than both (its J a lower bound).
  std::vector<double> full(4);
  for (std::size_t r = 0; r < 4; ++r)
    full[r] = optim::evaluate(s, optim::design_network(candidates[r].second.first, candidates[r].second.second)).penalised();
  std::vector<std::size_t> by_hand{0, 1, 2, 3};
  std::stable_sort(by_hand.begin(), by_hand.end(), [&](std::size_t a, std::size_t b) { return full[a] < full[b]; });
  for (std::size_t k = 0; k < o.screened.size(); ++k) {
    const optim::Screened& c = o.screened[k];
    ASSERT_GE(c.coarse_rank, 1);
    const auto r = static_cast<std::size_t>(c.coarse_rank - 1);
    const auto& [entry, design] = candidates[r];
    EXPECT_EQ(c.entry, entry);
    EXPECT_EQ(c.refined, k < 2);
    if (c.stopped) {
      EXPECT_GE(r, 2u) << design.first;  // the first two are the incumbents
      EXPECT_LE(c.cost.J, full[r]) << design.first;
      EXPECT_GT(full[r], std::max(full[0], full[1])) << design.first;
      continue;
    }
    EXPECT_EQ(c.cost.penalised(), full[r]) << design.first;  // the same design on the same line: bit for bit
    if (k < 2) {
      EXPECT_EQ(by_hand[k], r) << "rank " << k + 1;  // the refined are the full evaluations' best two
    }
    if (k > 0) {
      EXPECT_LE(o.screened[k - 1].cost.penalised(), c.cost.penalised());  // best first
    }
  }
  EXPECT_GE(std::count_if(o.screened.begin(), o.screened.end(), [](const auto& c) { return c.stopped; }), 1);
  // The refined networks are the screen's best two, each refined from the point the screen evaluated.
  ASSERT_EQ(o.results.size(), 2u);
  std::vector<std::size_t> refined_entries;
  for (std::size_t k = 0; k < o.results.size(); ++k) {
    const optim::Refinement& f = o.refinements[k];
    refined_entries.push_back(f.entry);
    ASSERT_GE(f.screen_rank, 1);
    ASSERT_LE(f.screen_rank, 2);
    const optim::Screened& c = o.screened[static_cast<std::size_t>(f.screen_rank - 1)];
    EXPECT_EQ(c.entry, f.entry);
    EXPECT_EQ(c.coarse_rank, f.coarse_rank);
    EXPECT_NEAR(o.results[k].coarse_here.J, c.cost.J, 1e-9 * c.cost.J) << o.results[k].expression;
  }
  std::sort(refined_entries.begin(), refined_entries.end());
  std::vector<std::size_t> best_two{o.screened[0].entry, o.screened[1].entry};
  std::sort(best_two.begin(), best_two.end());
  EXPECT_EQ(refined_entries, best_two);
  // Two networks: Spearman's ρ is ±1 — +1 if the fine stage keeps the order they were chosen in.
  const bool kept = (o.refinements[0].screen_rank < o.refinements[1].screen_rank) ==
                    (o.results[0].cost.penalised() <= o.results[1].cost.penalised());
  EXPECT_EQ(o.rank_agreement, kept ? 1.0 : -1.0);
  EXPECT_TRUE(o.coarse_rank_agreement == 1.0 || o.coarse_rank_agreement == -1.0);
  const std::string csv = o.screened_csv();
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_NE(o.refined_csv().find(",screen_rank\n"), std::string::npos);
  std::filesystem::remove(inerta::testing::temp_dir() / "fe_screen.yaml");
}

TEST(StudyFeAll, SeedsTimesTensionsAsAProductAreReproducibleBitForBit) {
  const optim::Study a = io::load_study(write_study("seeds_a.yaml", kProduct));
  ASSERT_EQ(a.catenaries.size(), 4u);  // the first factor varies slowest
  EXPECT_NE(a.catenary_labels[0].find("irregularity.seed=1"), std::string::npos);
  EXPECT_EQ(a.catenary_labels[0].find("tension"), std::string::npos);
  EXPECT_NE(a.catenary_labels[1].find("irregularity.seed=1"), std::string::npos);
  EXPECT_NE(a.catenary_labels[1].find("contact_wire.tension=24200"), std::string::npos);
  EXPECT_NE(a.catenary_labels[3].find("irregularity.seed=2"), std::string::npos);
  // Loaded again (new lines, new mode sets): every variant's σ and mean equal to the last bit.
  const optim::Study b = io::load_study(write_study("seeds_b.yaml", kProduct));
  const network::Network net = optim::default_suspension(a);
  const auto ca = optim::sigma_curves_time(a, net), cb = optim::sigma_curves_time(b, net);
  ASSERT_EQ(ca.size(), 4u);
  ASSERT_EQ(cb.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(ca[i].sigma, cb[i].sigma) << a.catenary_labels[i];
    EXPECT_EQ(ca[i].mean, cb[i].mean) << a.catenary_labels[i];
  }
  EXPECT_EQ(optim::evaluate(a, net).J, optim::evaluate(b, net).J);
  // The seeds are different lines; a listed variant is the product's.
  EXPECT_NE(ca[0].sigma, ca[2].sigma);
  const optim::Study listed = io::load_study(write_study(
      "seeds_listed.yaml",
      kHead + "catenaries:\n  - [line.spans=3, solver.cutoff=30, irregularity.dropper_length_std=0.01, irregularity.seed=2, "
              "contact_wire.tension=24200]\n"));
  const auto cl = optim::sigma_curves_time(listed, net);
  ASSERT_EQ(cl.size(), 1u);
  EXPECT_EQ(cl[0].sigma, ca[3].sigma);
  EXPECT_EQ(cl[0].mean, ca[3].mean);
}

TEST(StudyFeAll, ModelOverridesSetTheAerodynamicUplift) {
  const optim::Study s = io::load_study(write_study("set.yaml", kHead + "set: [pantograph.aerodynamic.a=0.0032]\n"), false);
  EXPECT_EQ(s.pantograph.aero.a, 0.0032);
  const optim::Study plain = io::load_study(write_study("noset.yaml", kHead), false);
  EXPECT_EQ(plain.pantograph.aero.a, 0.0);
}

TEST(StudyFeAll, FileErrorsNameFileLineAndKey) {
  // An override that matches nothing in the model.
  std::string e = error_of("bad_set.yaml", kHead + "set: [no_such_element.k=1]\n");
  EXPECT_NE(e.find("bad_set.yaml:6"), std::string::npos) << e;
  EXPECT_NE(e.find("set"), std::string::npos) << e;
  e = error_of("bad_set2.yaml", kHead + "set: pantograph.aerodynamic.a=1\n");
  EXPECT_NE(e.find("bad_set2.yaml:6: 'set'"), std::string::npos) << e;
  // A screen smaller than what it must choose from.
  std::string small = kAll;
  small.replace(small.find("refine: {best_networks: 3,"), 26, "refine: {screen: 2, best_networks: 3,");
  e = error_of("bad_screen2.yaml", small);
  EXPECT_NE(e.find("refine.screen"), std::string::npos) << e;
  EXPECT_NE(e.find("expected screen >= best_networks"), std::string::npos) << e;
  // A product factor that is not a list of override lists; a map other than {product: ...}.
  e = error_of("bad_product.yaml", kHead + "catenaries:\n  product:\n    - [irregularity.seed=1]\n");
  EXPECT_NE(e.find("bad_product.yaml:8"), std::string::npos) << e;
  EXPECT_NE(e.find("product"), std::string::npos) << e;
  e = error_of("bad_product2.yaml", kHead + "catenaries: {sum: [[[]]]}\n");
  EXPECT_NE(e.find("bad_product2.yaml:6"), std::string::npos) << e;
  EXPECT_NE(e.find("catenaries"), std::string::npos) << e;
  // best_networks belongs to layouts: all.
  std::string named = kAll;
  named.replace(named.find("layouts: all\nnetworks: {max_elements: 2}\n"), 41, "layouts: [k]\n");
  e = error_of("bad_best.yaml", named);
  EXPECT_NE(e.find("best_networks"), std::string::npos) << e;
  EXPECT_NE(e.find("layouts: all"), std::string::npos) << e;
  // The admittance bound would be a search on the fine line.
  e = error_of("bad_adm.yaml", kAll + "admittance: [2]\n");
  EXPECT_NE(e.find("admittance"), std::string::npos) << e;
}

// Issue 52: a bad catenary override in a study names the study file and the override's line; a CSV
// named in an override is relative to the study file; a height-error CSV without data is refused.
TEST(StudyFeAll, AStudysCatenaryOverridesAreCheckedAtTheirLineAndTheirFilesBesideIt) {
  std::string e = error_of("bad_cat.yaml", kHead + "catenaries:\n  - [line.spans=3]\n  - [line.spans=3, no_such.key=1]\n");
  EXPECT_NE(e.find("bad_cat.yaml:8"), std::string::npos) << e;  // the second variant's line
  EXPECT_NE(e.find("no_such.key=1"), std::string::npos) << e;
  e = error_of("bad_cat2.yaml", kHead + "catenaries:\n  product:\n    - [[line.spans=3]]\n    - [[contact_wire.tension=abc]]\n");
  EXPECT_NE(e.find("bad_cat2.yaml:9"), std::string::npos) << e;
  EXPECT_NE(e.find("'abc' is not a number"), std::string::npos) << e;
  // height_errors relative to the study file: found beside it whatever the working directory.
  const auto dir = inerta::testing::temp_dir();
  std::ofstream(dir / "dz_ok.csv") << "x,dz\n0,0\n10000,0\n";
  std::ofstream(dir / "dz_empty.csv") << "x,dz\n";
  e = error_of("rel_ok.yaml", kHead + "catenaries: [[line.spans=3, irregularity.height_errors=dz_ok.csv]]\n");
  EXPECT_EQ(e, "");
  e = error_of("rel_empty.yaml", kHead + "catenaries: [[line.spans=3, irregularity.height_errors=dz_empty.csv]]\n");
  EXPECT_NE(e.find("rel_empty.yaml:6"), std::string::npos) << e;
  EXPECT_NE(e.find("0 data row(s)"), std::string::npos) << e;
  std::filesystem::remove(dir / "dz_ok.csv"), std::filesystem::remove(dir / "dz_empty.csv");
}

}  // namespace test_optim_study_fe_all
