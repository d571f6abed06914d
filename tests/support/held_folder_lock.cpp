#include "support/held_folder_lock.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <string>

#include "common/folder_lock.hpp"

namespace crux::testing {

HeldFolderLock::HeldFolderLock(const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  descriptor_ = ::open((folder / kFolderLockFile).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  EXPECT_GE(descriptor_, 0) << folder;
  EXPECT_EQ(::flock(descriptor_, LOCK_EX | LOCK_NB), 0) << "the folder's lock is already held: " << folder;
  const std::string pid = std::to_string(::getpid()) + "\n";
  EXPECT_EQ(::write(descriptor_, pid.data(), pid.size()), static_cast<ssize_t>(pid.size()));
}

void HeldFolderLock::release() {
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = -1;
}

}  // namespace crux::testing
