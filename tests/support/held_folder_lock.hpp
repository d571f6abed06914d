#pragma once
// Another writer's lock on a folder, taken by the test itself with flock on the lock
// file (common/folder_lock.hpp), so that a test meets a busy folder deterministically.

#include <filesystem>

namespace crux::testing {

class HeldFolderLock {
 public:
  // Creates `folder` if missing, then locks its lock file and writes this process's pid
  // into it; fails the test when the lock is already held.
  explicit HeldFolderLock(const std::filesystem::path& folder);
  ~HeldFolderLock() { release(); }
  HeldFolderLock(const HeldFolderLock&) = delete;
  HeldFolderLock& operator=(const HeldFolderLock&) = delete;
  // Releases the lock and leaves the lock file, as a writer killed by SIGKILL does.
  void release();

 private:
  int descriptor_ = -1;
};

}  // namespace crux::testing
