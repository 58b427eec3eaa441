// `inerta identify …` run as a separate process on synthetic measurements written as CSV
// (docs/cli.md#identify); input errors exit 2 and name the file, line and column.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "inerta/analysis/frf.hpp"
#include "inerta/io/model_file.hpp"
#include "support/cli.hpp"
#include "support/synthetic.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_identify_cli {

namespace {

namespace fs = std::filesystem;
using inerta::testing::cd;

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;
using inerta::testing::Result;

// The number printed after `key` (e.g. "k2 = ") in `text`; NaN if absent.
double value_after(const std::string& text, const std::string& key) {
  const std::size_t p = text.find(key);
  return p == std::string::npos ? NAN : std::stod(text.substr(p + key.size()));
}

class Identify : public inerta::testing::CliTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  Result run(const std::string& args) const { return run_inerta("identify " + args); }
  // Head and upper-arm FRFs of the 2-DOF model, 0.5–20 Hz, with `noise` relative complex noise.
  std::string head_csv(const inerta::testing::HeadArm& p, double noise, unsigned seed) const {
    std::mt19937 rng(seed);
    std::string s = "f_hz,P_ay_re,P_ay_im,E_ay_re,E_ay_im\n";
    for (int k = 0; k <= 195; ++k) {
      const double f = 0.5 + 0.1 * k;
      auto [h, e] = inerta::testing::head_arm_frf(p, f);
      h = inerta::testing::noisy(h, noise, rng), e = inerta::testing::noisy(e, noise, rng);
      s += fmt::format("{:.4f},{:.17g},{:.17g},{:.17g},{:.17g}\n", f, h.real(), h.imag(), e.real(), e.imag());
    }
    return write("frf.csv", s);
  }
};

// ---- head-suspension ----

TEST_F(Identify, HeadSuspensionRecoversK2AndC2) {
  inerta::testing::HeadArm p;
  p.k2 = 7200, p.c2 = 65;  // the chapter-4 pantograph's values, not the defaults of the helper
  const std::string csv = head_csv(p, 0.01, 3), per = path("per.csv");
  Result r = run("head-suspension " + quote(csv) + " --head-mass 5.41 --out " + quote(per));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "band 4–20 Hz (161 frequencies)")) << r.out;
  EXPECT_NEAR(value_after(r.out, "k2 = ") / p.k2, 1.0, 0.02) << r.out;
  EXPECT_NEAR(value_after(r.out, "c2 = ") / p.c2, 1.0, 0.05) << r.out;
  std::istringstream lines(read_file(per));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "f_hz,k2,c2,in_band");
  int rows = 0, in_band = 0;
  while (std::getline(lines, line)) ++rows, in_band += line.back() == '1';
  EXPECT_EQ(rows, 196);
  EXPECT_EQ(in_band, 161);
}

TEST_F(Identify, HeadSuspensionBandWithoutData) {
  const std::string csv = head_csv({}, 0, 1);
  Result r = run("head-suspension " + quote(csv) + " --head-mass 5.41 --band 30:40");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "no frequency in the band 30–40 Hz (data cover 0.5–20 Hz)")) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Identify, HeadSuspensionMissingColumnNamesFileAndColumn) {
  const std::string csv = write("frf.csv", "f_hz,P_ay_re,P_ay_im,E_ay_re\n1,0,0,0\n");
  Result r = run("head-suspension " + quote(csv) + " --head-mass 5.41");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, csv + ": missing column 'E_ay_im'; the header has: f_hz, P_ay_re, P_ay_im, E_ay_re"))
      << r.err;
  const std::string none = write("none.csv", "f_hz,x\n1,0\n");
  r = run("head-suspension " + quote(none) + " --head-mass 5.41");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "missing columns 'P_ay_re' and 'P_ay_im' (or 'P_ay_mag' and 'P_ay_phase_deg')")) << r.err;
}

