// `inerta optimise STUDY --out DIR` on a tiny study (one catenary, two speeds, one layout, one start):
// the table, the results and the figures' CSV files, and the PNGs or a note that they cannot be drawn.
// The study's name has double quotes, a backslash and non-ASCII characters: results.json stays valid.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_apps_optimise_cli {

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string l;
  std::getline(in, l);
  return l;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(OptimiseCli, TinyStudyWritesTheTableResultsAndFigureData) {
  const fs::path dir = fs::temp_directory_path() / ("inerta_optimise_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path study = dir / "tiny.yaml", out = dir / "out";
  const std::string name = "my \"quoted\" \\ study \xc3\xa9";
  std::ofstream(study) << "name: '" << name << "'\nmodel: " << INERTA_SOURCE_DIR
                       << "/models/hsx.yaml\ncatenary: " << INERTA_SOURCE_DIR
                       << "/models/catenary.yaml\n"
                          "speeds: {from: 150, to: 200, step: 50, unit: kmh}\n"
                          "search: {starts: 1, seed: 1, min_step: 0.1}\n"
                          "layouts: [b|k]\n";
  const std::string cmd = std::string(INERTA_CLI) + " optimise '" + study.string() + "' --out '" + out.string() +
                          "' --map 3 > '" + (dir / "stdout.txt").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  const std::string text = read(dir / "stdout.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
  EXPECT_TRUE(contains(text, "layout")) << text;
  EXPECT_TRUE(contains(text, "post-processing for the figures")) << text;
  EXPECT_TRUE(contains(text, "[4/5] J2 map over (b, k) of b|k, 3×3 points")) << text;
  EXPECT_TRUE(contains(text, "time-domain re-check")) << text;

  EXPECT_EQ(first_line(out / "results.csv"), "layout,network,b,c,k,J2,reduction_pct,v_kmh,mean_N,evaluations");
  nlohmann::ordered_json results;
  ASSERT_NO_THROW(results = nlohmann::ordered_json::parse(read(out / "results.json"))) << read(out / "results.json");
  EXPECT_EQ(results["study"], name);
  ASSERT_EQ(results["layouts"].size(), 1u);
  EXPECT_EQ(results["layouts"][0]["layout"], "b|k");
  EXPECT_EQ(results["layouts"][0]["values"].size(), 2u);  // b and k
  EXPECT_GT(results["layouts"][0]["J2"].get<double>(), 0.0);
  EXPECT_EQ(first_line(out / "sigma.csv"), "design,catenary,v_kmh,sigma_N,mean_N");
  EXPECT_EQ(first_line(out / "frf.csv"), "design,f_hz,mag,phase_deg");
  EXPECT_EQ(first_line(out / "contact.csv"), "design,catenary,t_s,F_N");
  EXPECT_EQ(first_line(out / "j2_map.csv"), "b,k,J2_N");
  EXPECT_EQ(first_line(out / "centripetal.csv"), "design,centripetal,catenary,v_kmh,sigma_N,mean_N");
  EXPECT_TRUE(fs::exists(out / "report.json"));
  EXPECT_TRUE(nlohmann::json::accept(read(out / "report.json"))) << read(out / "report.json");
  // Either the PNGs were drawn, or the program said why not and still succeeded.
  if (contains(text, "note: no plots")) {
    EXPECT_FALSE(fs::exists(out / "sigma.png"));
  } else {
    for (const char* png : {"sigma.png", "frf.png", "contact.png", "j2_map.png", "centripetal.png"})
      EXPECT_GT(fs::exists(out / png) ? fs::file_size(out / png) : 0, 1000u) << png << "\n" << text;
  }
  fs::remove_all(dir);
}
}  // namespace test_apps_optimise_cli
