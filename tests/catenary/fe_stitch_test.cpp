// Stitched catenaries and irregular lines on the finite-element line (issue 34, docs/catenary-fe.md
// "Stitch wire", "Irregularities"): the stitch removed is the simple line with the same droppers;
// the static states are equilibria of the assembled line; the stitch evens the elasticity; the
// irregular line's random errors are reproducible, zero errors are the perfect line, a point mass
// sags the wire by its static influence; bad input names the file and key.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/fe_modal.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/numerics/random.hpp"
#include "support/fe_line.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_catenary_fe_stitch {

using namespace inerta;
using catenary::FeCatenaryData;
using catenary::FeLine;

// A 4-span stitched line of the bundled file's design (its data, fewer spans: fast).
FeCatenaryData stitched(int spans = 4) {
  FeCatenaryData d = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml", {});
  d.spans = spans;
  d.solver = FeCatenaryData::Solver::Direct;
  return d;
}

// Elasticity along span `s` (1-based) at n points, m/N.
std::vector<double> elasticity_along(const FeLine& line, int s, int n) {
  std::vector<double> e;
  const double L = line.data().span;
  for (int i = 0; i <= n; ++i) e.push_back(line.elasticity((s - 1) * L + L * i / n));
  return e;
}

TEST(FeStitch, DisabledIsTheSimpleLineWithTheSameDroppers) {
  FeCatenaryData a = stitched();
  a.stitch.enabled = false;
  // The same droppers in a simple-line description: the stitch droppers' data equal the span
  // droppers' in the bundled file, so one list of positions and pre-sags holds them all.
  ASSERT_EQ(a.stitch.dropper_EA, a.dropper_EA);
  ASSERT_EQ(a.stitch.dropper_mass_per_length, a.dropper_mass_per_length);
  ASSERT_EQ(a.stitch.clamp_mass_stitch, a.clamp_mass_messenger);
  ASSERT_EQ(a.stitch.clamp_mass_contact, a.clamp_mass_contact);
  FeCatenaryData b = a;
  b.stitch = {};
  std::vector<std::pair<double, double>> xs;
  for (std::size_t j = 0; j < a.dropper_x.size(); ++j) xs.push_back({a.dropper_x[j], a.presag[j]});
  for (std::size_t j = 0; j < a.stitch.dropper_x.size(); ++j) {
    const double p = a.stitch.dropper_x[j];
    xs.push_back({p > 0 ? p : a.span + p, a.stitch.dropper_presag.empty() ? 0.0 : a.stitch.dropper_presag[j]});
  }
  std::sort(xs.begin(), xs.end());
  b.dropper_x.clear(), b.presag.clear(), b.nominal_dropper_length.clear();
  for (const auto& [x, p] : xs) b.dropper_x.push_back(x), b.presag.push_back(p);
  const FeLine la(a), lb(b);
  ASSERT_EQ(la.n_dofs(), lb.n_dofs());
  ASSERT_EQ(la.droppers().size(), lb.droppers().size());
  const double kn = lb.K().norm(), mn = lb.M().norm();
  EXPECT_LE((la.K() - lb.K()).norm(), 1e-12 * kn);
  EXPECT_LE((la.M() - lb.M()).norm(), 1e-12 * mn);
  for (std::size_t k = 0; k < la.droppers().size(); ++k) {
    EXPECT_NEAR(la.droppers()[k].tension, lb.droppers()[k].tension, 1e-9 * std::abs(lb.droppers()[k].tension)) << k;
    EXPECT_NEAR(la.droppers()[k].length, lb.droppers()[k].length, 1e-12) << k;
  }
  for (double x = 0; x <= la.length(); x += 7.3) {
    EXPECT_NEAR(la.static_height(x), lb.static_height(x), 1e-12) << x;
    EXPECT_NEAR(la.elasticity(x), lb.elasticity(x), 1e-10 * lb.elasticity(x)) << x;
  }
}

