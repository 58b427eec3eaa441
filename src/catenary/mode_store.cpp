// Decompositions on disk (catenary/mode_store.hpp).
#include "inerta/catenary/mode_store.hpp"

#include <fmt/format.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cerrno>
#include <new>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#include "inerta/catenary/fe_modal.hpp"
#include "inerta/error.hpp"
#include "inerta/numerics/phase_times.hpp"

namespace inerta::catenary {

namespace {

// '4': the modes of the eigensolver of issue 39 (slices of 18, mirror-symmetric windows split), which
// differ from those of earlier files by round-off; a file of another version is another key.
constexpr char kMagic[8] = {'I', 'N', 'M', 'O', 'D', 'E', 'S', '4'};

struct Header {
  char magic[8];
  std::uint64_t key;
  std::int64_t n, m;
  double cutoff;
  std::uint64_t checksum;
};

// FNV-1a over 64-bit words (stable across processes; not cryptographic: it detects other data, not
// an adversary).
struct Hash {
  std::uint64_t h = 14695981039346656037ull;
  void word(std::uint64_t w) {
    for (int b = 0; b < 8; ++b) h = (h ^ ((w >> (8 * b)) & 0xffu)) * 1099511628211ull;
  }
  void words(const void* p, std::size_t bytes) {  // whole words; a faster mix for the bulk data
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i + 8 <= bytes; i += 8) {
      std::uint64_t w;
      std::memcpy(&w, c + i, 8);
      h = (h ^ w) * 1099511628211ull;
      h ^= h >> 29;
    }
    for (std::size_t i = bytes - bytes % 8; i < bytes; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  void matrix(const Eigen::SparseMatrix<double>& A) {
    word(static_cast<std::uint64_t>(A.rows())), word(static_cast<std::uint64_t>(A.cols()));
    word(static_cast<std::uint64_t>(A.nonZeros()));
    words(A.outerIndexPtr(), sizeof(int) * static_cast<std::size_t>(A.outerSize() + 1));
    words(A.innerIndexPtr(), sizeof(int) * static_cast<std::size_t>(A.nonZeros()));
    words(A.valuePtr(), sizeof(double) * static_cast<std::size_t>(A.nonZeros()));
  }
};

// The data's checksum: Fletcher-like sums over the 64-bit words in eight lanes, a running sum and the
// sum of the running sums (a changed word changes the first, moved words the second); additions only,
// so it vectorises and runs at memory speed. Fed in pieces (a piece of whole 8-word blocks, the last
// piece any length), so that a file is checked while its pieces are still in the cache; folded into
// one word with the FNV hash.
class Checksum {
 public:
  void add(const double* p, std::size_t words) {
    std::size_t i = 0;
    for (; i + 8 <= words; i += 8)
      for (int l = 0; l < 8; ++l) {
        std::uint64_t w;
        std::memcpy(&w, p + i + static_cast<std::size_t>(l), 8);
        a_[l] += w, b_[l] += a_[l];
      }
    for (; i < words; ++i) {
      std::uint64_t w;
      std::memcpy(&w, p + i, 8);
      a_[0] += w, b_[0] += a_[0];
    }
  }
  std::uint64_t value() const {
    Hash h;
    for (int l = 0; l < 8; ++l) h.word(a_[l]), h.word(b_[l]);
    return h.h;
  }

