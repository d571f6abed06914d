#include "common/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

namespace {

std::string system_error(const char* what) { return fmt::format("{}: {}", what, std::strerror(errno)); }

}  // namespace

std::string read_input_file(const std::string& path, std::string_view kind) {
  if (path.empty()) throw InputError(std::string(kind), "the file name is empty");
  // Non-blocking, so that a FIFO or a device is refused instead of waited on.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) throw InputError(path, "no such file");
    throw InputError(path, system_error("cannot open the file"));
  }
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw InputError(path, system_error("cannot read the file"));
  if (S_ISDIR(status.st_mode)) throw InputError(path, fmt::format("is a directory, not a {}", kind));
  if (!S_ISREG(status.st_mode)) throw InputError(path, fmt::format("is not a regular file, so not a {}", kind));
  if (status.st_size > static_cast<off_t>(kMaxInputFileBytes)) {
    throw InputError(
        path, fmt::format("is {} bytes; a {} may be at most {} bytes", status.st_size, kind, kMaxInputFileBytes));
  }
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path, system_error("cannot read the file"));
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > kMaxInputFileBytes) {
      throw InputError(path, fmt::format("grew beyond {} bytes while being read", kMaxInputFileBytes));
    }
  }
  return bytes;
}

}  // namespace crux
