// Issue 15: every reproduction of the hardening issue as a regression test (exit code and message).
// Exit codes: 2 model/file error, 1 other error (outputs), 3 numerical failure, 4 unstable periodic
// solution, 105 invalid option value (CLI11).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_hardening_cli {

namespace {

namespace fs = std::filesystem;
using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;
using inerta::testing::Result;

std::string model(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

class Hardening : public inerta::testing::CliTest {
 protected:
  // A J2 study on the HSX model with `search` and `extra` top-level lines.
  std::string j2_study(const std::string& search, const std::string& extra = "") const {
    return write("study.yaml", "name: s\nmodel: " + model("hsx.yaml") + "\ncatenary: " + model("catenary.yaml") +
                                   "\nspeeds: {from: 100, to: 200, step: 50, unit: kmh}\nlayouts: [S2-1]\nsearch: " +
                                   search + "\n" + extra);
  }
  std::string text_of(const std::string& path) const { return read_file(path); }
};

// ---- crashes ----------------------------------------------------------------------------------

TEST_F(Hardening, DeeplyNestedNetworkIsAnErrorNotACrash) {
  const std::string expr = std::string(40000, '(') + "b" + std::string(40000, ')');
  Result r = run("admittance " + quote(expr) + " --param b=1 --freq 1:1:2");
  EXPECT_EQ(r.code, 2) << r.err.substr(0, 300);
  EXPECT_TRUE(contains(r.err, "at most 10000 are accepted")) << r.err.substr(0, 300);
  const std::string deep = std::string(100, '(') + "b" + std::string(100, ')');
  r = run("admittance " + quote(deep) + " --param b=1 --freq 1:1:2");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "nested more than 64 deep")) << r.err.substr(0, 300);
  // Through a model file's network: an error at the file and line of the key.
  std::string t = text_of(model("twobar_network.yaml"));
  t.replace(t.find("network: \"k|c|b\""), 16, "network: \"" + deep.substr(0, 99) + "k|c|b" + deep.substr(101) + "\"");
  const std::string m = write("m.yaml", t);
  r = run("check " + quote(m));
  EXPECT_EQ(r.code, 2) << r.err.substr(0, 300);
  EXPECT_TRUE(contains(r.err, m + ":37: 'network'")) << r.err.substr(0, 300);
  EXPECT_TRUE(contains(r.err, "nested more than 64 deep")) << r.err.substr(0, 300);
}

TEST_F(Hardening, RangesWithTooManyPointsAreRefused) {
  Result r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
                 " --speeds 1:1e-300:2 --method periodic");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "at most 1000000 are accepted")) << r.err;
  r = run("admittance k --param k=1 --freq 1:1:1e300");
  EXPECT_EQ(r.code, 105) << r.err;
  r = run("admittance k --param k=1 --freq 0:1e-9:1e3");
  EXPECT_EQ(r.code, 105) << r.err;
  r = run("catenary-response " + quote(model("catenary.yaml")) + " --fp 1:1e-300:2");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--fp")) << r.err;
}

TEST_F(Hardening, SamplingTooFineIsRefusedNotTruncated) {
  Result r = run("simulate " + quote(model("onedof.yaml")) + " --sample 1e-300 --out " + quote((dir_ / "o.csv").string()));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "at most 10000000 are written")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o.csv"));
}

TEST_F(Hardening, NonFiniteOptionValuesAreUsageErrors) {
  const std::string csv = write("dyn.csv", "t,displacement,force\n0,0,0\n0.1,1,1\n0.2,0,0\n0.3,-1,-1\n0.4,0,0\n0.5,1,1\n0.6,0,0\n0.7,-1,-1\n");
  Result r = run("identify actuator-dynamic " + quote(csv) + " --c1 10440 --freq 1 --piston-mass nan");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--piston-mass")) << r.err;
  r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
          " --speeds 100:10:110 --method periodic --harmonics 100000");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--harmonics")) << r.err;
  r = run("simulate " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
          " --speed 50 --spans 100000");
  EXPECT_EQ(r.code, 105) << r.err;
  r = run("simulate " + quote(model("onedof.yaml")) + " --t-end 1e18");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--t-end")) << r.err;
}

// ---- study files --------------------------------------------------------------------------------

