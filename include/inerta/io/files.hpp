#pragma once
// Input and output files (issue 15). Inputs: only regular files of a bounded size are read.
// Safe outputs: a file is written under a temporary name in its destination folder and
// renamed over the destination only when complete (commit), so an interrupted or failed run never
// leaves a file that looks complete; every write error is an error. A destination that exists and is
// not a regular file (a device such as /dev/null or /dev/full, a FIFO) is written directly, and its
// write errors are reported the same way.
#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace inerta::io {

/// From now on every file read by read_input_text is protected: check_output_path, OutputFile's commit
/// and prepare_output_folder refuse to replace it ("'out' is the input file 'in'"), whatever name the
/// output gives it (the CLI calls it first: every input a command reads — model, line, criteria, study,
/// CSV — is safe from every output it writes, derived names included).
void protect_inputs();

/// Throws std::runtime_error if `out` names the same file as one of `inputs` or as an input protected
/// by protect_inputs() ("refusing to overwrite it"), or is a directory, or its folder does not exist or is not writable. Empty `out`: nothing.
void check_output_path(const std::string& out, const std::vector<std::string>& inputs = {});

/// Largest input file read, bytes (models, catenaries, studies, CSV tables).
inline constexpr std::size_t max_input_bytes = 256u << 20;

/// Called with each input's path, its `what` and its whole text once read_input_text has read it (the
/// report layer hashes it: report/provenance.hpp). One observer; a new one replaces the last.
using InputObserver = std::function<void(const std::string& path, const std::string& what, const std::string& text)>;
void observe_inputs(InputObserver observer);

/// The whole text of the input file `path`: ModelError "path: cannot open the <what>" if it cannot be
/// opened, "path: not a regular file (...)" for a folder, a device such as /dev/zero or a FIFO, and
/// "path: larger than 256 MiB" above max_input_bytes.
std::string read_input_text(const std::string& path, const std::string& what);

class OutputFile {
 public:
  /// `path` empty: standard output. Otherwise check_output_path(path, inputs) and open the temporary file
  /// (std::runtime_error "cannot write 'path': reason" if it cannot be created).
  explicit OutputFile(const std::string& path, const std::vector<std::string>& inputs = {});
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Not committed: the temporary file is removed, the destination is untouched.
  ~OutputFile();
  std::FILE* get() const { return file_ ? file_ : stdout; }
  const std::string& path() const { return path_; }
  /// Flushes, checks for write errors and renames the temporary file over the destination
  /// (std::runtime_error "cannot write 'path': reason" on any failure; the destination is then untouched).
  void commit();

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

/// A CSV field (RFC 4180): `s` itself, or quoted with its quotes doubled if it holds a comma, a quote
/// or a line break (network expressions and layout names may hold commas in their values).
std::string csv_field(const std::string& s);

/// Writes `text` to `path` through an OutputFile (created or replaced when complete).
void write_text_file(const std::string& path, const std::string& text);

/// The files `inerta optimise` may write in its --out folder (results, figures' data and PNGs).
const std::vector<std::string>& study_output_names();

/// Prepares the output folder of a study: creates it, refuses (InvalidArgument naming a few of them) a
/// folder that already holds files unless `force`, and with `force` removes the files of `owned` in it
/// first (other files are kept). Then checks that it is writable.
void prepare_output_folder(const std::string& dir, const std::vector<std::string>& owned, bool force);

/// Installs SIGINT/SIGTERM/SIGHUP/SIGBUS handlers that remove the temporary files of the OutputFiles still
/// open, then end the process with the signal's default action (the CLI; not the Python module).
void remove_partial_outputs_on_signal();

}  // namespace inerta::io
