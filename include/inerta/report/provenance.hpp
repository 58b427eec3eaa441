#pragma once
// Where a result came from (issue 53 "Traceable"): the program (version, the git commit embedded at
// build, whether the tree was modified), the command line, the working folder, the date, and every
// input file read (path and SHA-256 of the bytes read). A report states it; `inerta verify-report`
// re-runs the command from it.
#include <string>
#include <vector>

namespace inerta::report {

/// The program as built: cmake/git_version.cmake writes it at every build.
struct BuildInfo {
  std::string version;    ///< the project's version (CMakeLists.txt)
  std::string commit;     ///< the git commit of the source tree, "unknown" outside a git checkout
  bool modified = false;  ///< tracked files differed from the commit when it was built
};
const BuildInfo& build_info();

/// One input file as it was read (io::read_input_text).
struct InputFile {
  std::string path;    ///< as given (relative to the working folder, or absolute)
  std::string what;    ///< its role as the reader named it ("model file", "criteria file", …)
  std::string sha256;  ///< of the bytes read, lowercase hex
  std::size_t bytes = 0;
};

/// From now on every input read through io::read_input_text is recorded with its SHA-256 (the CLI
/// calls it first). A file read twice is recorded once (the first read).
void record_inputs();
/// The inputs recorded so far, in the order first read.
std::vector<InputFile> recorded_inputs();

/// SHA-256 of `data` as lowercase hex (OpenSSL).
std::string sha256_hex(const std::string& data);

struct Provenance {
  BuildInfo build;
  std::vector<std::string> argv;  ///< the exact command line, argv[0] included
  std::string cwd;                ///< the working folder it ran in
  std::string date;               ///< UTC, ISO 8601 ("2026-12-07T12:34:56Z")
  std::vector<InputFile> inputs;
  /// Solver and its settings, overrides, …: (name, value) as the command states them.
  std::vector<std::pair<std::string, std::string>> settings;
};

/// The provenance of this process now: build_info(), argv, the working folder, the date and
/// recorded_inputs(); settings empty (the command adds them).
Provenance current_provenance(const std::vector<std::string>& argv);

/// The command line as one shell-quoted string ("inerta sweep models/hsx.yaml --speeds '200:50:300'").
std::string shell_quoted(const std::vector<std::string>& argv);

}  // namespace inerta::report