TEST_F(Hardening, StudyNumbersAreCheckedBeforeAnyCast) {
  struct Case {
    std::string search, extra, message;
  } cases[] = {
      {"{starts: -2147483649}", "", "'starts': -2147483649; expected a whole number from 1 to 10000"},
      {"{seed: -1}", "", "'seed': -1; expected a whole number from 0 to 4294967295"},
      {"{hi: .inf}", "", "'hi': .inf is not a finite number"},
      {"{min_step: 0}", "", "'min_step': 0; expected a mesh size"},
      {"{max_evaluations: 2.5}", "", "'max_evaluations': 2.5 is not a whole number"},
      {"{starts: 1}", "harmonics: 2.7\n", "'harmonics': 2.7 is not a whole number"},
      {"{starts: 1}", "harmonics: 0\n", "'harmonics': 0; expected a whole number from 1 to 256"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.search + " " + c.extra);
    const std::string s = j2_study(c.search, c.extra);
    Result r = run("optimise " + quote(s));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(contains(r.err, s + ":")) << r.err;
    EXPECT_TRUE(contains(r.err, c.message)) << r.err;
  }
}

TEST_F(Hardening, StudyTypoInSpeedsIsAnError) {
  const std::string s = write("study.yaml", "name: s\nmodel: " + model("hsx.yaml") + "\ncatenary: " + model("catenary.yaml") +
                                                "\nspeeds: {from: 100, to: 200, step: 50, unitx: kmh}\nlayouts: [S2-1]\n");
  Result r = run("optimise " + quote(s));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, s + ":4: 'unitx': unknown key in speeds")) << r.err;
}

TEST_F(Hardening, ExhaustedBudgetAndBoundsAreMarked) {
  const std::string s = j2_study("{starts: 1, max_evaluations: 2}");
  Result r = run("optimise " + quote(s));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "budget exhausted")) << r.out;
  // S2-1's spring optimum (≈ 9.3e4 N/m) lies below lo = 2e5: the value ends on a limit, marked '*'.
  r = run("optimise " + quote(j2_study("{starts: 1, lo: 2.0e5, hi: 1.0e6}")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "*: on a bound")) << r.out;
  // A model study marks its exhausted searches too.
  std::string q = text_of(std::string(INERTA_SOURCE_DIR) + "/studies/quarter_car.yaml");
  q.replace(q.find("model: ../models/"), 17, "model: " + std::string(INERTA_SOURCE_DIR) + "/models/");
  q.replace(q.find("min_step: 0.01}"), 15, "min_step: 0.01, max_evaluations: 3}");
  r = run("optimise " + quote(write("qc.yaml", q)) + " --no-plots");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "budget exhausted (max_evaluations reached before min_step)")) << r.out;
}

// ---- catenary and model files -------------------------------------------------------------------

TEST_F(Hardening, CatenaryDuplicateAndMissingKeysAreErrors) {
  std::string dup = write("dup.yaml", "catenary:\n  span: 60\n  kc: [7000, 2100, 350, 140]\n  mc: [177.3, 0, 0, 0]\n"
                                      "  cc: [111, 0, 0, 0]\n  kc: [1, 0, 0, 0]\n");
  Result r = run("check " + quote(dup));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, dup + ":6: 'kc': duplicate key")) << r.err;
  std::string missing = write("missing.yaml", "catenary:\n  span: 60\n  kc: [7000, 2100, 350, 140]\n  cc: [111, 0, 0, 0]\n");
  r = run("check " + quote(missing));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "'mc': missing in catenary")) << r.err;
}

TEST_F(Hardening, NonFiniteModelNumbersAreErrorsAtTheirLine) {
  std::string t = text_of(model("twobar.yaml"));
  t.replace(t.find("D: [0.25, 0]"), 12, "D: [.nan, 0]");
  const std::string m = write("m.yaml", t);
  Result r = run("check " + quote(m));
  EXPECT_EQ(r.code, 2) << r.err;
  const auto line = 1 + std::count(t.begin(), t.begin() + static_cast<long>(t.find("D: [.nan")), '\n');
  EXPECT_TRUE(contains(r.err, fmt::format("{}:{}: 'bar1.D': expected finite numbers, got '.nan'", m, line))) << r.err;
}

TEST_F(Hardening, InputThatIsNotARegularFileIsRefused) {
  Result r = run("check /dev/zero");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "/dev/zero: not a regular file")) << r.err;
  r = run("check " + quote(dir_.string()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "not a regular file (a folder)")) << r.err;
}

