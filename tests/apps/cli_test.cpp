// The `inerta` command-line program (apps/inerta/main.cpp), run as a separate process.
// Every file the tests write goes to a fresh directory under the system temp directory.
#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_cli {

namespace {

namespace fs = std::filesystem;

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;
using inerta::testing::Result;

std::string model_path(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> fields_of(const std::string& line) {
  std::vector<double> v;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) v.push_back(std::stod(f));
  return v;
}

class Cli : public inerta::testing::CliTest {};

TEST_F(Cli, CheckTwobarReportsTwoDegreesOfFreedom) {
  Result r = run("check " + quote(model_path("twobar.yaml")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "degrees of freedom: 2\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "joints (2), constraint equations: 4")) << r.out;
}

TEST_F(Cli, CheckModelErrorExitsTwoWithFileAndLine) {
  const std::string bad = path("bad.yaml").string();
  std::ofstream(bad) << "options: {gravity: false}\n"
                        "bodies:\n"
                        "  - name: b\n"
                        "    mass: -2\n"  // line 4
                        "    inertia: 1\n"
                        "    position: [0, 0]\n";
  Result r = run("check " + quote(bad));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, bad + ":4: 'mass'")) << r.err;
  EXPECT_TRUE(contains(r.err, "must be >= 0")) << r.err;
  EXPECT_EQ(r.out, "");  // nothing is printed for a model that does not load
}

TEST_F(Cli, SimulateTwobarWritesSampledCsvAndSummary) {
  const fs::path csv = path("twobar.csv");
  Result r =
      run("simulate " + quote(model_path("twobar.yaml")) + " --t-end 1 --sample 0.01 --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;

  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 102u);
  EXPECT_EQ(lines[0], "t,C_x,C_y");
  for (std::size_t k = 0; k <= 100; ++k) {
    const auto v = fields_of(lines[k + 1]);
    ASSERT_EQ(v.size(), 3u) << lines[k + 1];
    EXPECT_NEAR(v[0], 0.01 * static_cast<double>(k), 1e-9) << "row " << k;
    EXPECT_TRUE(std::isfinite(v[1]) && std::isfinite(v[2])) << lines[k + 1];
  }
  // t = 0: the model starts at rest at θ = (45°, 135°), so C = (0, √2).
  const auto first = fields_of(lines[1]);
  EXPECT_NEAR(first[1], 0.0, 1e-8);
  EXPECT_NEAR(first[2], std::sqrt(2.0), 1e-8);

  // With --out, the summary goes to standard output.
  bool summary = false;
  for (const auto& line : lines_of(r.out))
    summary = summary || (contains(line, "steps") && contains(line, "RHS evaluations") && contains(line, "wall") &&
                          contains(line, "max constraint violation"));
  EXPECT_TRUE(summary) << r.out;
}

TEST_F(Cli, NoCentripetalChangesTheResult) {
  auto last_cy = [&](const std::string& extra, const std::string& file) -> double {
    const fs::path csv = path(file);
    Result r = run("simulate " + quote(model_path("twobar.yaml")) + " --t-end 1 --sample 0.01 --out " +
                   quote(csv.string()) + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    const auto lines = lines_of(read_file(csv));
    if (lines.size() != 102u) {
      ADD_FAILURE() << file << ": " << lines.size() << " lines";
      return std::nan("");
    }
    const auto v = fields_of(lines.back());
    EXPECT_NEAR(v.at(0), 1.0, 1e-9);
    return v.at(2);
  };
  const double with = last_cy("", "with.csv");
  const double without = last_cy(" --no-centripetal", "without.csv");
  ASSERT_TRUE(std::isfinite(with) && std::isfinite(without));
  EXPECT_GT(std::abs(with - without), 1e-3) << "C_y(1) with " << with << ", without " << without;
}

TEST_F(Cli, SimulateOnedofWritesItsOutputs) {
  const fs::path csv = path("onedof.csv");
  Result r =
      run("simulate " + quote(model_path("onedof.yaml")) + " --t-end 0.1 --sample 0.01 --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 12u);
  EXPECT_EQ(lines[0], "t,y,F_inerter");
  const auto first = fields_of(lines[1]);
  ASSERT_EQ(first.size(), 3u);
  EXPECT_EQ(first[0], 0.0);
  EXPECT_NEAR(first[1], 1.5, 1e-12);  // released from y0 = 1.5 m
}

TEST_F(Cli, SimulateWithoutOutWritesCsvToStdoutAndSummaryToStderr) {
  Result r = run("simulate " + quote(model_path("onedof.yaml")) + " --t-end 0.02 --sample 0.01");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[0], "t,y,F_inerter");
  EXPECT_TRUE(contains(r.err, "RHS evaluations")) << r.err;
}

TEST_F(Cli, NonexistentModelPathFails) {
  const std::string missing = path("no_such_model.yaml").string();
  Result r = run("check " + quote(missing));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.code, -1);
  EXPECT_TRUE(contains(r.err, missing)) << r.err;

  Result s = run("simulate " + quote(missing) + " --out " + quote(path("x.csv").string()));
  EXPECT_NE(s.code, 0);
  EXPECT_NE(s.code, -1);
  EXPECT_TRUE(contains(s.err, missing)) << s.err;
  EXPECT_FALSE(fs::exists(path("x.csv")));
}

TEST_F(Cli, UnknownOptionFails) {
  const fs::path csv = path("x.csv");
  Result r =
      run("simulate " + quote(model_path("onedof.yaml")) + " --t-end 0.01 --bogus-option --out " + quote(csv.string()));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.code, -1);
  EXPECT_TRUE(contains(r.err, "--bogus-option")) << r.err;
  EXPECT_FALSE(fs::exists(csv));
}

