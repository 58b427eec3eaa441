#include "inerta/io/files.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "inerta/error.hpp"

namespace inerta::io {

namespace fs = std::filesystem;

namespace {

// Temporary files still open, for the signal handler (async-signal-safe: atomics and unlink only).
std::array<std::atomic<const char*>, 64> partial{};

void register_partial(const char* p) {
  for (auto& slot : partial) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, p)) return;
  }
}
void unregister_partial(const char* p) {
  for (auto& slot : partial) {
    const char* expected = p;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

extern "C" void remove_partial_and_die(int sig) {
  for (auto& slot : partial)
    if (const char* p = slot.load()) ::unlink(p);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

std::string reason() { return std::strerror(errno); }

// The inputs read since protect_inputs(): no output may replace them (identified by device and inode,
// so another name of the same file, a link or a relative path, is the same input).
struct Input {
  dev_t dev;
  ino_t ino;
  std::string path;
};
std::mutex inputs_mutex;
bool protecting = false;
std::vector<Input> inputs_read;

void record_input(const struct stat& st, const std::string& path) {
  std::lock_guard lock(inputs_mutex);
  if (!protecting) return;
  for (const Input& i : inputs_read)
    if (i.dev == st.st_dev && i.ino == st.st_ino) return;
  inputs_read.push_back({st.st_dev, st.st_ino, path});
}

// Throws if `out` exists and is an input read so far.
void refuse_input(const std::string& out) {
  struct stat st {};
  if (::stat(out.c_str(), &st) != 0) return;
  std::lock_guard lock(inputs_mutex);
  for (const Input& i : inputs_read)
    if (i.dev == st.st_dev && i.ino == st.st_ino)
      throw std::runtime_error(fmt::format("'{}' is the input file '{}': refusing to overwrite it; give another output name", out, i.path));
}

}  // namespace

InputObserver& input_observer() {
  static InputObserver observer;
  return observer;
}

void observe_inputs(InputObserver observer) {
  std::lock_guard lock(inputs_mutex);
  input_observer() = std::move(observer);
}

void protect_inputs() {
  std::lock_guard lock(inputs_mutex);
  protecting = true;
}

std::string read_input_text(const std::string& path, const std::string& what) {
  // Opened without blocking (a FIFO named as an input must not hang open()), then checked on the
  // descriptor itself: what is read is what was checked.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw ModelError(fmt::format("{}: cannot open the {} ({})", path, what, reason()));
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw ModelError(fmt::format("{}: cannot open the {} ({})", path, what, reason()));
  if (!S_ISREG(st.st_mode))
    throw ModelError(fmt::format("{}: not a regular file ({}); expected the {}", path,
                                 S_ISDIR(st.st_mode) ? "a folder" : "a device, FIFO or socket", what));
  if (static_cast<std::size_t>(st.st_size) > max_input_bytes)
    throw ModelError(fmt::format("{}: {} bytes, larger than the 256 MiB accepted for the {}", path, st.st_size, what));
  record_input(st, path);
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t r = ::read(fd, buffer, sizeof buffer);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw ModelError(fmt::format("{}: cannot read the {} ({})", path, what, reason()));
    if (r == 0) break;
    text.append(buffer, static_cast<std::size_t>(r));
    if (text.size() > max_input_bytes)  // grew while being read
      throw ModelError(fmt::format("{}: larger than the 256 MiB accepted for the {}", path, what));
  }
  // Text files hold no NUL byte: a binary file (an image, a compiled program) is named as such, not
  // parsed into a YAML error quoting its bytes.
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw ModelError(fmt::format("{}: a binary file (a NUL byte at offset {}), not the {} (YAML text)", path, nul, what));
  InputObserver observer;
  {
    std::lock_guard lock(inputs_mutex);
    observer = input_observer();
  }
  if (observer) observer(path, what, text);
  return text;
}

void check_output_path(const std::string& out, const std::vector<std::string>& inputs) {
  if (out.empty()) return;
  std::error_code ec;
  const fs::path p(out);
  if (fs::is_directory(p, ec)) throw std::runtime_error(fmt::format("'{}' is a folder; give the name of the file to write", out));
  for (const auto& in : inputs)
    if (!in.empty() && fs::exists(p, ec) && fs::equivalent(p, fs::path(in), ec))
      throw std::runtime_error(fmt::format("'{}' is the input file '{}': refusing to overwrite it; give another output name", out, in));
  refuse_input(out);
  if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) return;  // a device or FIFO: written directly
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(fmt::format("cannot write '{}': the folder '{}' does not exist", out, dir.string()));
  if (::access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error(fmt::format("cannot write '{}': the folder '{}' is not writable", out, dir.string()));
}

OutputFile::OutputFile(const std::string& path, const std::vector<std::string>& inputs) : path_(path) {
  if (path.empty()) return;
  check_output_path(path, inputs);
  std::error_code ec;
  const fs::path p(path);
  if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) {  // /dev/null, /dev/full, a FIFO
    file_ = std::fopen(path.c_str(), "w");
    if (!file_) throw std::runtime_error(fmt::format("cannot write '{}': {}", path, reason()));
    return;
  }
  static std::atomic<unsigned> counter{0};
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  temp_ = (dir / fmt::format(".{}.partial-{}-{}", p.filename().string(), ::getpid(), counter++)).string();
  const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot write '{}': {}", path, reason()));
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    ::close(fd);
    ::unlink(temp_.c_str());
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, reason()));
  }
  register_partial(temp_.c_str());
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);
  if (!temp_.empty() && !committed_) {
    unregister_partial(temp_.c_str());
    ::unlink(temp_.c_str());
  }
}