TEST(FeStitch, FormFoundStitchedLineIsAnEquilibriumWithItsStitchOnTheMessenger) {
  const FeLine line(stitched());
  const FeLine::Residual r = line.equilibrium_residual();
  // The residual of the assembled equations against the largest gravity load of a DOF.
  EXPECT_LT(r.force, 1e-8 * r.load_scale) << r.force << " N of " << r.load_scale;
  EXPECT_LT(r.dropper, 1e-8);
  // The contact wire at its prescribed heights at every dropper, stitch droppers included.
  for (const auto& dr : line.droppers()) EXPECT_NEAR(line.static_height(dr.x), 0.0, 1e-9) << dr.x;
  // The stitch wire: at the messenger's height at its clamps, below it in between (it carries the
  // droppers near the mast), and never below the contact wire.
  int stitch_nodes = 0;
  for (int n = 0; n < line.n_nodes(); ++n) {
    const double ys = line.stitch_height(n);
    if (std::isnan(ys)) continue;
    ++stitch_nodes;
    EXPECT_LE(ys, line.messenger_height(n) + 1e-12);
    EXPECT_GT(ys, 0.5);
  }
  EXPECT_GT(stitch_nodes, 3 * 72);  // 3 interior masts, 18 m each at <= 0.25 m
  int on_stitch = 0;
  for (const auto& dr : line.droppers()) on_stitch += dr.on_stitch_wire;
  EXPECT_EQ(on_stitch, 3 * static_cast<int>(line.data().stitch.dropper_x.size()));  // the end masts carry no stitch wire
}

TEST(FeStitch, TheStitchEvensTheElasticityAlongASpan) {
  FeCatenaryData d = stitched(4);
  const FeLine with(d);
  d.stitch.enabled = false;
  const FeLine without(d);
  const std::vector<double> a = elasticity_along(with, 2, 130), b = elasticity_along(without, 2, 130);
  const auto ratio = [](const std::vector<double>& e) {
    return *std::max_element(e.begin(), e.end()) / *std::min_element(e.begin(), e.end());
  };
  std::fprintf(stderr, "elasticity max/min along span 2: stitched %.4f (%.4f … %.4f mm/N), without %.4f (%.4f … %.4f mm/N)\n",
               ratio(a), 1e3 * *std::min_element(a.begin(), a.end()), 1e3 * *std::max_element(a.begin(), a.end()),
               ratio(b), 1e3 * *std::min_element(b.begin(), b.end()), 1e3 * *std::max_element(b.begin(), b.end()));
  EXPECT_LT(ratio(a), ratio(b));
  // Softer at the mast (the droppers there hang from the stitch wire, not the support).
  EXPECT_GT(a.front(), b.front());
}

