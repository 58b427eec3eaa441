// Provenance of a run (report/provenance.hpp).
#include "inerta/report/provenance.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "inerta/io/files.hpp"

namespace inerta::report {

namespace {
std::mutex mutex;
std::vector<InputFile> inputs;
}  // namespace

std::string sha256_hex(const std::string& data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  if (EVP_Digest(data.data(), data.size(), digest, &n, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256: OpenSSL's EVP_Digest failed");
  std::string hex;
  hex.reserve(2 * n);
  for (unsigned int i = 0; i < n; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

void record_inputs() {
  io::observe_inputs([](const std::string& path, const std::string& what, const std::string& text) {
    const std::string hash = sha256_hex(text);
    std::lock_guard lock(mutex);
    for (const InputFile& f : inputs)
      if (f.path == path) return;
    inputs.push_back({path, what, hash, text.size()});
  });
}

std::vector<InputFile> recorded_inputs() {
  std::lock_guard lock(mutex);
  return inputs;
}

Provenance current_provenance(const std::vector<std::string>& argv) {
  Provenance p;
  p.build = build_info();
  p.argv = argv;
  std::error_code ec;
  p.cwd = std::filesystem::current_path(ec).string();
  const auto now = std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now());
  p.date = fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", now);
  p.inputs = recorded_inputs();
  return p;
}

std::string shell_quoted(const std::vector<std::string>& argv) {
  std::string out;
  for (const std::string& a : argv) {
    if (!out.empty()) out += ' ';
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                         "-_./=:,+@%") == std::string::npos;
    if (plain) {
      out += a;
      continue;
    }
    out += '\'';
    for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

}  // namespace inerta::report
