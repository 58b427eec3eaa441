// Contact-wire wear (issue 51 item 5; docs/catenary-fe.md "Wear"): the worn line against the same line
// with its wire data changed by hand, and the mass a local wear removes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"

namespace test_catenary_fe_wear {

using namespace inerta;
using catenary::FeCatenaryData;
using catenary::FeLine;

const char* const kStitched = INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml";

FeCatenaryData stitched(const std::vector<std::string>& sets = {}) {
  std::vector<std::string> s{"line.spans=6"};
  s.insert(s.end(), sets.begin(), sets.end());
  return io::read_fe_catenary_data(kStitched, s);
}

void expect_same_line(const FeLine& a, const FeLine& b) {
  ASSERT_EQ(a.n_dofs(), b.n_dofs());
  EXPECT_EQ((a.K() - b.K()).norm(), 0.0);
  EXPECT_EQ((a.M() - b.M()).norm(), 0.0);
  EXPECT_EQ((a.K_static() - b.K_static()).norm(), 0.0);
  for (double x = 0; x <= a.length(); x += 1.3) EXPECT_EQ(a.static_height(x), b.static_height(x)) << x;
  ASSERT_EQ(a.droppers().size(), b.droppers().size());
  for (std::size_t k = 0; k < a.droppers().size(); ++k) {
    EXPECT_EQ(a.droppers()[k].tension, b.droppers()[k].tension) << k;
    EXPECT_EQ(a.droppers()[k].length, b.droppers()[k].length) << k;
  }
}

TEST(FeWear, UniformWearIsTheLineWithItsContactWireDataChangedByHand) {
  // 80 % of the section: mass per length × 0.8, EI × 0.8², the tension unchanged — bit for bit.
  const FeLine worn(stitched({"wear.uniform=80"}));
  FeCatenaryData hand = stitched();
  const double p = 80.0 / 100;
  hand.contact_wire.mass_per_length *= p;
  hand.contact_wire.EI *= p * p;
  expect_same_line(worn, FeLine(hand));
  // and it is not the new line: lighter, so the droppers carry less
  const FeLine fresh(stitched());
  EXPECT_LT(worn.droppers()[3].tension, fresh.droppers()[3].tension);
  // 100 %: the new wire, bit for bit
  expect_same_line(FeLine(stitched({"wear.uniform=100"})), fresh);
}

TEST(FeWear, AProfileAtOnePercentEverywhereIsTheUniformWear) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("inerta_wear_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "flat.csv") << "x,percent\n0,85\n390,85\n";
  const FeLine flat(stitched({"wear.profile=" + (dir / "flat.csv").string()}));
  expect_same_line(flat, FeLine(stitched({"wear.uniform=85"})));
  std::filesystem::remove_all(dir);
}

TEST(FeWear, ALocalWearRemovesItsShareOfTheContactWiresMass) {
  // Worn to 80 % over spans 4–5 (195–325 m): the contact wire's consistent mass (the sum of its w–w
  // entries is ∫ρA dx) is 0.2 ρA × 130 m less; droppers massless so that nothing else moves.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("inerta_wear2_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "local.csv") << "x,percent\n0,100\n194.9,100\n195.1,80\n324.9,80\n325.1,100\n390,100\n";
  const std::vector<std::string> light{"droppers.mass_per_length=0", "stitch.droppers.mass_per_length=0"};
  std::vector<std::string> worn_sets = light;
  worn_sets.push_back("wear.profile=" + (dir / "local.csv").string());
  const FeLine fresh(stitched(light)), worn(stitched(worn_sets));
  auto contact_mass = [](const FeLine& l) {
    double m = 0;
    for (int i = 0; i < l.n_nodes(); ++i)
      for (int j = std::max(0, i - 1); j <= std::min(l.n_nodes() - 1, i + 1); ++j)
        if (l.dof(1, i, 0) >= 0 && l.dof(1, j, 0) >= 0) m += l.M().coeff(l.dof(1, i, 0), l.dof(1, j, 0));
    return m;
  };
  const double rhoA = stitched().contact_wire.mass_per_length;
  EXPECT_NEAR(contact_mass(fresh) - contact_mass(worn), 0.2 * rhoA * 130, 1e-9 * rhoA * 390);
  // The static sag changes where it is worn: the worn spans' droppers carry less than the new ones'.
  double new_load = 0, worn_load = 0;
  for (std::size_t k = 0; k < fresh.droppers().size(); ++k)
    if (fresh.droppers()[k].x > 195 && fresh.droppers()[k].x < 325)
      new_load += fresh.droppers()[k].tension, worn_load += worn.droppers()[k].tension;
  EXPECT_LT(worn_load, new_load);
  std::filesystem::remove_all(dir);
}

TEST(FeWear, FileErrorsNameTheKey) {
  auto error = [](const std::vector<std::string>& sets) {
    try {
      (void)stitched(sets);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error({"wear.uniform=0"}).find("wear: uniform: must be > 0 (%), got 0"), std::string::npos) << error({"wear.uniform=0"});
  EXPECT_NE(error({"wear.uniform=120"}).find("must be <= 100 (%)"), std::string::npos);
  EXPECT_NE(error({"wear.profile=/nonexistent/w.csv"}).find("--set 'wear.profile=/nonexistent/w.csv': /nonexistent/w.csv"), std::string::npos)
      << error({"wear.profile=/nonexistent/w.csv"});
  EXPECT_NE(error({"wear.profile=/dev/zero"}).find("not a regular file"), std::string::npos) << error({"wear.profile=/dev/zero"});
  EXPECT_NE(error({"wear.uniform=nan"}).find("must be > 0 (%), got nan"), std::string::npos) << error({"wear.uniform=nan"});
  EXPECT_NE(error({"stitch.droppers.EA=1e300"}).find("must be <= 1e+09 (N), got 1e+300"), std::string::npos)
      << error({"stitch.droppers.EA=1e300"});
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("inerta_wear3_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.csv") << "x,percent\n0,100\n100,130\n";
  EXPECT_NE(error({"wear.profile=" + (dir / "bad.csv").string()}).find("percent must be > 0 and at most 100, got 130"), std::string::npos)
      << error({"wear.profile=" + (dir / "bad.csv").string()});
  // in the file: at the line of its key
  std::ifstream in(kStitched);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "line.yaml") << text << "wear: {uniform: 80, profile: w.csv}\n";
  try {
    (void)io::read_fe_catenary_data((dir / "line.yaml").string());
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("'profile': give either wear.uniform or wear.profile, not both"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "line.yaml") << text << "wear: {uniform: -5}\n";
  try {
    (void)io::read_fe_catenary_data((dir / "line.yaml").string());
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("line.yaml:"), std::string::npos) << w;
    EXPECT_NE(w.find("'uniform': must be > 0 (%), got -5 in wear"), std::string::npos) << w;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace test_catenary_fe_wear