TEST_F(Hardening, CsvSignsAndByteOrderMark) {
  const std::string bom = write("bom.csv", "\xEF\xBB\xBFvelocity,force\n0.1,10\n0.2,20\n-0.1,-10\n-0.2,-20\n");
  Result r = run("identify actuator-static " + quote(bom));
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string pm = write("pm.csv", "velocity,force\n0.1,10\n0.2,20\n-0.1,+-10\n-0.2,-20\n");
  r = run("identify actuator-static " + quote(pm));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, pm + ":4: column 'force': '+-10' is not a finite number")) << r.err;
}

// ---- numerics -----------------------------------------------------------------------------------

TEST_F(Hardening, StiffModelStopsWithTheAdviceToUseBdf) {
  Result r = run("simulate " + quote(model("onedof.yaml")) + " --set k.k=1e14 --t-end 1");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_TRUE(contains(r.err, "the model is stiff")) << r.err;
  EXPECT_TRUE(contains(r.err, "--integrator bdf")) << r.err;
}

TEST_F(Hardening, StrutThroughZeroLengthStopsWithItsNameAndTime) {
  // The mass slides along x = 0 through the pivot O: released 1 m beyond the spring's free length (0.5 m),
  // it reaches O with speed to spare, and the spring's axis would flip.
  std::string t = text_of(model("onedof.yaml"));
  t.replace(t.find("rail: [1, 0]"), 12, "rail: [0, 0.5]");
  t.replace(t.find("position: [1, 1.5]"), 18, "position: [0, 1.5]");
  t.replace(t.find("free_length: 1.4142135623730951"), 31, "free_length: 0.5");
  const std::string m = write("m.yaml", t);
  Result r = run("simulate " + quote(m) + " --t-end 2");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_TRUE(contains(r.err, "strut 'k'") || contains(r.err, "strut 'b'")) << r.err;
  EXPECT_TRUE(contains(r.err, "zero length")) << r.err;
  EXPECT_TRUE(contains(r.err, "t = ")) << r.err;
}

TEST_F(Hardening, PeriodicSweepReportsParametricResonanceAsUnstable) {
  const std::string out = (dir_ / "s.csv").string();
  Result r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
                 " --set catenary.kc1=6500 --speeds 380:10:400 --unit kmh --method periodic --out " + quote(out));
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_TRUE(contains(r.err, "unstable: the periodic solution is unstable at 380 (")) << r.err;
  EXPECT_TRUE(contains(r.err, "400 (")) << r.err;
  const std::string csv = read_file(out);
  EXPECT_TRUE(contains(csv, ",floquet_max,stable\n")) << csv;
  EXPECT_TRUE(contains(csv, ",0\n")) << csv;
  EXPECT_FALSE(contains(csv, ",1\n")) << csv;
  // A stable sweep exits 0 with stable = 1.
  r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
          " --speeds 100:100:200 --unit kmh --method periodic");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, ",1\n")) << r.out;
}

TEST_F(Hardening, TimeSweepHasAConvergedColumn) {
  Result r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
                 " --speeds 150:10:150 --unit kmh");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "loss_pct,converged\n")) << r.out;
}

// ---- outputs ------------------------------------------------------------------------------------

TEST_F(Hardening, OutputEqualToAnInputIsRefused) {
  const std::string m = write("m.yaml", text_of(model("onedof.yaml")));
  const std::string before = text_of(m);
  Result r = run("simulate " + quote(m) + " --t-end 0.1 --out " + quote(m));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is the input file")) << r.err;
  EXPECT_EQ(text_of(m), before);
  const std::string c = write("c.yaml", text_of(model("catenary.yaml")));
  r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(c) + " --speeds 100:10:100 --unit kmh --out " +
          quote(c));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is the input file")) << r.err;
  const std::string x = (dir_ / "x.csv").string();
  r = run("modes " + quote(model("onedof.yaml")) + " --out " + quote(x) + " --export " + quote(x));
  EXPECT_EQ(r.code, 1) << r.err;
}

