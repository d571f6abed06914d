#include "common/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

#include "common/input_error.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

// The pid that the lock file records, or "" when it holds none (it is being written).
std::string recorded_lock_pid(const fs::path& lock_file) {
  std::ifstream in(lock_file);
  long pid = 0;
  return in >> pid && pid > 0 ? std::to_string(pid) : std::string();
}

}  // namespace

FolderLock::FolderLock(const fs::path& folder, const std::string& writer) : folder_(folder) {
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
    throw InputError(folder.string(), "exists and is not a folder");
  }
  created_folder_ = fs::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "cannot create the folder: " + error.message());
  const fs::path lock_file = folder / kFolderLockFile;
  // A holder removes the lock file as it releases it: a lock taken on a file that is no
  // longer the one named in the folder locks nothing, and is taken again.
  for (;;) {
    descriptor_ = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor_ < 0) {
      const std::string reason = std::strerror(errno);
      if (created_folder_) fs::remove(folder, error);
      throw InputError(folder.string(), "cannot create its lock file " + std::string(kFolderLockFile) + ": " + reason);
    }
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
      const int lock_errno = errno;
      ::close(descriptor_);
      descriptor_ = -1;
      if (lock_errno == EINTR) continue;
      if (lock_errno != EWOULDBLOCK) {
        throw InputError(folder.string(), "cannot lock its lock file " + std::string(kFolderLockFile) + ": " +
                                              std::strerror(lock_errno));
      }
      const std::string pid = recorded_lock_pid(lock_file);
      throw InputError(folder.string(), "is being written by another " + writer +
                                            (pid.empty() ? std::string() : " (pid " + pid + ")") +
                                            "; wait until it ends, or choose another folder");
    }
    struct stat held {};
    struct stat named {};
    if (::fstat(descriptor_, &held) == 0 && ::stat(lock_file.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      break;
    }
    ::close(descriptor_);
    descriptor_ = -1;
  }
  // The pid only makes another writer's refusal clearer: the lock holds without it.
  const std::string pid = std::to_string(::getpid()) + "\n";
  const bool recorded = ::ftruncate(descriptor_, 0) == 0 && ::pwrite(descriptor_, pid.data(), pid.size(), 0) > 0;
  static_cast<void>(recorded);
}

FolderLock::FolderLock(FolderLock&& other) noexcept
    : folder_(std::move(other.folder_)),
      descriptor_(std::exchange(other.descriptor_, -1)),
      created_folder_(other.created_folder_) {}

FolderLock::~FolderLock() {
  if (descriptor_ < 0) return;
  std::error_code error;
  // Removed while still held: no other writer can lock this file after it is gone.
  fs::remove(folder_ / kFolderLockFile, error);
  ::close(descriptor_);
  if (created_folder_) fs::remove(folder_, error);  // only when empty
}

}  // namespace crux