TEST(FeStitch, AVanishingStitchConvergesToTheLineWithoutItsDroppers) {
  // Stitch tension, EI, mass and dropper stiffness scaled by ε, the stitch droppers' clamps massless:
  // the elasticity along a span converges to that of the line without them as ε → 0.
  FeCatenaryData base = stitched(4);
  FeCatenaryData simple = base;
  simple.stitch = {};
  const FeLine ls(simple);
  auto diff = [&](double eps) {
    FeCatenaryData d = base;
    d.stitch.wire.tension *= eps, d.stitch.wire.EI *= eps, d.stitch.wire.mass_per_length *= eps;
    d.stitch.dropper_EA *= eps;
    d.stitch.dropper_mass_per_length = d.stitch.clamp_mass_stitch = d.stitch.clamp_mass_contact = d.stitch.clamp_mass = 0;
    d.stitch.dropper_presag.clear();
    // Each stitch dropper's contact-wire target 1e-3 ε m above the height the line without it has
    // there (so it pulls, with a tension that vanishes with ε), through a height-error profile: the
    // stitch droppers' pre-sag is one value an offset from a mast, the heights differ mast to mast.
    d.stitch.dropper_presag.assign(d.stitch.dropper_x.size(), 0.0);
    std::vector<std::pair<double, double>> prof{{0.0, 0.0}, {d.spans * d.span, 0.0}};
    for (int m = 0; m < d.spans; ++m)
      for (double x : d.dropper_x) prof.push_back({m * d.span + x, 0.0});
    for (int m = 0; m <= d.spans; ++m)
      for (double p : d.stitch.dropper_x)
        if (const double x = m * d.span + p; x > 0 && x < d.spans * d.span)
          prof.push_back({x, ls.static_height(x) + 1e-3 * eps});
    std::sort(prof.begin(), prof.end());
    for (const auto& [x, dz] : prof) d.irregularity.height_error_x.push_back(x), d.irregularity.height_error_dz.push_back(dz);
    const FeLine l(d);
    double worst = 0;
    for (int i = 1; i < 40; ++i) {
      const double x = 1.5 * d.span + d.span * i / 40.0;  // span 2's second half and span 3's first
      worst = std::max(worst, std::abs(l.elasticity(x) - ls.elasticity(x)) / ls.elasticity(x));
    }
    return worst;
  };
  const double d2 = diff(1e-2), d4 = diff(1e-4);
  std::fprintf(stderr, "vanishing stitch: elasticity difference %.3g (ε = 1e-2), %.3g (ε = 1e-4)\n", d2, d4);
  EXPECT_LT(d4, 0.3 * d2);
  EXPECT_LT(d4, 2e-3);  // what is left: the extra stations of the stitched mesh
}

TEST(FeStitch, TheBundledStitchedLineMeetsItsPublishedElasticity) {
  // Issue 48: the bundled line calibrated to the published design elasticity of its type (SICAT H1.0:
  // 0.40 mm/N at the support, 0.44 mm/N mid-span; Orden FOM/1630/2015, Cuadro 3.6), each within 10 %,
  // and a stitched line's even elasticity: max/min ≤ 1.25 along a span (span 5 of 10, 220 points
  // as `inerta catenary fit --table`, and the mast itself).
  const FeCatenaryData d = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml", {});
  const FeLine line(d);
  const double L = d.span, x0 = 4 * L;
  const double mast = line.elasticity(x0), mid = line.elasticity(x0 + L / 2);
  double lo = mast, hi = mast;
  for (int i = 0; i < 220; ++i) {
    const double e = line.elasticity(x0 + L * (i + 0.5) / 220);
    lo = std::min(lo, e), hi = std::max(hi, e);
  }
  std::fprintf(stderr, "bundled stitched line: mast %.4f, mid-span %.4f mm/N; %.4f … %.4f mm/N, max/min %.4f\n", 1e3 * mast,
               1e3 * mid, 1e3 * lo, 1e3 * hi, hi / lo);
  EXPECT_NEAR(mast, 0.40e-3, 0.1 * 0.40e-3);
  EXPECT_NEAR(mid, 0.44e-3, 0.1 * 0.44e-3);
  EXPECT_LE(hi / lo, 1.25);
  // Its design: the stitch droppers 5 m from the mast, five span droppers (issue 48's public layout).
  EXPECT_EQ(d.stitch.dropper_x, (std::vector<double>{-5, 5}));
  EXPECT_EQ(d.dropper_x.size(), 5u);
}