// Issue 52: every input a command reads — criteria, a CSV the line reads, the study — is safe from every
// output it writes, derived names (OUT.acceptance.csv) included.
TEST_F(Hardening, NoOutputReplacesAnyInput) {
  const std::string crit = write("c.yaml", text_of(std::string(INERTA_SOURCE_DIR) + "/criteria/en50367-ac.yaml"));
  const std::string before = text_of(crit);
  const std::string sim = "simulate " + quote(model("pantograph-3mass.yaml")) + " --catenary " + quote(model("catenary-fe.yaml")) +
                          " --speed 250 --unit kmh --t-end 0.05 --acceptance " + quote(crit);
  Result r = run(sim + " --out " + quote(crit));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is the input file")) << r.err;
  EXPECT_EQ(text_of(crit), before);
  // The derived name: --out X.csv writes X.acceptance.csv beside it.
  const std::string derived = write("x.acceptance.csv", text_of(crit));
  r = run("simulate " + quote(model("pantograph-3mass.yaml")) + " --catenary " + quote(model("catenary-fe.yaml")) +
          " --speed 250 --unit kmh --t-end 0.05 --acceptance " + quote(derived) + " --out " + quote((dir_ / "x.csv").string()));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is the input file")) << r.err;
  EXPECT_EQ(text_of(derived), before);
  // A height-error CSV the line reads.
  std::string dz = "x,dz\n0,0\n100000,0\n";
  const std::string csv = write("dz.csv", dz);
  r = run("simulate " + quote(model("pantograph-3mass.yaml")) + " --catenary " + quote(model("catenary-fe.yaml")) +
          " --set irregularity.height_errors=" + quote(csv) + " --speed 250 --unit kmh --t-end 0.05 --out " + quote(csv));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is the input file")) << r.err;
  EXPECT_EQ(text_of(csv), dz);
}

// Issue 52: inputs that were accepted in silence, and errors that named the wrong thing.
TEST_F(Hardening, SilentAcceptsAreErrorsThatSayWhatToChange) {
  const std::string fe = " --catenary " + quote(model("catenary-fe.yaml")) + " --speed 250 --unit kmh --t-end 0.05 --out " +
                         quote((dir_ / "o.csv").string());
  for (const std::string p : {"0,0", "100,100.0"}) {
    Result r = run("simulate " + quote(model("hsx.yaml")) + fe + " --positions " + p);
    EXPECT_EQ(r.code, 105) << p << r.err;
    EXPECT_TRUE(contains(r.err, "given twice")) << r.err;
  }
  Result r = run("simulate " + quote(model("hsx.yaml")) + fe + " --positions ''");
  EXPECT_EQ(r.code, 105) << r.err;
  EXPECT_TRUE(contains(r.err, "--positions: empty")) << r.err;
  // Absurd tensions are refused by their range, the stitch wire's too (was: a singular matrix).
  r = run("simulate " + quote(model("hsx.yaml")) + fe + " --set messenger.tension=1e300");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "must be <= 1e+07 (N), got 1e+300")) << r.err;
  r = run("check " + quote(model("catenary-fe-stitched.yaml")) + " --set stitch.tension=1e300");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "stitch: tension")) << r.err;
  r = run("check " + quote(model("catenary-fe.yaml")) + " --set contact_wire.mass_per_length=1e-9");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "wave speed")) << r.err;
  // The seed's bound is stated.
  r = run("check " + quote(model("catenary-fe.yaml")) + " --set irregularity.seed=18446744073709551615");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "2^53")) << r.err;
  // Stitch droppers at the mast: the stitch wire sags, not the messenger.
  std::string st = text_of(model("catenary-fe-stitched.yaml"));
  st.replace(st.find("x: [-5, 5]"), 10, "x: [-0.01, 0.01]");
  r = run("simulate " + quote(model("hsx.yaml")) + " --catenary " + quote(write("st.yaml", st)) +
          " --speed 250 --unit kmh --t-end 0.05 --out " + quote((dir_ / "o.csv").string()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "the stitch wire sags below the contact wire")) << r.err;
  EXPECT_TRUE(contains(r.err, "stitch.droppers.x")) << r.err;
  // A criteria filter above the run's Nyquist frequency: refused before the run, naming the key.
  std::string crit = text_of(std::string(INERTA_SOURCE_DIR) + "/criteria/en50367-ac.yaml");
  crit.replace(crit.find("cutoff: 20,"), 11, "cutoff: 600,");
  r = run("simulate " + quote(model("pantograph-3mass.yaml")) + " --catenary " + quote(model("catenary-fe.yaml")) +
          " --set line.spans=4 --speed 250 --unit kmh --acceptance " + quote(write("c600.yaml", crit)) + " --out " +
          quote((dir_ / "o.csv").string()));
  EXPECT_NE(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "filter.cutoff")) << r.err;
  EXPECT_TRUE(contains(r.err, "Nyquist")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o.csv"));
  // Sections adding up to more than 1000 spans name the sections, not a key the file does not have.
  std::string ov = text_of(model("catenary-fe-overlap.yaml"));
  for (const char* n : {"{spans: 12,", "{spans: 13,", "{spans: 12,"}) ov.replace(ov.find(n), std::string(n).size(), "{spans: 400,");
  r = run("check " + quote(write("ov.yaml", ov)));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "'tension_sections': the sections make a line of 1194 spans")) << r.err;
  // A lumped fit of an overlap span (two contact wires) is refused.
  r = run("catenary fit " + quote(model("catenary-fe-overlap.yaml")) + " --span 11 --out " + quote((dir_ / "f.yaml").string()));
  EXPECT_NE(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "span 11 is in the overlap of sections 1 and 2 (spans 10 … 12")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "f.yaml"));
}

