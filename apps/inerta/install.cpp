// Where this program runs from (install.hpp).
#include "install.hpp"

#include <filesystem>
#include <system_error>

#include "inerta/io/data_dir.hpp"

namespace inerta::cli {

namespace {
std::filesystem::path program_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}
}  // namespace

void find_installed_data() {
  if (const auto bin = program_dir(); !bin.empty()) io::set_data_dir(bin / ".." / INERTA_DATA_REL_DIR);
}

std::string python_package_dir() {
  if (const auto bin = program_dir(); !bin.empty()) {
    const std::filesystem::path installed = bin / ".." / INERTA_PYTHON_REL_DIR;
    std::error_code ec;
    if (std::filesystem::is_directory(installed / "inerta", ec)) return std::filesystem::weakly_canonical(installed, ec).string();
  }
  return INERTA_PYTHON_DIR;
}

}  // namespace inerta::cli