 private:
  std::uint64_t a_[8] = {}, b_[8] = {};
};

std::uint64_t checksum(const double* omega2, std::size_t m, const double* phi, std::size_t count) {
  Checksum c;
  c.add(omega2, m);
  c.add(phi, count);
  return c.value();
}

// `bytes` from `offset` with pread (interrupted or short reads continued); false on an error or
// an early end of file.
bool read_fully(int fd, void* buffer, std::size_t bytes, std::size_t offset) {
  auto* p = static_cast<char*>(buffer);
  while (bytes > 0) {
    const ssize_t r = ::pread(fd, p, std::min<std::size_t>(bytes, std::size_t{1} << 30), static_cast<off_t>(offset));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r, bytes -= static_cast<std::size_t>(r), offset += static_cast<std::size_t>(r);
  }
  return true;
}

// The SIGBUS guard of mapped mode files: a slot per mapping ([begin, end), its damage flag). A bus
// error inside a slot's range (the file was cut short under the mapping) maps anonymous zero pages
// over the rest of that mapping, marks it damaged and returns, so the access completes; any other
// SIGBUS goes to the handler installed before (or kills the process as by default).
struct Guard {
  std::atomic<std::uintptr_t> begin{0}, end{0};
  std::atomic<int> damaged{0};
  std::atomic<bool> taken{false};
};
Guard g_guards[ModeStore::kGuards];
struct sigaction g_previous {};
std::uintptr_t g_page = 4096;

extern "C" void on_bus_error(int sig, siginfo_t* info, void* context) {
  if (info && info->si_code == BUS_ADRERR) {
    const auto a = reinterpret_cast<std::uintptr_t>(info->si_addr);
    for (Guard& g : g_guards) {
      const std::uintptr_t b = g.begin.load(), e = g.end.load();
      if (a < b || a >= e) continue;
      const std::uintptr_t page = a & ~(g_page - 1);
      if (::mmap(reinterpret_cast<void*>(page), e - page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) !=
          MAP_FAILED) {
        g.damaged.store(1);
        return;
      }
      break;
    }
  }
  if (g_previous.sa_flags & SA_SIGINFO) {
    if (g_previous.sa_sigaction) g_previous.sa_sigaction(sig, info, context);
    return;
  }
  if (g_previous.sa_handler != SIG_DFL && g_previous.sa_handler != SIG_IGN) {
    g_previous.sa_handler(sig);
    return;
  }
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);  // delivered on return (a fault: the access repeats and ends the process)
}

Guard* take_guard() {
  static const bool installed = [] {
    g_page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    struct sigaction sa {};
    sa.sa_sigaction = on_bus_error;
    sa.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&sa.sa_mask);
    return ::sigaction(SIGBUS, &sa, &g_previous) == 0;
  }();
  if (!installed) return nullptr;
  for (Guard& g : g_guards) {
    bool free = false;
    if (g.taken.compare_exchange_strong(free, true)) return &g;
  }
  return nullptr;
}

// A file on a network filesystem is not mapped: another machine sharing the store (Dask workers)
// can remove it, and pages the kernel drops could then not be read again; it is read into memory.
bool local_filesystem(int fd) {
  struct statfs fs {};
  if (::fstatfs(fd, &fs) != 0) return false;
  switch (static_cast<unsigned long>(fs.f_type)) {
    case 0x6969:      // NFS
    case 0x517B:      // SMB
    case 0xFF534D42:  // CIFS
    case 0xFE534D42:  // SMB2
    case 0x65735546:  // FUSE (sshfs, …)
    case 0x00C36400:  // Ceph
    case 0x0BD00BD0:  // Lustre
    case 0x47504653:  // GPFS
    case 0x01021997:  // 9P
    case 0x5346414F:  // AFS
    case 0x73757245:  // Coda
      return false;
    default:
      return true;
  }
}

// A mapping of a mode file under its guard; unmapped (and the guard freed) with the last owner.
struct Mapping {
  void* base = nullptr;
  std::size_t length = 0;
  Guard* guard = nullptr;
  ~Mapping() {
    guard->begin.store(0), guard->end.store(0);
    ::munmap(base, length);
    guard->damaged.store(0);
    guard->taken.store(false);
  }
};

}  // namespace

ModeStore::ModeStore(std::filesystem::path directory, std::uintmax_t max_bytes)
    : dir_(std::move(directory)), max_bytes_(max_bytes) {}

std::optional<ModeStore> ModeStore::from_environment() {
  if (const char* v = std::getenv("INERTA_CACHE")) {
    const std::string s = v;
    if (s.empty() || s == "off" || s == "0" || s == "no") return std::nullopt;
    // A relative folder (or "~/x", which no shell expanded) would create folders wherever a run starts.
    if (!std::filesystem::path(s).is_absolute())
      throw ModelError(fmt::format("INERTA_CACHE='{}': expected an absolute folder for the mode store (such as {}/"
                                   "inerta-modes), or off (also 0, no or empty) for none",
                                   s, std::getenv("HOME") ? std::getenv("HOME") : "/tmp"));
    return ModeStore(s);
  }
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return ModeStore(std::filesystem::path(x) / "inerta" / "modes");
  if (const char* home = std::getenv("HOME"); home && *home)
    return ModeStore(std::filesystem::path(home) / ".cache" / "inerta" / "modes");
  return std::nullopt;
}

