#pragma once
// Shared helpers of the fuzz targets (docs/fuzzing.md). Each target defines
// LLVMFuzzerTestOneInput; std::exception (ModelError, NetworkError, ...) is an accepted outcome,
// anything else — a crash, a sanitizer report, an uncaught non-std exception, a hang — is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#ifndef INERTA_SOURCE_DIR
#error "INERTA_SOURCE_DIR must name the source tree (fuzz/CMakeLists.txt defines it)"
#endif

namespace inerta::fuzz {

inline std::string as_text(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Splits an input into a file's text and overrides: lines after a line "#@overrides" (a YAML
/// comment, so such seeds are still valid files) are overrides ("NAME.KEY=VALUE"), one a line.
inline std::string split_overrides(std::string text, std::vector<std::string>& overrides) {
  const std::string marker = "#@overrides\n";
  const auto at = text.find(marker);
  if (at == std::string::npos) return text;
  const std::string rest = text.substr(at + marker.size());
  text.resize(at);
  std::size_t start = 0;
  while (start < rest.size()) {
    std::size_t end = rest.find('\n', start);
    if (end == std::string::npos) end = rest.size();
    if (end > start) overrides.push_back(rest.substr(start, end - start));
    start = end + 1;
  }
  return text;
}

/// A per-process scratch tree for the path-based loaders, made once and removed at exit:
///   <root>/models/   symlinks to every file of the source tree's models/ (plus heights.csv)
///   <root>/studies/  where a study input is written, so "../models/hsx.yaml" resolves
/// <root> is under /dev/shm when it exists (no disk traffic per input), else $TMPDIR or /tmp.
class Scratch {
 public:
  static Scratch& get() {
    static Scratch s;
    return s;
  }
  const std::filesystem::path& root() const { return root_; }
  /// Writes `text` to <root>/<dir>/fuzz-input.yaml and returns the path.
  std::string write(const std::string& dir, const std::string& text) const {
    const auto p = root_ / dir / "fuzz-input.yaml";
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    f.close();
    if (!f) std::abort();  // the harness itself failed: not a finding of the library
    return p.string();
  }

 private:
  Scratch() {
    namespace fs = std::filesystem;
    fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    root_ = base / ("inerta-fuzz-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(root_, ec);
    fs::create_directories(root_ / "models");
    fs::create_directories(root_ / "studies");
    for (const auto& e : fs::directory_iterator(fs::path(INERTA_SOURCE_DIR) / "models"))
      fs::create_symlink(e.path(), root_ / "models" / e.path().filename());
    // A wire-profile catenary may read `file: heights.csv` (docs/model-format.md).
    std::ofstream(root_ / "models" / "heights.csv") << "x,height\n0,0\n30,-0.06\n60,0\n";
    std::atexit([] { std::error_code e; std::filesystem::remove_all(get().root_, e); });
  }
  std::filesystem::path root_;
};

}  // namespace inerta::fuzz