TEST_F(Identify, NonNumericCellAndBadFrequencyNameTheLine) {
  const std::string csv = write("frf.csv", "f_hz,P_ay_re,P_ay_im,E_ay_re,E_ay_im\n5,1,2,3,4\n6,1,x2,3,4\n");
  Result r = run("head-suspension " + quote(csv) + " --head-mass 5.41");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, csv + ":3: column 'P_ay_im': 'x2' is not a finite number")) << r.err;
  const std::string zero = write("zero.csv", "f_hz,P_ay_re,P_ay_im,E_ay_re,E_ay_im\n5,1,2,3,4\n0,1,2,3,4\n");
  r = run("head-suspension " + quote(zero) + " --head-mass 5.41");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, zero + ":3: column 'f_hz': 0 Hz; expected a frequency > 0")) << r.err;
}

TEST_F(Identify, MissingFileAndRaggedRow) {
  Result r = run("actuator-static " + quote(path("nothing.csv")));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, path("nothing.csv") + ": cannot open the CSV file")) << r.err;
  const std::string csv = write("s.csv", "velocity,force\n0.001,1\n0.002\n");
  r = run("actuator-static " + quote(csv));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, csv + ":3: 1 field(s), but the header has 2 column(s)")) << r.err;
}

// ---- frf-fit ----

TEST_F(Identify, FrfFitRecoversTwoHsxParametersFromInertaFrfOutput) {
  // "Measured" = the HSX with c2 = 60 and c_f = 150 (file: 78, 128) by frf_linear, written as
  // the mag/phase CSV that `inerta frf` writes; the search starts at the centre of the given boxes.
  const std::string model = std::string(INERTA_SOURCE_DIR) + "/models/hsx.yaml";
  const std::vector<double> f = {0.5, 1, 1.5, 2, 3, 4, 5, 5.5, 6, 6.5, 7, 8, 9, 10, 11};
  const auto H =
      inerta::analysis::frf_linear(inerta::io::load_model_file(model, {"c2.c=60", "kf_cf.c=150"}), {"P_ay", "E_ay"}, f);
  std::string s = "f_hz,P_ay_mag,P_ay_phase_deg,E_ay_mag,E_ay_phase_deg\n";
  for (std::size_t k = 0; k < f.size(); ++k)
    s += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", f[k], std::abs(H.H[0][k]),
                     std::arg(H.H[0][k]) * 180 / M_PI, std::abs(H.H[1][k]), std::arg(H.H[1][k]) * 180 / M_PI);
  const std::string csv = write("meas.csv", s), fitted = path("fitted.csv");
  Result r = run(quote("frf-fit") + " " + quote(model) + " --measured " + quote(csv) +
                 " --fit c2.c=20:200 --fit kf_cf.c=30:600 --starts 1 --out " + quote(fitted));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "outputs P_ay, E_ay, band 0.5–11 Hz (15 frequencies)")) << r.out;
  EXPECT_NEAR(value_after(r.out, "c2.c ") / 60, 1.0, 0.01) << r.out;
  EXPECT_NEAR(value_after(r.out, "kf_cf.c ") / 150, 1.0, 0.01) << r.out;
  EXPECT_TRUE(contains(read_file(fitted), "f_hz,P_ay_re,P_ay_im,P_ay_meas_re,P_ay_meas_im,E_ay_re")) << r.out;
}

TEST_F(Identify, FrfFitErrors) {
  const std::string model = std::string(INERTA_SOURCE_DIR) + "/models/hsx.yaml";
  const std::string csv = write("meas.csv", "f_hz,P_ay_re,P_ay_im\n1,0.1,0.1\n2,0.1,0.1\n");
  Result r = run("frf-fit " + quote(model) + " --measured " + quote(csv) + " --fit nothing.c");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "parameter 'nothing.c': no force element, body or joint named 'nothing'")) << r.err;
  r = run("frf-fit " + quote(model) + " --measured " + quote(csv) + " --fit c2.c --band 20:30");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "no measured frequency in the band 20–30 Hz (data cover 1–2 Hz)")) << r.err;
  r = run("frf-fit " + quote(model) + " --measured " + quote(csv) + " --fit c2.c --outputs P_ay,X_ay");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "'X_ay_re' and 'X_ay_im'")) << r.err;
  r = run("frf-fit " + quote(model) + " --measured " + quote(csv) + " --fit c2.c --set c2.x=3");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "override 'c2.x=3': 'c2' has no value 'x'")) << r.err;
  EXPECT_EQ(r.out, "");  // checked before the search starts
}

