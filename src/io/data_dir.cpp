// The run-time data folder (io/data_dir.hpp).
#include "inerta/io/data_dir.hpp"

#include <cstdlib>
#include <mutex>

namespace inerta::io {

namespace {
std::mutex mutex;
std::filesystem::path host;  // set_data_dir's
}  // namespace

std::filesystem::path source_tree() { return INERTA_SOURCE_TREE; }

bool set_data_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir / "criteria", ec)) return false;
  const std::lock_guard<std::mutex> lock(mutex);
  host = std::filesystem::weakly_canonical(dir, ec);
  if (ec) host = dir;
  return true;
}

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("INERTA_DATA_DIR"); env && *env) return env;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!host.empty()) return host;
  }
  return source_tree();
}

}  // namespace inerta::io