std::uint64_t ModeStore::key(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                             double cutoff_hz) {
  Hash h;
  h.words(kMagic, sizeof kMagic);
  std::uint64_t c;
  std::memcpy(&c, &cutoff_hz, 8);
  h.word(c);
  h.matrix(K);
  h.matrix(M);
  return h.h;
}

std::filesystem::path ModeStore::file(std::uint64_t key) const { return dir_ / fmt::format("modes-{:016x}.bin", key); }

std::optional<StoredModes> ModeStore::load(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                           double cutoff_hz) const {
  const numerics::PhaseTimer timer("mode store: read and verify");
  const std::uint64_t k = key(K, M, cutoff_hz);
  // Never blocks: O_NONBLOCK so that a FIFO (or any special file) named like a mode file does not
  // hang open(), then only a regular file is read.
  const int fd = ::open(file(k).c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::nullopt;
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } closer{fd};
  struct stat st{};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size < static_cast<off_t>(sizeof(Header))) return std::nullopt;
  Header hd{};
  if (!read_fully(fd, &hd, sizeof hd, 0)) return std::nullopt;
  if (std::memcmp(hd.magic, kMagic, sizeof kMagic) != 0 || hd.key != k || hd.n != K.rows() || hd.m < 0 ||
      hd.m > hd.n || std::memcmp(&hd.cutoff, &cutoff_hz, 8) != 0)
    return std::nullopt;
  const std::size_t m = static_cast<std::size_t>(hd.m), count = static_cast<std::size_t>(hd.n) * m;
  const std::size_t bytes = static_cast<std::size_t>(st.st_size);
  if (bytes != sizeof hd + sizeof(double) * (m + count)) return std::nullopt;  // cut short, or extra data
  StoredModes out;
  out.n = hd.n, out.m = hd.m;
  out.file = file(k);
  // Mapped under a guard (above), checked where it lies; a file cut short meanwhile fails the check.
  if (Guard* g = local_filesystem(fd) ? take_guard() : nullptr) {
    void* base = ::mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (base == MAP_FAILED) {
      g->taken.store(false);
    } else {
      auto map = std::make_shared<Mapping>();
      map->base = base, map->length = bytes, map->guard = g;
      const auto b = reinterpret_cast<std::uintptr_t>(base);
      g->end.store(b + (bytes + g_page - 1) / g_page * g_page);
      g->begin.store(b);
      const double* data = reinterpret_cast<const double*>(static_cast<const char*>(base) + sizeof hd);
      Checksum sum;  // fed as written (the lanes restart at Φ)
      sum.add(data, m);
      sum.add(data + m, count);
      if (sum.value() != hd.checksum || g->damaged.load()) return std::nullopt;
      (void)::futimens(fd, nullptr);  // used now (see below)
      out.omega2 = Eigen::Map<const Eigen::VectorXd>(data, hd.m);
      out.phi = data + m;
      out.damaged = &g->damaged;
      out.file_device = static_cast<std::uint64_t>(st.st_dev), out.file_inode = static_cast<std::uint64_t>(st.st_ino);
      out.file_bytes = bytes;
      out.owner = std::move(map);
      return out;
    }
  }
  // Every guard taken: read into memory of the run's own. Transparent huge pages where the kernel
  // offers them (madvise): the copy then faults once per 2 MB
  // instead of once per 4 kB page, which on a virtual machine cost more than the copy itself.
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  const std::size_t words = m + count, alloc = (sizeof(double) * words + kHuge - 1) / kHuge * kHuge;
  std::shared_ptr<double[]> data(static_cast<double*>(std::aligned_alloc(kHuge, alloc)), [](double* p) { std::free(p); });
  if (!data) return std::nullopt;
#ifdef MADV_HUGEPAGE
  (void)::madvise(data.get(), alloc, MADV_HUGEPAGE);
