#pragma once
// An output folder that one crux process writes at a time: an advisory flock on a lock
// file inside it, held while the folder is written. The kernel releases it when the
// process ends in any way (SIGKILL too), so a killed writer leaves no stale lock; a lock
// file it leaves behind is unlocked and taken again by the next writer.

#include <filesystem>
#include <string>

namespace crux {

// The lock file's name inside the locked folder; it holds the writer's pid. Not an
// output: a folder that holds only it counts as empty.
inline constexpr const char* kFolderLockFile = ".crux.lock";

class FolderLock {
 public:
  // Creates `folder` if it is missing and locks it, never waiting: InputError naming the
  // folder when another process holds the lock ("is being written by another
  // <writer> (pid N)"), or when the folder or its lock file cannot be made.
  FolderLock(const std::filesystem::path& folder, const std::string& writer);
  // Removes the lock file, and the folder if this lock created it and it is still empty
  // (a refused command leaves no folder behind).
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&&) = delete;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::filesystem::path folder_;
  int descriptor_ = -1;
  bool created_folder_ = false;
};

}  // namespace crux