// ----------------------------------------------------------------------------------------------
// inerta admittance (network admittance Y = F / relative velocity as CSV) and network models
// ----------------------------------------------------------------------------------------------

// Checks one CSV row f_hz,mag,phase_deg,re,im against the exact Y at that frequency.
void expect_admittance_row(const std::vector<double>& v, std::complex<double> y, const std::string& row) {
  ASSERT_EQ(v.size(), 5u) << row;
  const double tol = 1e-8;
  EXPECT_NEAR(v[3], y.real(), tol * std::abs(y.real())) << row;
  EXPECT_NEAR(v[4], y.imag(), tol * std::abs(y.imag())) << row;
  EXPECT_NEAR(v[1], std::abs(y), tol * std::abs(y)) << row;
  const double phase = std::arg(y) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(v[2], phase, tol * std::abs(phase)) << row;
  // The columns agree with each other.
  EXPECT_NEAR(v[1], std::hypot(v[3], v[4]), tol * v[1]) << row;
  EXPECT_NEAR(v[2], std::atan2(v[4], v[3]) * 180.0 / std::numbers::pi, 1e-7) << row;
}

TEST_F(Cli, AdmittanceOfS2DefaultIsAMaxwellElement) {
  const fs::path csv = path("s2.csv");
  Result r = run("admittance S2-default --freq 0.5:0.5:20 --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 41u);
  EXPECT_EQ(lines[0], "f_hz,mag,phase_deg,re,im");
  const double k = 141e3, c = 10.44e3;
  for (std::size_t n = 1; n < lines.size(); ++n) {
    const auto v = fields_of(lines[n]);
    ASSERT_EQ(v.size(), 5u) << lines[n];
    const double f = 0.5 * static_cast<double>(n);
    EXPECT_NEAR(v[0], f, 1e-9) << lines[n];
    const std::complex<double> iw(0.0, 2 * std::numbers::pi * f);
    expect_admittance_row(v, k * c / (k + c * iw), lines[n]);
  }
  EXPECT_NEAR(fields_of(lines[1])[0], 0.5, 1e-12);
  EXPECT_NEAR(fields_of(lines.back())[0], 20.0, 1e-12);
  // A Maxwell element lags: the phase falls from 0 towards −90° as f grows.
  EXPECT_LT(fields_of(lines.back())[2], fields_of(lines[1])[2]);
}

TEST_F(Cli, AdmittanceOfAnExpression) {
  const fs::path csv = path("tid.csv");
  Result r = run("admittance 'b-(k|c)' --param b=10 --param k=100 --param c=100 --freq 0.1:0.1:10 --out " +
                 quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 101u);
  EXPECT_EQ(lines[0], "f_hz,mag,phase_deg,re,im");
  const double b = 10, k = 100, c = 100;
  for (std::size_t n : {1u, 2u, 16u, 50u, 77u, 100u}) {
    const auto v = fields_of(lines[n]);
    ASSERT_EQ(v.size(), 5u) << lines[n];
    const double f = 0.1 * static_cast<double>(n);
    EXPECT_NEAR(v[0], f, 1e-9) << lines[n];
    const std::complex<double> s(0.0, 2 * std::numbers::pi * f);
    expect_admittance_row(v, b * s * (k + c * s) / (k + c * s + b * s * s), lines[n]);
  }
  EXPECT_NEAR(fields_of(lines.back())[0], 10.0, 1e-9);
}

TEST_F(Cli, AdmittanceMalformedExpressionShowsTheColumn) {
  Result r = run("admittance 'b-k|c' --param b=1 --param k=1 --param c=1 --freq 1:1:2");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "column 4")) << r.err;
  EXPECT_TRUE(contains(r.err, "without parentheses")) << r.err;
  // The expression, then a caret under its 4th character (same indentation).
  const auto lines = lines_of(r.err);
  bool caret = false;
  for (std::size_t n = 0; n + 1 < lines.size(); ++n) {
    const auto at = lines[n].find("b-k|c");
    if (at == std::string::npos || contains(lines[n], "error")) continue;
    caret = lines[n + 1] == std::string(at + 3, ' ') + "^";
  }
  EXPECT_TRUE(caret) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, AdmittanceMissingParameterNamesTheElement) {
  Result r = run("admittance 'b-(k|c)' --param b=1 --param k=1 --freq 1:1:2");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "no value for element(s) c")) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, AdmittanceBadFrequencyRange) {
  for (const char* freq : {"1:0:2", "abc", "2:1:1", "1:1"}) {
    SCOPED_TRACE(freq);
    const fs::path csv = path("f.csv");
    Result r = run(std::string("admittance S2-default --freq ") + quote(freq) + " --out " + quote(csv.string()));
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.code, -1);
    EXPECT_TRUE(contains(r.err, "--freq")) << r.err;
    EXPECT_TRUE(contains(r.err, freq)) << r.err;
    EXPECT_FALSE(fs::exists(csv));
  }
}

