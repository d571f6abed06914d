#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include "common/input_error.hpp"

namespace crux {

namespace {

// Temporaries being written, so that SIGINT and SIGTERM can remove them: fixed storage,
// since a signal handler may neither allocate nor lock.
constexpr std::size_t kTemporarySlots = 64;
constexpr std::size_t kTemporaryPathBytes = 4096;
// A slot is claimed, then filled, then published: the handler only reads published
// slots, so it never unlinks a half-copied path.
enum SlotState : int { kFree, kClaimed, kPublished };
struct TemporarySlot {
  std::atomic<int> state{kFree};
  char path[kTemporaryPathBytes]{};
};
std::array<TemporarySlot, kTemporarySlots> temporaries;

// The slot now holding `path`, or -1 when all are taken or the path is too long (the
// temporary is then only not removed on a signal).
int remember_temporary(const std::string& path) {
  if (path.size() >= kTemporaryPathBytes) return -1;
  for (std::size_t i = 0; i < kTemporarySlots; ++i) {
    int expected = kFree;
    if (!temporaries[i].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(temporaries[i].path, path.c_str(), path.size() + 1);
    temporaries[i].state.store(kPublished, std::memory_order_release);
    return static_cast<int>(i);
  }
  return -1;
}

void forget_temporary(int slot) {
  if (slot >= 0) temporaries[slot].state.store(kFree);
}

extern "C" void remove_temporaries_and_reraise(int signal) {
  for (TemporarySlot& slot : temporaries) {
    if (slot.state.load(std::memory_order_acquire) == kPublished) ::unlink(slot.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

[[noreturn]] void fail(const std::filesystem::path& path, int fd, const char* temporary, int slot) {
  const std::string reason = std::strerror(errno);
  if (fd >= 0) ::close(fd);
  ::unlink(temporary);
  forget_temporary(slot);
  throw InputError(path.string(), "cannot write: " + reason);
}

// False, with errno set, when a write fails.
bool write_all(int fd, std::string_view contents) {
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    written += static_cast<std::size_t>(n);
  }
  return true;
}

// Written as the shell's `>` does, without creating or truncating: no temporary, no
// rename, no fsync (a device or a pipe has nothing to flush to disk).
void write_to_stream(const std::filesystem::path& path, std::string_view contents) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw InputError(path.string(), std::string("cannot write: ") + std::strerror(errno));
  if (!write_all(fd, contents)) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    throw InputError(path.string(), "cannot write: " + reason);
  }
  if (::close(fd) != 0) throw InputError(path.string(), std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace

void remove_temporaries_on_signals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, remove_temporaries_and_reraise);
}

OutputNode output_node(const std::filesystem::path& path) {
  struct stat node {};
  // Followed through symbolic links: /dev/stdout is a link to /proc/self/fd/1.
  if (::stat(path.c_str(), &node) != 0 || S_ISREG(node.st_mode)) return {};
  if (S_ISCHR(node.st_mode) || S_ISFIFO(node.st_mode)) return {OutputTarget::kStream, {}};
  if (S_ISDIR(node.st_mode)) return {OutputTarget::kRefuse, "is a folder; name a file to write"};
  if (S_ISSOCK(node.st_mode)) return {OutputTarget::kRefuse, "is a socket; crux writes files, FIFOs and devices"};
  return {OutputTarget::kRefuse, "is a block device; crux does not write to disks"};
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  const OutputNode node = output_node(path);
  if (node.target == OutputTarget::kRefuse) throw InputError(path.string(), node.refusal);
  if (node.target == OutputTarget::kStream) {
    write_to_stream(path, contents);
    return;
  }
  // An unpredictable name created exclusively (O_EXCL, O_NOFOLLOW), so a planted file or
  // symbolic link is never written through. The name is remembered before the file
  // exists, so that a signal at any moment finds every temporary to remove.
  std::string temporary;
  int slot = -1;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    std::array<unsigned char, kTemporarySuffixDigits / 2> random{};
    if (::getrandom(random.data(), random.size(), 0) != static_cast<ssize_t>(random.size())) break;
    temporary = path.string() + ".tmp.";
    for (const unsigned char byte : random) {
      temporary += "0123456789abcdef"[byte >> 4];
      temporary += "0123456789abcdef"[byte & 15];
    }
    slot = remember_temporary(temporary);
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) {
      const int reason = errno;
      forget_temporary(slot);
      errno = reason;
      if (reason != EEXIST) break;
    }
  }
  if (fd < 0) throw InputError(path.string(), std::string("cannot write: ") + std::strerror(errno));
  if (::fchmod(fd, 0644) != 0) fail(path, fd, temporary.c_str(), slot);
  if (!write_all(fd, contents)) fail(path, fd, temporary.c_str(), slot);
  if (::fsync(fd) != 0) fail(path, fd, temporary.c_str(), slot);
  if (::close(fd) != 0) fail(path, -1, temporary.c_str(), slot);
  if (::rename(temporary.c_str(), path.c_str()) != 0) fail(path, -1, temporary.c_str(), slot);
  forget_temporary(slot);
}

void make_output_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory)) {
    throw InputError(directory.string(), "cannot create the output folder");
  }
}

}  // namespace crux