TEST(FeStitch, ModalIsTheDirectSolveWithinTwoPercentAt250To350KmH) {
  // The bundled stitched line, one span shorter (9 spans: its window of 2 spans behind and 5 ahead
  // still moves; issue 52: the test suite's budget), its own cut-off and window: σ raw and after the
  // 20 Hz low-pass within 2 % of the direct solve (check-reduction's tolerance) — the 3-mass at 250
  // and 350 km/h, the HSX at 300 km/h (one direct solve a speed: issue 52, the test suite's budget).
  const std::string file = INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml";
  const auto direct = io::load_catenary(file, {"solver.type=direct", "line.spans=9"});
  const auto reduced = io::load_catenary(file, {"line.spans=9"});
  const FeCatenaryData d = io::read_fe_catenary_data(file, {"line.spans=9"});
  ASSERT_LT(d.window_behind + 1 + d.window_ahead, d.spans);  // the window moves along the line
  for (const char* model : {"pantograph-3mass.yaml", "hsx.yaml"}) {
    const auto panto = io::load_pantograph(std::string(INERTA_SOURCE_DIR "/models/") + model);
    const std::vector<double> speeds = model == std::string("hsx.yaml") ? std::vector<double>{300 / 3.6}
                                                                         : std::vector<double>{250 / 3.6, 350 / 3.6};
    const auto rows = analysis::compare({{panto, 0.0, direct.contact}}, *direct.catenary, *reduced.catenary, speeds, {});
    for (const auto& r : rows) {
      EXPECT_NEAR(r.candidate.stats.std, r.reference.stats.std, 0.02 * r.reference.stats.std) << model << " " << r.speed * 3.6;
      EXPECT_NEAR(r.candidate.filtered[0].std, r.reference.filtered[0].std, 0.02 * r.reference.filtered[0].std)
          << model << " " << r.speed * 3.6;
    }
  }
}

TEST(FeStitch, InteriorWindowsShareOneDecomposition) {
  // The stitched line's interior windows differ mast to mast by ≈ 0.1 % in their droppers (the
  // stitch wires carry the end spans' influence further in) and share one decomposition, as a simple
  // line's do: first, interior, last = the first mirrored; two eigenproblems.
  FeCatenaryData d = stitched(10);
  d.solver = FeCatenaryData::Solver::Modal;
  d.modal_cutoff = 20;
  d.element_length = 1.0;
  const catenary::FeModalLine ml(std::make_shared<const FeLine>(d));
  ml.prepare(6);
  EXPECT_EQ(ml.shapes(), 3);
  EXPECT_EQ(ml.decompositions(), 2);
  EXPECT_EQ(ml.window(1, 6)->modes, ml.window(2, 6)->modes);
  EXPECT_EQ(ml.window(1, 6)->modes, ml.window(3, 6)->modes);
  // But not an irregular line's windows with each dropper's own stiffness (≈ 1 % apart at 10 mm).
  d.irregularity.dropper_length_std = 0.01;
  d.irregularity.exact_dropper_dynamics = true;
  const catenary::FeModalLine irr(std::make_shared<const FeLine>(d));
  irr.prepare(6);
  EXPECT_EQ(irr.shapes(), 5);
}

TEST(FeIrregularity, ZeroErrorsAreThePerfectLine) {
  FeCatenaryData d = inerta::testing::fe_benchmark_line(4);
  const FeLine perfect(d);
  d.irregularity.dropper_length_errors.assign(perfect.droppers().size(), 0.0);
  d.irregularity.dropper_length_std = 0;
  d.irregularity.seed = 99;
  const FeLine same(d);
  EXPECT_EQ((same.K() - perfect.K()).norm(), 0.0);
  EXPECT_EQ((same.M() - perfect.M()).norm(), 0.0);
  for (double x = 0; x <= perfect.length(); x += 3.1) EXPECT_EQ(same.static_height(x), perfect.static_height(x));
}