TEST_F(Cli, AdmittanceParamWithoutValue) {
  Result r = run("admittance 'k|c' --param k --param c=1 --freq 1:1:2");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.code, -1);
  EXPECT_TRUE(contains(r.err, "--param")) << r.err;
  EXPECT_TRUE(contains(r.err, "NAME=VALUE")) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, SimulateTwobarNetworkEqualsTwobar) {
  const fs::path net = path("net.csv"), ref = path("ref.csv");
  Result r = run("simulate " + quote(model_path("twobar_network.yaml")) + " --t-end 1 --sample 0.01 --out " +
                 quote(net.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(read_file(net));
  ASSERT_EQ(lines.size(), 102u);
  EXPECT_EQ(lines[0], "t,C_x,C_y,F_strut");

  // The network "k|c|b" is the separate spring, damper and inerter of models/twobar.yaml.
  Result q =
      run("simulate " + quote(model_path("twobar.yaml")) + " --t-end 1 --sample 0.01 --out " + quote(ref.string()));
  ASSERT_EQ(q.code, 0) << q.err;
  const auto expected = lines_of(read_file(ref));
  ASSERT_EQ(expected.size(), 102u);
  for (std::size_t n = 1; n < lines.size(); ++n) {
    const auto v = fields_of(lines[n]), w = fields_of(expected[n]);
    ASSERT_EQ(v.size(), 4u) << lines[n];
    ASSERT_EQ(w.size(), 3u) << expected[n];
    EXPECT_NEAR(v[0], 0.01 * static_cast<double>(n - 1), 1e-9) << lines[n];
    EXPECT_NEAR(v[1], w[1], 1e-7) << lines[n];
    EXPECT_NEAR(v[2], w[2], 1e-7) << lines[n];
    EXPECT_TRUE(std::isfinite(v[3])) << lines[n];
  }
  EXPECT_NEAR(fields_of(lines[1])[3], 0.0, 1e-9);  // released at rest with the free length initial
  double peak = 0;
  for (std::size_t n = 1; n < lines.size(); ++n) peak = std::max(peak, std::abs(fields_of(lines[n])[3]));
  EXPECT_GT(peak, 0.1);  // the strut does carry force once F_a acts
}

}  // namespace

TEST_F(Cli, AdmittanceInfiniteAtZeroFrequencyIsRefused) {
  // A spring path makes Y = k/s infinite at 0 Hz: an error, not a row of inf/nan.
  const fs::path csv = path("y0.csv");
  Result r = run("admittance 'k|c' --param k=100 --param c=1 --freq 0:1:2 --out " + quote(csv.string()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "infinite at f = 0 Hz")) << r.err;
  EXPECT_FALSE(fs::exists(csv));
  // Starting above 0 works.
  r = run("admittance 'k|c' --param k=100 --param c=1 --freq 0.5:0.5:2 --out " + quote(csv.string()));
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(Cli, ModesOfOneDofAndLinearModelExport) {
  // The 1-DOF's single mode at the linearised natural frequency (spec/01 §1.2) and its JSON export
  // with the reduced mass m + (Lb/L0)² b = 55 kg and stiffness k (Lb/L0)² = 5000 N/m.
  const fs::path json = path("lin.json"), csv = path("modes.csv");
  Result r = run("modes " + quote(model_path("onedof.yaml")) + " --export " + quote(json.string()) + " --out " +
                 quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "1.51748")) << r.out;  // six significant figures
  const std::string j = read_file(json);
  // The 1 × 1 matrices' entries, to rounding (an AVX2 build writes 54.999999999999986).
  auto entry = [&](const std::string& key) {
    const std::string head = "\"" + key + "\": [\n    [";
    const std::size_t at = j.find(head);
    return at == std::string::npos ? std::nan("") : std::stod(j.substr(at + head.size()));
  };
  EXPECT_NEAR(entry("M"), 55.0, 1e-9) << j;
  EXPECT_NEAR(entry("K"), 5000.0, 5e-6) << j;  // relative 1e-9 (a finite-difference linearisation)
  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(contains(lines[0], "mode,f_hz,f_damped_hz,zeta,re_lambda,im_lambda,mass.x,mass.y,mass.theta")) << lines[0];
}
}  // namespace test_apps_cli
