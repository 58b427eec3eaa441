#pragma once
// Test helper: a temp directory of this test process, so tests run in parallel (ctest -j) never share a
// file; removed with everything in it when the process that made it exits (issue 52: a `make test` run
// left ~50 folders behind; a forked child, e.g. a death test's, leaves it to its parent).
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace inerta::testing {

struct TempDir {
  std::filesystem::path path;
  pid_t owner = ::getpid();
  TempDir() : path(std::filesystem::temp_directory_path() / ("inerta_test_" + std::to_string(::getpid()))) {}
  ~TempDir() {
    std::error_code ec;
    if (::getpid() == owner) std::filesystem::remove_all(path, ec);
  }
};

inline std::filesystem::path temp_dir() {
  static TempDir dir;
  std::filesystem::create_directories(dir.path);
  return dir.path;
}

}  // namespace inerta::testing