TEST(FeIrregularity, RandomErrorsAreReproducibleAndHaveTheirStd) {
  catenary::FeIrregularity irr;
  irr.dropper_length_std = 0.005;
  irr.seed = 7;
  const std::vector<double> a = catenary::dropper_length_errors(irr, 20000), b = catenary::dropper_length_errors(irr, 20000);
  EXPECT_EQ(a, b);
  irr.seed = 8;
  EXPECT_NE(catenary::dropper_length_errors(irr, 10), std::vector<double>(a.begin(), a.begin() + 10));
  double mean = 0, var = 0, peak = 0;
  for (double v : a) mean += v / a.size(), peak = std::max(peak, std::abs(v));
  for (double v : a) var += (v - mean) * (v - mean) / (a.size() - 1);
  // N(0, σ²) truncated at ±4σ: standard deviation σ·0.99959; the mean within 4 standard errors.
  EXPECT_NEAR(std::sqrt(var), 0.005 * 0.99959, 0.005 * 0.02);
  EXPECT_LT(std::abs(mean), 4 * 0.005 / std::sqrt(20000.0));
  EXPECT_LE(peak, 4 * 0.005);
  // The portable logarithm against the library's.
  for (double x : {1e-300, 1e-9, 0.3, 0.70710678, 0.9999999, 1.0, 1.5, 7.0, 1e200})
    EXPECT_NEAR(numerics::portable_log(x), std::log(x), 4e-16 * std::max(1.0, std::abs(std::log(x)))) << x;
}

TEST(FeIrregularity, TheIrregularStaticStateIsAnEquilibriumAtTheFixedLengths) {
  FeCatenaryData d = inerta::testing::fe_benchmark_line(4);
  d.irregularity.dropper_length_std = 0.01;
  d.irregularity.seed = 3;
  d.irregularity.point_masses = {{60.3, 5.0}, {131.0, 2.5}};
  const FeLine line(d);
  const FeLine::Residual r = line.equilibrium_residual();
  EXPECT_LT(r.force, 1e-7 * r.load_scale) << r.force << " N of " << r.load_scale;
  EXPECT_LT(r.dropper, 1e-7);
  // The unstretched lengths are the form-found ones plus the errors.
  FeCatenaryData p = d;
  p.irregularity = {};
  const FeLine perfect(p);
  const std::vector<double> e = catenary::dropper_length_errors(d.irregularity, perfect.droppers().size());
  for (std::size_t k = 0; k < e.size(); ++k)
    EXPECT_NEAR(line.droppers()[k].length, perfect.droppers()[k].length + e[k], 1e-12) << k;
}

TEST(FeIrregularity, DropperErrorsKeepThePerfectLinesDynamicsAndItsModes) {
  // Dropper-length and height errors change the static state (exactly: K_static, the tensions) but
  // not K and M, which hold the droppers as designed: the modal solve shares the perfect line's modes.
  FeCatenaryData d = inerta::testing::fe_benchmark_line(4);
  const FeLine perfect(d);
  d.irregularity.dropper_length_std = 0.01;
  d.irregularity.seed = 5;
  d.irregularity.height_error_x = {0, 120, 220};
  d.irregularity.height_error_dz = {0, -0.02, 0.01};
  const FeLine line(d);
  EXPECT_EQ((line.K() - perfect.K()).norm(), 0.0);
  EXPECT_EQ((line.M() - perfect.M()).norm(), 0.0);
  EXPECT_GT((line.K_static() - perfect.K_static()).norm(), 1e3);
  d.irregularity.exact_dropper_dynamics = true;
  const FeLine exact(d);
  EXPECT_EQ((exact.K() - exact.K_static()).norm(), 0.0);
  EXPECT_GT((exact.M() - perfect.M()).norm(), 0.0);
}

TEST(FeIrregularity, TheDesignedDroppersInTheDynamicsChangeSigmaByLessThanATenthOfAPercent) {
  // 10 mm dropper-length errors, the direct solve: σ (raw and 20 Hz) with the droppers' stiffness
  // and mass as designed against their own (exact_dropper_dynamics), 3-mass at 250 and 300 km/h.
  const std::string file = INERTA_SOURCE_DIR "/models/catenary-fe.yaml";
  const std::vector<std::string> base{"line.spans=6", "solver.type=direct", "irregularity.dropper_length_std=0.01",
                                      "irregularity.seed=2"};
  std::vector<std::string> ex = base;
  ex.push_back("irregularity.exact_dropper_dynamics=true");
  const auto exact = io::load_catenary(file, ex), designed = io::load_catenary(file, base);
  const auto panto = io::load_pantograph(INERTA_SOURCE_DIR "/models/pantograph-3mass.yaml");
  const auto rows = analysis::compare({{panto, 0.0, exact.contact}}, *exact.catenary, *designed.catenary,
                                      {250 / 3.6, 300 / 3.6}, {});
  for (const auto& r : rows) {
    EXPECT_NE(r.candidate.stats.std, r.reference.stats.std);  // not the same model
    EXPECT_NEAR(r.candidate.stats.std, r.reference.stats.std, 1e-3 * r.reference.stats.std) << r.speed * 3.6;
    EXPECT_NEAR(r.candidate.filtered[0].std, r.reference.filtered[0].std, 1e-3 * r.reference.filtered[0].std) << r.speed * 3.6;
  }
}

