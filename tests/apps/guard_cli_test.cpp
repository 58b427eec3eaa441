// Issue 38: nothing hangs, crashes or silently guesses — the cost guard, the speeds that would run
// without end (or not at all), the supercritical FE run. Each case ends at once with its message
// (or the test runs into ctest's time-out, which fails it).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_guard_cli {

namespace {

namespace fs = std::filesystem;
using inerta::testing::contains;
using inerta::testing::Result;

std::string model(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

class Guard : public inerta::testing::CliTest {
 protected:
  // No file other than the captured streams is left in the test's folder (no partial output).
  void expect_no_output_files() const {
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string name = e.path().filename().string();
      EXPECT_TRUE(name == "stdout.txt" || name == "stderr.txt") << "left behind: " << name;
    }
  }
  std::string fe_run(const std::string& extra) const {
    return "simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary-fe.yaml") +
           " --speed 250 --unit kmh --out " + path("a.csv").string() + " " + extra;
  }
};

TEST_F(Guard, AnExpensiveFeRunIsRefusedBeforeItsSetupWithHowToProceed) {
  // 1000 spans solved directly: ≈ 900 000 unknowns a step for 1.6 million steps; refused by its
  // estimate (hours) before the line is built.
  Result r = run(fe_run("--set line.spans=1000 --set solver.type=direct"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "error: this run is estimated at about")) << r.err;
  EXPECT_TRUE(contains(r.err, "above the limit of 600 s; give --max-seconds")) << r.err;
  EXPECT_TRUE(contains(r.err, "mesh.element_length")) << r.err;
  expect_no_output_files();
  // A 1 mm mesh: millions of unknowns, the modes of a window tens of GB — refused by its memory
  // (on this machine) or its time.
  r = run(fe_run("--set mesh.element_length=0.001 --max-seconds 60"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "error: this run needs about") || contains(r.err, "error: this run is estimated at about"))
      << r.err;
  expect_no_output_files();
  // 1000 spans: about a minute by the estimate — under the default limit, over a lower one.
  r = run(fe_run("--set line.spans=1000 --max-seconds 20"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "above the limit of 20 s; give --max-seconds")) << r.err;
  expect_no_output_files();
  // The same guard in the sweep and the catenary commands.
  r = run("sweep " + model("hsx.yaml") + " --catenary " + model("catenary-fe.yaml") +
          " --speeds 200:10:300 --unit kmh --set line.spans=1000 --set solver.type=direct");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "this sweep of 11 speeds is estimated at")) << r.err;
  r = run("catenary check-reduction " + model("catenary-fe.yaml") + " --speed 250 --unit kmh --set line.spans=1000");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "this comparison at 1 speed(s) is estimated at")) << r.err;
  r = run("catenary fit " + model("catenary-fe.yaml") + " --out " + path("l.yaml").string() +
          " --set mesh.element_length=0.001 --max-seconds 10");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "this fit is estimated at")) << r.err;
  expect_no_output_files();
  // --max-seconds is checked like every number.
  r = run(fe_run("--max-seconds 0"));
  EXPECT_EQ(r.code, 105) << r.err;
  r = run(fe_run("--max-seconds nan"));
  EXPECT_EQ(r.code, 105) << r.err;
}

// Issue 52: the estimate of a study covers every stage — the coarse search of every network included.
TEST_F(Guard, AStudysEstimateCoversItsCoarseSearch) {
  std::string text = inerta::testing::read_file(std::string(INERTA_SOURCE_DIR) + "/studies/hsx-s2-fe-all.yaml");
  for (std::size_t at; (at = text.find("../models/")) != std::string::npos;)
    text.replace(at, 10, std::string(INERTA_SOURCE_DIR) + "/models/");
  const std::string four = write("s4.yaml", text);
  text.replace(text.find("max_elements: 4"), 15, "max_elements: 7");  // 14 453 networks
  const std::string seven = write("s7.yaml", text);
  Result r = run("optimise " + seven + " --max-seconds 600");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "search evaluations")) << r.err;
  EXPECT_TRUE(contains(r.err, "above the limit of 600 s; give --max-seconds")) << r.err;
  EXPECT_TRUE(contains(r.err, "networks: {max_elements}")) << r.err;
  // Its four-element version: the coarse search (119 networks) is a few per cent of the seven's.
  const auto searched = [&](const std::string& err) {
    const std::size_t at = err.find("this study (");
    return at == std::string::npos ? -1L : std::stol(err.substr(at + 12));
  };
  const long n7 = searched(r.err);
  r = run("optimise " + four + " --max-seconds 1");
  EXPECT_EQ(r.code, 2) << r.err;
  const long n4 = searched(r.err);
  EXPECT_GT(n4, 119 * 60) << r.err;  // at least 60 evaluations a network
  EXPECT_GT(n7, 100 * n4) << r.err;
  EXPECT_FALSE(fs::exists(path("results.csv")));  // refused before any output
}