void OutputFile::commit() {
  if (committed_) return;
  if (!file_) {  // standard output
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
      throw std::runtime_error(fmt::format("cannot write to standard output: {}", reason()));
    committed_ = true;
    return;
  }
  const bool bad = std::fflush(file_) != 0 || std::ferror(file_);
  const int err = errno;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (bad || close_failed) {
    errno = bad ? err : errno;
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path_, reason()));
  }
  if (!temp_.empty()) {
    refuse_input(path_);  // an input read after this output was opened (the temporary file is removed)
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
      throw std::runtime_error(fmt::format("cannot write '{}': {}", path_, reason()));
    unregister_partial(temp_.c_str());
  }
  committed_ = true;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void write_text_file(const std::string& path, const std::string& text) {
  OutputFile f(path);
  if (std::fwrite(text.data(), 1, text.size(), f.get()) != text.size())
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, reason()));
  f.commit();
}

const std::vector<std::string>& study_output_names() {
  static const std::vector<std::string> names{
      "results.csv",   "results.json",   "sigma.csv",  "sigma.png",  "frf.csv",        "frf.png",
      "contact.csv",   "contact.png",    "map.csv",    "map.png",    "j2_map.csv",     "j2_map.png",
      "centripetal.csv", "centripetal.png", "report.json", "structure.csv", "structure.json", "pareto.csv",
      "pareto.png",    "admittance.csv", "admittance.json", "recheck.csv", "refined.csv", "screened.csv", "acceptance_margins.csv", "acceptance.png",
      "checkpoint.pkl", "report.html"};
  return names;
}

void prepare_output_folder(const std::string& dir, const std::vector<std::string>& owned, bool force) {
  std::error_code ec;
  const fs::path d(dir);
  if (fs::exists(d, ec) && !fs::is_directory(d, ec))
    throw InvalidArgument(fmt::format("--out '{}' is a file; give a folder for the study's results", dir));
  fs::create_directories(d, ec);
  if (ec) throw InvalidArgument(fmt::format("cannot create the folder '{}': {}", dir, ec.message()));
  std::vector<std::string> present;
  for (const auto& e : fs::directory_iterator(d, ec)) present.push_back(e.path().filename().string());
  std::sort(present.begin(), present.end());
  if (!present.empty() && !force)
    throw InvalidArgument(fmt::format("--out '{}' is not empty ({} entries: {}{}); give a new or empty folder, or "
                                      "--force to replace the files the study writes there",
                                      dir, present.size(),
                                      fmt::join(present.begin(), present.begin() + std::min<std::ptrdiff_t>(4, std::ssize(present)), ", "),
                                      present.size() > 4 ? ", ..." : ""));
  if (force) {
    for (const auto& name : owned) refuse_input((d / name).string());  // none removed if one is an input
    for (const auto& name : owned)
      if (fs::is_regular_file(d / name, ec) && !fs::remove(d / name, ec))
        throw InvalidArgument(fmt::format("cannot remove '{}': {}", (d / name).string(), ec.message()));
  }
  if (::access(d.c_str(), W_OK) != 0)
    throw InvalidArgument(fmt::format("cannot write in the folder '{}': {}", dir, reason()));
}

void remove_partial_outputs_on_signal() {
  // SIGBUS too: a file the process maps that is cut short underneath still leaves no partial output
  // (a mode file's mapping has a guard of its own that stops the run cleanly: catenary/mode_store.hpp;
  // it passes every other SIGBUS on to this handler).
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGBUS}) std::signal(sig, remove_partial_and_die);
}

}  // namespace inerta::io
