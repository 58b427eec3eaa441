// `inerta frf --input`, `rms`, `modes --export` of any model and `optimise` of a model study
// (apps/inerta/linear.cpp): the numbers the library gives, the files, and every documented error.
#include <gtest/gtest.h>

#include <fstream>

#include "inerta/analysis/state_space.hpp"
#include "inerta/io/model_file.hpp"
#include "support/cli.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_linear_cli {

namespace {

using inerta::testing::contains;
using inerta::testing::quote;
using inerta::testing::read_file;

std::string src(const std::string& rel) { return quote(std::string(INERTA_SOURCE_DIR) + "/" + rel); }

class LinearCli : public inerta::testing::CliTest {};

}  // namespace

TEST_F(LinearCli, FrfOfAnyInputWritesMagnitudePhaseAndParts) {
  const auto csv = dir_ / "qf.csv";
  const auto r = run_inerta("frf " + src("models/quarter_car.yaml") + " --input road --outputs a_body,travel --freq 1:1:3 --out " +
                            quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = read_file(csv);
  EXPECT_TRUE(contains(text, "f_hz,a_body_mag,a_body_phase_deg,a_body_re,a_body_im,travel_mag")) << text;
  // The same H as the library at 2 Hz.
  const auto ss = inerta::analysis::state_space(inerta::io::load_model(std::string(INERTA_SOURCE_DIR) + "/models/quarter_car.yaml"),
                                                {"road"}, {"a_body", "travel"});
  const double mag = std::abs(inerta::analysis::frequency_response(ss, {2.0})[0](0, 0));
  std::istringstream in(text);
  std::string line;
  std::getline(in, line), std::getline(in, line), std::getline(in, line);  // header, 1 Hz, 2 Hz
  EXPECT_NEAR(std::stod(line.substr(line.find(',') + 1)), mag, 1e-8 * mag) << line;
}

TEST_F(LinearCli, ErrorsNameTheInputOutputOrOption) {
  auto expect = [&](const std::string& args, const std::string& part) {
    const auto r = run_inerta(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_TRUE(contains(r.err, part)) << args << "\n" << r.err;
  };
  const std::string qc = src("models/quarter_car.yaml");
  expect("frf " + qc + " --input roud --outputs a_body --freq 1:1:2", "no input 'roud'");
  expect("frf " + qc + " --input road --outputs a_bdy --freq 1:1:2", "no output 'a_bdy'");
  expect("frf " + qc + " --input road --outputs a_body --freq 1:1:2 --method stepped-sine", "with --input the FRF is the linear one");
  expect("frf " + qc + " --input road --outputs a_body --freq 1:1:2 --set k_s.kk=1", "k_s.kk");
  expect("rms " + qc + " --outputs a_body", "give either a road");
  expect("rms " + qc + " --outputs a_body --road J --speed 20 --inputs road", "expected an ISO 8608 class A to H, got 'J'");
  expect("rms " + qc + " --outputs a_body --road C --inputs road", "a road needs the speed");
  expect("rms " + qc + " --outputs y_body --road C --speed 20 --inputs road", "'y_body' follows the road displacement statically");
  expect("rms " + qc + " --outputs a_body --white-noise F_body=-1", "expected INPUT=W with W > 0");
  expect("rms " + qc + " --outputs a_body --white-noise F_body=1", "output 'a_body' responds directly to input 'F_body'");
}

TEST_F(LinearCli, RmsPrintsAndWritesTheLyapunovValues) {
  const auto csv = dir_ / "rms.csv";
  const auto r = run_inerta("rms " + src("models/quarter_car.yaml") +
                            " --road C --speed 25 --inputs road --outputs travel --out " + quote(csv.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  inerta::analysis::Road road;
  road.speed = 25, road.inputs = {"road"};
  const auto ss = inerta::analysis::state_space(inerta::io::load_model(std::string(INERTA_SOURCE_DIR) + "/models/quarter_car.yaml"),
                                                {"road"}, {"travel"});
  const double rms = inerta::analysis::road_response(ss, road).rms[0];
  const std::string text = read_file(csv);
  ASSERT_TRUE(contains(text, "output,rms\ntravel,")) << text;
  EXPECT_NEAR(std::stod(text.substr(text.find("travel,") + 7)), rms, 1e-9 * rms);
}

TEST_F(LinearCli, ModesExportsTheStateSpaceAsJsonAndCsv) {
  const auto json = dir_ / "qss.json";
  const auto r = run_inerta("modes " + src("models/quarter_car.yaml") + " --export " + quote(json.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "undamped natural frequencies of (M, K)")) << r.out;
  const std::string j = read_file(json);
  EXPECT_TRUE(contains(j, "\"states\": [\"wheel.y\", \"body.y\", \"wheel.y_dot\", \"body.y_dot\"]")) << j;
  EXPECT_TRUE(contains(j, "\"inputs\": [\"F_body\", \"road\"]")) << j;
  const std::string a = read_file(dir_ / "qss_A.csv");
  EXPECT_TRUE(contains(a, "wheel.y,body.y,wheel.y_dot,body.y_dot\n0,0,1,0\n")) << a;
  EXPECT_TRUE(contains(read_file(dir_ / "qss_B.csv"), "F_body,road\n")) << read_file(dir_ / "qss_B.csv");
}

TEST_F(LinearCli, AModelStudyWritesItsTableAndFiles) {
  const auto out = dir_ / "qs";
  const auto r = run_inerta("optimise " + src("studies/quarter_car.yaml") + " --no-plots --out " + quote(out.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "[1/4] c ")) << r.out;
  // The default's J is the body acceleration rms of the model's own damper on the study's road,
  // computed here by the state space and the Lyapunov road response directly.
  inerta::analysis::Road road;
  road.gd0 = 256e-6, road.speed = 25, road.inputs = {"road"};
  const auto ss = inerta::analysis::state_space(inerta::io::load_model(std::string(INERTA_SOURCE_DIR) + "/models/quarter_car.yaml"),
                                                {"road"}, {"a_body"});
  const double a_rms = inerta::analysis::road_response(ss, road).rms[0];
  const auto at = r.out.find("default (c=1000) J = ");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(r.out.substr(at + 21)), a_rms, 1e-5 * a_rms) << r.out;
  const std::string csv = read_file(out / "results.csv");
  EXPECT_TRUE(contains(csv, "layout,expression,J,vs_default_pct,feasible,evaluations,a_body,travel,tyre_force,c,b,k1\n")) << csv;
  EXPECT_TRUE(contains(read_file(out / "frf.csv"), "f_hz,a_body_default,a_body_best")) << read_file(out / "frf.csv");
  EXPECT_TRUE(contains(read_file(out / "results.json"), "\"objective\": \"rms\""));
  // A J2 study may say so; anything else there is an error naming the key.
  std::ofstream(dir_ / "bad.yaml") << "model: " << std::string(INERTA_SOURCE_DIR) << "/models/hsx.yaml\ncatenary: "
                                   << std::string(INERTA_SOURCE_DIR) << "/models/catenary.yaml\nobjective: {type: j2, x: 1}\n"
                                   << "speeds: {from: 100, to: 200, step: 50, unit: kmh}\nlayouts: [S2-1]\n";
  const auto b = run_inerta("optimise " + quote((dir_ / "bad.yaml").string()));
  EXPECT_EQ(b.code, 2);
  EXPECT_TRUE(contains(b.err, "bad.yaml:3: 'objective': a study with catenary: optimises J2")) << b.err;
}
}  // namespace test_apps_linear_cli