// Issue 52: a point model's run is estimated like an FE run (its length is set by the speed).
TEST_F(Guard, ALumpedRunAtACrawlIsRefusedByItsEstimate) {
  Result r = run("simulate " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") + " --speed 1e-4 --out " +
                 path("slow.csv").string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "this run is estimated at about")) << r.err;
  EXPECT_TRUE(contains(r.err, "a higher --speed, fewer --spans or a shorter --t-end")) << r.err;
  r = run("sweep " + model("hsx.yaml") + " --catenary " + model("wire-profile.yaml") + " --speeds 0.001:0.001:0.002");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "this sweep of 2 speeds is estimated at")) << r.err;
  // A short --t-end at the same crawl is cheap and runs.
  r = run("simulate " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") + " --speed 1e-4 --t-end 1 --out " +
          path("slow.csv").string());
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(Guard, SpeedsThatWouldRunWithoutEndOrNotAtAllAreRefused) {
  // 1e-9 km/h on the lumped line: 40 spans would last ≈ 1e14 s (the --t-end limit is 1e7 s).
  Result r = run("sweep " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") +
                 " --speeds 1e-9:1:1e-9 --unit kmh --out " + path("b.csv").string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "beyond the limit of 1e+07 s (that of --t-end)")) << r.err;
  r = run("simulate " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") + " --speed 1e-9 --unit kmh");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "12 spans (720 m) would last")) << r.err;
  // 1e300 km/h: no σ of 0 "converged", an error.
  r = run("sweep " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") +
          " --speeds 1e300:1:1e300 --unit kmh --out " + path("c.csv").string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "above the fastest run accepted, 1000 m/s (3600 km/h)")) << r.err;
  r = run("sweep " + model("hsx.yaml") + " --catenary " + model("catenary.yaml") + " --speeds 1e7:1:1e7 --unit kmh");
  EXPECT_EQ(r.code, 2) << r.err;
  expect_no_output_files();
}

TEST_F(Guard, AboveTheContactWiresWaveSpeedIsAnErrorAndNearItAWarning) {
  // 600 km/h against the 459.6 km/h that `check` prints.
  Result r = run("simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary-fe.yaml") +
                 " --speed 600 --unit kmh --out " + path("d.csv").string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "above the contact wire's wave speed sqrt(T/rho A) = 459.6 km/h")) << r.err;
  EXPECT_TRUE(contains(r.err, "--allow-supercritical")) << r.err;
  expect_no_output_files();
  // 350 km/h (76 %): runs (a line of 3 spans), with a warning on standard error only.
  const std::string short_run = "simulate " + model("pantograph-3mass.yaml") + " --catenary " +
                                model("catenary-fe.yaml") + " --speed 350 --unit kmh --set line.spans=3 --set solver.type=direct";
  r = run(short_run);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "warning: 350 km/h is 76 % of the contact wire's wave speed (459.6 km/h)")) << r.err;
  EXPECT_FALSE(contains(r.out, "warning")) << r.out;
  // Below 70 % (300 km/h, 65 %): no warning.
  r = run("simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary-fe.yaml") +
          " --speed 300 --unit kmh --set line.spans=3 --set solver.type=direct");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(contains(r.err, "warning")) << r.err;
}

TEST_F(Guard, AModalSolveWithoutModesIsRefusedAndCheckSaysWhichSolver) {
  // A cut-off below the line's lowest natural frequency kept no mode and ran (σ 30.2 instead of 31.3 N).
  for (const auto& [fc, shown] : {std::pair<std::string, std::string>{"0.5", "0.5"}, {"1e-5", "1e-05"}}) {
    Result r = run(fe_run("--set solver.cutoff=" + fc));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(contains(r.err, "solver.cutoff = " + shown + " Hz is below the lowest natural frequency")) << r.err;
  }
  expect_no_output_files();
  Result r = run("check " + model("catenary-fe.yaml"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "\n  solver: type modal, cutoff 100 Hz, window_behind 2, window_ahead 3\n")) << r.out;
  r = run("check " + model("catenary-fe.yaml") + " --set solver.type=direct");
  EXPECT_TRUE(contains(r.out, "\n  solver: type direct, cutoff 100 Hz, window_behind 2, window_ahead 3\n")) << r.out;
}

