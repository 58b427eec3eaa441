#pragma once
// Test helper: a temp directory of this test process, so tests run in parallel (ctest -j) never share a file.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace inerta::testing {

inline std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("inerta_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace inerta::testing