TEST(FeIrregularity, SigmaGrowsWithTheDropperLengthErrors) {
  // The 3-mass at 250 km/h on 6 spans of the bundled line, modal solve (the perfect line's modes,
  // shared through a mode store of this test's own): σ averaged over seeds 1–10 grows with the
  // dropper-length error std 0, 2, 5, 10 mm (docs/catenary-fe.md "σ against the dropper-length error").
  const std::filesystem::path store = std::filesystem::temp_directory_path() / fmt::format("inerta-sigma-std-{}", ::getpid());
  const char* saved = std::getenv("INERTA_CACHE");
  const std::string keep = saved ? saved : "";
  ::setenv("INERTA_CACHE", store.c_str(), 1);
  const auto panto = io::load_pantograph(INERTA_SOURCE_DIR "/models/pantograph-3mass.yaml");
  auto sigma = [&](double std_m, int seed) {
    const io::CatenaryFile c = io::load_catenary(
        INERTA_SOURCE_DIR "/models/catenary-fe.yaml",
        {"line.spans=6", fmt::format("irregularity.dropper_length_std={}", std_m), fmt::format("irregularity.seed={}", seed)});
    auto sys = c.catenary->couple(panto, c.contact, 250 / 3.6);
    return analysis::run_speed(*sys, analysis::RunOptions{}).stats.std;
  };
  std::vector<double> mean;
  for (double s : {0.0, 0.002, 0.005, 0.01}) {
    double m = 0;
    const int seeds = s > 0 ? 10 : 1;
    for (int seed = 1; seed <= seeds; ++seed) m += sigma(s, seed) / seeds;
    mean.push_back(m);
  }
  std::fprintf(stderr, "σ mean over 10 seeds at 0, 2, 5, 10 mm: %.3f, %.3f, %.3f, %.3f N\n", mean[0], mean[1], mean[2], mean[3]);
  for (std::size_t k = 1; k < mean.size(); ++k) EXPECT_GT(mean[k], mean[k - 1]) << k;
  if (saved) ::setenv("INERTA_CACHE", keep.c_str(), 1); else ::unsetenv("INERTA_CACHE");
  std::filesystem::remove_all(store);
}

TEST(FeIrregularity, APointMassSagsTheWireByItsStaticInfluence) {
  // A small point mass m at x: the wire sags there by m g e(x) (e the elasticity: Maxwell–Betti),
  // to first order in m.
  FeCatenaryData d = inerta::testing::fe_benchmark_line(4);
  const FeLine perfect(d);
  const double x = 2 * 55 + 20.0, m = 0.01;
  d.irregularity.point_masses = {{x, m}};
  const FeLine line(d);
  const double sag = perfect.static_height(x) - line.static_height(x), expect = m * d.gravity * perfect.elasticity(x);
  EXPECT_NEAR(sag, expect, 1e-3 * expect);
}