// ---- actuator-static ----

TEST_F(Identify, ActuatorStaticRecoversTheThesisFit) {
  inerta::testing::ActuatorTruth a;
  a.F_c = 5374, a.F_r = 40, a.c1 = 9000;
  auto [v, F] = inerta::testing::actuator_static_data(a, 2.0, 5);
  std::string s = "velocity,force\n";
  for (std::size_t k = 0; k < v.size(); ++k) s += fmt::format("{:.17g},{:.17g}\n", v[k], F[k]);
  Result r = run("actuator-static " + quote(write("s.csv", s)));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(value_after(r.out, "F_c = "), a.F_c, 2.0) << r.out;
  EXPECT_NEAR(value_after(r.out, "F_r = "), a.F_r, 2.0) << r.out;
  EXPECT_NEAR(value_after(r.out, "c1 = ") / a.c1, 1.0, 0.04) << r.out;
}

TEST_F(Identify, ActuatorStaticErrors) {
  Result r = run("actuator-static " + quote(write("a.csv", "velocity,F\n0.001,1\n0.002,2\n-0.001,1\n-0.002,0\n")));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "missing column 'force'; the header has: velocity, F")) << r.err;
  r = run("actuator-static " + quote(write("b.csv", "velocity,force\n0.001,1\n0.002,2\n0.003,1\n0.004,0\n")));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "the backward (v < 0) stroke has 0 distinct velocities; its line needs at least 2"))
      << r.err;
  r = run("actuator-static " + quote(write("c.csv", "velocity,force\n0.001,1\n")));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "c.csv: 1 data row(s); the constant-velocity fit")) << r.err;
}

// ---- actuator-dynamic ----

TEST_F(Identify, ActuatorDynamicRecoversK1) {
  inerta::testing::ActuatorTruth a;
  a.k1 = 95e3;  // the thesis's 3 mm result
  const auto tests = inerta::testing::actuator_dynamic_data(a, 3e-3, {0.5, 1, 2, 3, 4, 5, 6}, 3.0, 5e-6, 11, 4);
  std::string s = "f_hz,t,displacement,force\n";
  for (const auto& T : tests)
    for (std::size_t k = 0; k < T.t.size(); ++k)
      s += fmt::format("{:g},{:.10g},{:.10g},{:.10g}\n", T.f, T.t[k], T.x[k], T.F[k]);
  const std::string out = path("y.csv");
  Result r = run("actuator-dynamic " + quote(write("d.csv", s)) +
                 " --c1 10440 --piston-mass 3.45 --friction 53 --out " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(value_after(r.out, "k1 = ") / a.k1, 1.0, 0.02) << r.out;
  EXPECT_TRUE(contains(r.out, "7 frequencies")) << r.out;
  EXPECT_TRUE(contains(read_file(out), "f_hz,amplitude,Y_E_re,Y_E_im,Y_re,Y_im\n0.5,")) << read_file(out);
}

TEST_F(Identify, ActuatorDynamicErrors) {
  std::string s = "t,displacement,force\n";
  for (int k = 0; k < 20; ++k) s += fmt::format("{},{},{}\n", 0.01 * k, std::sin(0.3 * k), 1.0);
  const std::string csv = write("d.csv", s);
  Result r = run("actuator-dynamic " + quote(csv) + " --c1 10440");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, csv + ": no column 'f_hz'; give the excitation frequency with --freq F")) << r.err;
  r = run("actuator-dynamic " + quote(csv) + " --c1 10440 --freq 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "1 Hz: the samples span 0.19 s, less than one period (1 s)")) << r.err;
  r = run("actuator-dynamic " + quote(write("e.csv", "t,displacement,force\n0,0,0\n0.1,1,1\n")) + " --c1 1 --freq 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.err, "2 data row(s); the correlation method needs at least 8")) << r.err;
  r = run("actuator-dynamic " + quote(csv) + " --freq 1");
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(contains(r.err, "--c1")) << r.err;
}

}  // namespace
}  // namespace test_apps_identify_cli
