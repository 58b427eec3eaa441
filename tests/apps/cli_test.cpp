// The `inerta` command-line program (apps/inerta/main.cpp), run as a separate process.
// Every file the tests write goes to a fresh directory under the system temp directory.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string model_path(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

// Single-quoted for /bin/sh.
std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

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

struct Result {
  int code = -1;  ///< exit status (-1 if the process did not exit normally)
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("inerta_cli_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path path(const std::string& name) const { return dir_ / name; }

  // Runs `inerta <args>` (args already quoted as needed), capturing stdout and stderr.
  Result run(const std::string& args) {
    const fs::path out = path("stdout.txt"), err = path("stderr.txt");
    const std::string cmd =
        quote(INERTA_CLI) + " " + args + " >" + quote(out.string()) + " 2>" + quote(err.string()) + " </dev/null";
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(out);
    r.err = read_file(err);
    return r;
  }

  fs::path dir_;
};

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

}  // namespace