#endif
  // Exactly the size fstat gave: a file that shrank meanwhile fails here, one that grew is not read
  // whole. Read and checked piece by piece (each piece checked while it is in the cache).
  double* omega2 = data.get();
  Checksum sum;
  if (!read_fully(fd, omega2, sizeof(double) * m, sizeof hd)) return std::nullopt;
  sum.add(omega2, m);
  constexpr std::size_t kPiece = std::size_t{1} << 17;  // words (1 MB), a multiple of the 8 lanes
  for (std::size_t done = 0; done < count;) {
    const std::size_t w = std::min(kPiece, count - done);
    if (!read_fully(fd, omega2 + m + done, sizeof(double) * w, sizeof hd + sizeof(double) * (m + done))) return std::nullopt;
    sum.add(omega2 + m + done, w);
    done += w;
  }
  if (sum.value() != hd.checksum) return std::nullopt;
  // Used now: the directory's size limit removes the least recently used files first (save), so a
  // file that every run reads is not the first to go (best effort: a read-only file keeps its time).
  (void)::futimens(fd, nullptr);
  out.omega2 = Eigen::Map<const Eigen::VectorXd>(omega2, hd.m);
  out.phi = omega2 + m;
  out.owner = std::move(data);
  return out;
}

bool ModeStore::save(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double cutoff_hz,
                     const Modes& modes) const noexcept {
  try {
    return save(key(K, M, cutoff_hz), cutoff_hz, modes.omega2, modes.phi.data(), modes.phi.rows(), modes.phi.cols());
  } catch (...) {
    return false;
  }
}

bool ModeStore::save(std::uint64_t key, double cutoff_hz, const Eigen::VectorXd& omega2, const double* phi,
                     Eigen::Index n, Eigen::Index m) const noexcept {
  try {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return false;
    Header hd{};
    std::memcpy(hd.magic, kMagic, sizeof kMagic);
    hd.key = key;
    hd.n = n, hd.m = m;
    hd.cutoff = cutoff_hz;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(m);
    hd.checksum = checksum(omega2.data(), static_cast<std::size_t>(omega2.size()), phi, count);
    static std::atomic<unsigned> counter{0};
    const fs::path target = file(hd.key);
    const fs::path tmp = dir_ / fmt::format(".{}.{}.{}.tmp", target.filename().string(), ::getpid(), counter++);
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(&hd), sizeof hd);
      out.write(reinterpret_cast<const char*>(omega2.data()),
                static_cast<std::streamsize>(sizeof(double) * static_cast<std::size_t>(omega2.size())));
      out.write(reinterpret_cast<const char*>(phi), static_cast<std::streamsize>(sizeof(double) * count));
      out.close();
      if (!out) {
        fs::remove(tmp, ec);
        return false;
      }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
      fs::remove(tmp, ec);
      return false;
    }
    // Keep the directory under max_bytes: the least recently used files go first (load touches a
    // file it reads; never the one just written).
    struct F {
      fs::path p;
      fs::file_time_type t;
      std::uintmax_t size;
    };
    std::vector<F> files;
    std::uintmax_t total = 0;
    for (const auto& e : fs::directory_iterator(dir_, ec)) {
      const std::string name = e.path().filename().string();
      // A temporary file a process left when it ended mid-write (killed, or a Python process that
      // exits while its line's writes run): removed after an hour (a live write takes seconds).
      if (name.rfind(".modes-", 0) == 0 && e.path().extension() == ".tmp") {
        const auto t = e.last_write_time(ec);
        if (!ec && fs::file_time_type::clock::now() - t > std::chrono::hours(1)) fs::remove(e.path(), ec);
        continue;
      }
      if (name.rfind("modes-", 0) != 0 || e.path().extension() != ".bin") continue;
      const auto size = e.file_size(ec);
      if (ec) continue;
      files.push_back({e.path(), e.last_write_time(ec), size});
      total += size;
    }
    std::sort(files.begin(), files.end(), [](const F& a, const F& b) { return a.t < b.t; });
    for (const F& f : files) {
      if (total <= max_bytes_) break;
      if (f.p == target) continue;
      if (fs::remove(f.p, ec)) total -= f.size;
    }
    return true;
  } catch (...) {
    return false;
  }
}

}  // namespace inerta::catenary