TEST_F(Guard, AnOverrideOfANameTwoItemsShareIsRefused) {
  // A damper named like a body hid the body from --set: now the override says which two it names.
  std::string t = inerta::testing::read_file(model("twobar.yaml"));
  t.replace(t.find("{name: c, type: damper"), 22, "{name: bar1, type: damper");
  const std::string m = write("m.yaml", t);
  Result r = run("check " + m + " --set bar1.mass=2");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "'bar1' names a force element and a body: the override cannot tell which")) << r.err;
  r = run("check " + m + " --set bar2.mass=2");  // a name of one item: as before
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(Guard, TheModeStoreSaysWhenItCannotBeWrittenAndRefusesARelativeFolder) {
  const char* saved = std::getenv("INERTA_CACHE");
  const std::string keep = saved ? saved : "";
  const std::string run_fe = "simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary-fe.yaml") +
                             " --speed 250 --unit kmh --set line.spans=3 --set solver.cutoff=20";
  ::setenv("INERTA_CACHE", "/proc/inerta-modes", 1);  // cannot be created
  Result r = run(run_fe);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "note: the mode store /proc/inerta-modes cannot be written")) << r.err;
  EXPECT_FALSE(contains(r.out, "mode store")) << r.out;
  ::setenv("INERTA_CACHE", "relative/modes", 1);
  r = run(run_fe);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "INERTA_CACHE='relative/modes': expected an absolute folder")) << r.err;
  if (saved) ::setenv("INERTA_CACHE", keep.c_str(), 1); else ::unsetenv("INERTA_CACHE");
  expect_no_output_files();
}

TEST_F(Guard, InertaTimingsPrintsWhereTheProcessSpentItsTimeOnStandardError) {
  // Issue 39 item 1: the whole-process split of a run (docs/benchmarks.md), the second run reading
  // its window's modes from the store.
  const std::string store = (std::filesystem::temp_directory_path() / "inerta-timings-test-store").string();
  std::filesystem::remove_all(store);
  const char* saved = std::getenv("INERTA_CACHE");
  const std::string keep = saved ? saved : "";
  ::setenv("INERTA_CACHE", store.c_str(), 1);
  const std::string run_fe = "simulate " + model("pantograph-3mass.yaml") + " --catenary " + model("catenary-fe.yaml") +
                             " --speed 250 --unit kmh --set line.spans=3 --set solver.cutoff=20";
  Result r = run(run_fe);  // no timings unless asked
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(contains(r.err, "timings")) << r.err;
  ::setenv("INERTA_TIMINGS", "1", 1);
  r = run(run_fe);
  ::unsetenv("INERTA_TIMINGS");
  if (saved) ::setenv("INERTA_CACHE", keep.c_str(), 1); else ::unsetenv("INERTA_CACHE");
  std::filesystem::remove_all(store);
  EXPECT_EQ(r.code, 0) << r.err;
  for (const char* phase : {"load: catenary file", "line: mesh, form-finding, matrices", "mode store: read and verify",
                            "time steps (with sampling)", "process (from start to exit)"})
    EXPECT_TRUE(contains(r.err, phase)) << phase << "\n" << r.err;
  EXPECT_FALSE(contains(r.out, "timings")) << r.out;
}

TEST_F(Guard, ALineOfOneSpanRunsAndSaysItHasNoSupport) {
  // line.spans=1 failed with "support uplift: the history is empty".
  const Result r = run(fe_run("--set line.spans=1 --set solver.type=direct"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "support uplift in the section: no support in the section")) << r.out;
}

TEST_F(Guard, DeeplyNestedYamlIsNamedAsSuch) {
  // yaml-cpp's depth guard said "bad file".
  const std::string deep = write("deep.yaml", "a: " + std::string(5000, '[') + std::string(5000, ']') + "\n");
  const Result r = run("check " + deep);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "deep.yaml:1: YAML nested too deeply to read")) << r.err;
  EXPECT_FALSE(contains(r.err, "bad file")) << r.err;
}

}  // namespace

}  // namespace test_apps_guard_cli
