#pragma once
// Decompositions of the finite-element line kept on disk between processes (docs/catenary-fe.md
// "Mode store"): a window's modes depend only on its matrices (K₀, M) and the cut-off, so a second
// process with the same line reads them instead of solving the eigenproblem again (≈ 1 s a shape).
//
// A file `modes-<key>.bin` per decomposition, the key a 64-bit hash of K₀, M (structure and values,
// bit for bit) and the cut-off; the header repeats the key, sizes and cut-off and a checksum of the
// data, so a file that does not match (another line, a truncated or damaged file) is ignored and the
// modes are computed. Files are written under a temporary name and renamed (processes sharing the
// directory never read a partial file). The loaded modes are the computed ones bit for bit, so
// results do not depend on whether the store was used. A file is mapped, not copied (a run reads the
// page cache's pages: no zeroing or copying of 40 MB a window), under a SIGBUS guard: a file cut short
// while a run maps it cannot kill the process — the pages gone read as zeros, the mapping is marked
// damaged (`StoredModes::damaged`) and the modal solve stops with an error naming the file at its
// next step, so no result is computed from them. Beyond kGuards mappings at once, or on a network
// filesystem (NFS, SMB, FUSE, …: another machine may remove the file), a file is read into memory of
// the run's own. Only a regular file is read, opened without blocking (a FIFO named
// like a mode file is ignored, never waited on).
#include <Eigen/Sparse>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

namespace inerta::numerics {
struct Modes;
}  // namespace inerta::numerics

namespace inerta::catenary {

using numerics::Modes;

/// Modes read from the store: ω² and Φ (n × m, row-major) in a mapping or buffer kept alive by
/// `owner`; `damaged` (a mapping's) becomes non-zero once the file under it was cut short.
struct StoredModes {
  Eigen::VectorXd omega2;
  std::shared_ptr<const void> owner;
  const double* phi = nullptr;
  Eigen::Index n = 0, m = 0;
  const std::atomic<int>* damaged = nullptr;
  std::filesystem::path file;
  std::uint64_t file_device = 0, file_inode = 0, file_bytes = 0;  ///< of a mapped file, as mapped
};

class ModeStore {
 public:
  static constexpr int kGuards = 4096;  ///< mode files mapped at once in a process (then read into memory)
  explicit ModeStore(std::filesystem::path directory, std::uintmax_t max_bytes = std::uintmax_t{4} << 30);
  /// From the environment: INERTA_CACHE=off, 0, no or empty → none; INERTA_CACHE=DIR (absolute;
  /// a relative one, or "~/x", is a ModelError) → DIR; unset → $XDG_CACHE_HOME/inerta/modes, else
  /// $HOME/.cache/inerta/modes; none if neither is set.
  static std::optional<ModeStore> from_environment();
  const std::filesystem::path& directory() const { return dir_; }

  static std::uint64_t key(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                           double cutoff_hz);
  std::filesystem::path file(std::uint64_t key) const;
  /// The stored modes of (K, M, cutoff), or nothing (absent, or not matching).
  std::optional<StoredModes> load(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                            double cutoff_hz) const;
  /// Stores them; true if written. A failure (read-only or full disk) only loses the cache. Beyond
  /// max_bytes in all, the least recently written files are removed.
  bool save(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double cutoff_hz,
            const Modes& modes) const noexcept;
  /// The same with the key made before (`key(K, M, cutoff_hz)`): ω² (m) and Φ (n × m, row-major).
  bool save(std::uint64_t key, double cutoff_hz, const Eigen::VectorXd& omega2, const double* phi, Eigen::Index n,
            Eigen::Index m) const noexcept;

 private:
  std::filesystem::path dir_;
  std::uintmax_t max_bytes_;
};

}  // namespace inerta::catenary