TEST(FeIrregularity, AHeightErrorMovesTheFormFoundWireAtTheDroppers) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / fmt::format("inerta-irr-{}", ::getpid());
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "dz.csv") << "x,dz\n0,0\n110,0.01\n220,0\n";
    std::ofstream(dir / "line.yaml") << "irregularity:\n  height_errors: dz.csv\n";
  }
  FeCatenaryData d = inerta::testing::fe_benchmark_line(4);
  const FeLine perfect(d);
  d.irregularity.height_error_x = {0, 110, 220};
  d.irregularity.height_error_dz = {0, 0.01, 0};
  const FeLine line(d);
  for (const auto& dr : line.droppers()) {
    const double dz = dr.x <= 110 ? 0.01 * dr.x / 110 : 0.01 * (220 - dr.x) / 110;
    EXPECT_NEAR(line.static_height(dr.x) - perfect.static_height(dr.x), dz, 1e-9) << dr.x;
  }
  std::filesystem::remove_all(dir);
}

// Bad input: ModelError naming the file and the key (the CLI exits 2 on a ModelError).
TEST(FeStitchErrors, NameTheFileAndKey) {
  // Each case edits one line of the bundled file's text.
  struct Case {
    const char* name;
    const char* from;
    const char* to;
    const char* key;
  };
  const Case cases[] = {
      {"long", "  length: 18 ", "  length: 70 ", "length"},
      {"outside", "    x: [-5, 5]", "    x: [-5, 9.5]", "x[1]"},
      {"tension", "  tension: 3500 ", "  tension: -3500 ", "tension"},
      {"nan", "  tension: 3500 ", "  tension: .nan ", "tension"},
      {"mass", "  mass_per_length: 0.31 ", "  mass_per_length: -0.31 ", "mass_per_length"},
      {"inside", "  x:      [17.5,", "  x:      [8.5,", "x[0]"},
      {"std", "solver:", "irregularity:\n  dropper_length_std: -0.001\nsolver:", "dropper_length_std"},
      {"stdnan", "solver:", "irregularity:\n  dropper_length_std: .nan\nsolver:", "dropper_length_std"},
      {"count", "solver:", "irregularity:\n  dropper_length_errors: [0.001, 0.002]\nsolver:", "dropper_length_errors"},
      {"cover", "solver:", "irregularity:\n  height_errors: short.csv\nsolver:", "height_errors"},
      {"order", "solver:", "irregularity:\n  height_errors: back.csv\nsolver:", "height_errors"},
      {"offline", "solver:", "irregularity:\n  point_masses: [{x: 700, mass: 2}]\nsolver:", "point_masses"},
      {"pmass", "solver:", "irregularity:\n  point_masses: [{x: 70, mass: -2}]\nsolver:", "point_masses"},
  };
  std::ifstream in(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    std::string t = text;
    t.replace(at, std::string(c.from).size(), c.to);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / fmt::format("inerta-bad-{}-{}", c.name, ::getpid());
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "bad.yaml").string();
    std::ofstream(path) << t;
    std::ofstream(dir / "short.csv") << "x,dz\n0,0\n300,0.01\n";
    std::ofstream(dir / "back.csv") << "x,dz\n0,0\n400,0.01\n300,0\n700,0\n";
    try {
      (void)io::read_fe_catenary_data(path, {});
      ADD_FAILURE() << "no error";
    } catch (const ModelError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find(c.key), std::string::npos) << what;
    }
    std::filesystem::remove_all(dir);
  }
}

TEST(FeStitchErrors, ASetOnAFileWithoutTheSectionTakesTheDefaults) {
  const FeCatenaryData d = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe.yaml",
                                                     {"irregularity.dropper_length_std=0.005", "irregularity.seed=7"});
  EXPECT_EQ(d.irregularity.dropper_length_std, 0.005);
  EXPECT_EQ(d.irregularity.seed, 7u);
  EXPECT_TRUE(d.irregularity.point_masses.empty());
  EXPECT_TRUE(d.irregularity.height_error_x.empty());
  EXPECT_THROW((void)io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe.yaml", {"stitch.enabled=false"}),
               ModelError);
  const FeCatenaryData s = io::read_fe_catenary_data(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml", {"stitch.enabled=false"});
  EXPECT_FALSE(s.has_stitch());
}

}  // namespace test_catenary_fe_stitch
