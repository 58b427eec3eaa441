// The linear-model export (io/linear_model_file.hpp) read back with nlohmann-json: valid for a
// model name with quotes, a backslash and non-ASCII, and every matrix entry bit for bit.
#include "inerta/io/linear_model_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_linear_model_file {

using namespace inerta;

namespace {

void expect_rows(const nlohmann::ordered_json& rows, const Eigen::MatrixXd& m, const char* what) {
  ASSERT_TRUE(rows.is_array()) << what;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(m.rows())) << what;
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    const auto& row = rows[static_cast<std::size_t>(i)];
    ASSERT_EQ(row.size(), static_cast<std::size_t>(m.cols())) << what;
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      EXPECT_EQ(row[static_cast<std::size_t>(j)].get<double>(), m(i, j)) << what << "(" << i << ", " << j << ")";
  }
}

}  // namespace

TEST(LinearModelFile, ReadsBackExactlyWithAnAwkwardName) {
  // The HSX pantograph on its rig: constraints (N ≠ I) and an internal state (z) in its actuator.
  mbs::Model model = io::load_model(std::string(INERTA_SOURCE_DIR) + "/models/hsx.yaml");
  model.name = "my \"quoted\" \\ model \xc3\xa9";
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  const mbs::LinearModel lin = mbs::linearise(model, x);
  ASSERT_GT(lin.nz, 0);
  ASSERT_LT(lin.dof, model.n_coords());

  const auto path = std::filesystem::temp_directory_path() / ("inerta_linear_model_" + std::to_string(::getpid()) +
                                                             ".json");
  io::write_linear_model(path.string(), model, lin);
  std::ifstream in(path);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);  // keeps the key order
  std::filesystem::remove(path);

  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"model", "state", "coordinates", "dof", "internal_states", "q_e", "N", "A",
                                            "M", "C", "K"}));
  EXPECT_EQ(j["model"], model.name);
  EXPECT_EQ(j["state"], "X = [xi; xi_dot; z], q = q_e + N xi, dX/dt = A X");
  ASSERT_EQ(j["coordinates"].size(), static_cast<std::size_t>(model.n_coords()));
  for (int k = 0; k < model.n_coords(); ++k) EXPECT_EQ(j["coordinates"][static_cast<std::size_t>(k)], model.coord_name(k));
  EXPECT_EQ(j["dof"], lin.dof);
  EXPECT_EQ(j["internal_states"], lin.nz);
  expect_rows(j["q_e"], x.q.transpose(), "q_e");
  expect_rows(j["N"], lin.N, "N");
  expect_rows(j["A"], lin.A, "A");
  expect_rows(j["M"], lin.M, "M");
  expect_rows(j["C"], lin.C, "C");
  expect_rows(j["K"], lin.K, "K");
}
}  // namespace test_io_linear_model_file