TEST_F(Hardening, UnwritableOutIsFoundBeforeTheComputation) {
  Result r = run("sweep " + quote(model("hsx.yaml")) + " --catenary " + quote(model("catenary.yaml")) +
                 " --speeds 50:5:300 --unit kmh --out " + quote((dir_ / "no" / "such" / "s.csv").string()));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "does not exist")) << r.err;
  EXPECT_FALSE(contains(r.out, "sweep: ")) << r.out;  // refused before the sweep started (it prints this first)
}

TEST_F(Hardening, WriteErrorsAreErrors) {
  Result r = run("simulate " + quote(model("onedof.yaml")) + " --t-end 0.5 --out /dev/full");
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_TRUE(contains(r.err, "cannot write '/dev/full'")) << r.err;
  EXPECT_FALSE(contains(r.out, "wrote")) << r.out;
}

TEST_F(Hardening, InterruptedSimulationLeavesNoIncompleteFile) {
  // Ctrl-C, and SIGBUS (issue 38: the death a file cut short under a mapping gives).
  for (const int sig : {SIGINT, SIGBUS}) {
    const fs::path out = dir_ / "o.csv";
    const std::string cmd = quote(INERTA_CLI) + " simulate " + quote(model("twobar.yaml")) +
                            " --t-end 100000 --sample 0.01 --out " + quote(out.string());
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const rlimit no_core{0, 0};  // SIGBUS would dump core in the working directory
      setrlimit(RLIMIT_CORE, &no_core);
      execl("/bin/sh", "sh", "-c", ("exec " + cmd + " >/dev/null 2>&1").c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    // Wait until the partial file exists (the run has started), then interrupt.
    for (int i = 0; i < 200; ++i) {
      bool partial = false;
      for (const auto& e : fs::directory_iterator(dir_)) partial = partial || contains(e.path().filename().string(), ".partial-");
      if (partial) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_FALSE(fs::exists(out));
    for (const auto& e : fs::directory_iterator(dir_))
      EXPECT_FALSE(contains(e.path().filename().string(), ".partial-")) << "signal " << sig;
  }
}

TEST_F(Hardening, OptimiseOutNeedsForceForANonEmptyFolder) {
  const std::string study = write("tmd.yaml", "name: t\nmodel: " + model("tmd.yaml") +
                                                  "\nstrut: absorber\nobjective:\n  type: hinf\n  input: F\n  outputs: {x: 1}\n"
                                                  "  band: {from: 3, to: 8, points: 50}\nlayouts: [\"k|c\"]\n"
                                                  "search: {starts: 1, seed: 1, lo: 0.01, hi: 1.0e7, min_step: 0.2}\n");
  const fs::path out = dir_ / "res";
  fs::create_directories(out);
  std::ofstream(out / "results.csv") << "stale\n";
  std::ofstream(out / "mine.txt") << "keep\n";
  Result r = run("optimise " + quote(study) + " --no-plots --out " + quote(out.string()));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "is not empty")) << r.err;
  EXPECT_TRUE(contains(r.err, "--force")) << r.err;
  EXPECT_EQ(read_file(out / "results.csv"), "stale\n");
  r = run("optimise " + quote(study) + " --no-plots --force --out " + quote(out.string()));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(read_file(out / "results.csv"), "layout,expression,J")) << read_file(out / "results.csv");
  EXPECT_EQ(read_file(out / "mine.txt"), "keep\n");  // not the study's: kept
}

}  // namespace
}  // namespace test_apps_hardening_cli
