#include "common/folder_lock.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <optional>

#include "common/input_error.hpp"
#include "support/held_folder_lock.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

fs::path lock_scratch(const std::string& name) {
  const fs::path folder = testing::test_folder() / "folder-lock" / name;
  fs::remove_all(folder);
  return folder;
}

// flock locks belong to an open file: a second lock in the same process conflicts as
// another process's would.
TEST(FolderLock, ASecondWriterIsRefusedWithTheHoldersPidUntilTheFirstEnds) {
  const fs::path folder = lock_scratch("busy");
  std::optional<FolderLock> first;
  first.emplace(folder, "crux sweep");
  try {
    FolderLock second(folder, "crux sweep");
    FAIL() << "two writers locked one folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), folder.string());
    EXPECT_EQ(e.problem(), "is being written by another crux sweep (pid " + std::to_string(::getpid()) +
                               "); wait until it ends, or choose another folder");
  }
  first.reset();
  EXPECT_FALSE(fs::exists(folder / kFolderLockFile)) << "a released lock leaves no file";
  FolderLock again(folder, "crux sweep");
}

TEST(FolderLock, ALockFileLeftByAKilledWriterIsTakenAgain) {
  const fs::path folder = lock_scratch("killed");
  testing::HeldFolderLock killed(folder);
  EXPECT_THROW(FolderLock(folder, "crux sweep"), InputError);
  killed.release();
  ASSERT_TRUE(fs::exists(folder / kFolderLockFile));
  const FolderLock lock(folder, "crux sweep");
  std::ifstream in(folder / kFolderLockFile);
  long pid = 0;
  in >> pid;
  EXPECT_EQ(pid, ::getpid()) << "the new writer's pid replaces the old one";
}

TEST(FolderLock, AFolderItCreatedGoesWithItWhenLeftEmptyAndOtherFoldersStay) {
  const fs::path created = lock_scratch("created");
  { const FolderLock lock(created, "crux sweep"); }
  EXPECT_FALSE(fs::exists(created)) << "a refused command leaves no folder behind";
  {
    const FolderLock lock(created, "crux sweep");
    std::ofstream(created / "result.csv") << "a\n";
  }
  EXPECT_TRUE(fs::exists(created / "result.csv"));
  const fs::path existing = lock_scratch("existing");
  fs::create_directories(existing);
  { const FolderLock lock(existing, "crux sweep"); }
  EXPECT_TRUE(fs::is_directory(existing));
  EXPECT_TRUE(fs::is_empty(existing));
}

TEST(FolderLock, AFileInPlaceOfTheFolderIsRefused) {
  const fs::path file = lock_scratch("file");
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "x";
  try {
    FolderLock lock(file, "crux sweep");
    FAIL() << "a file was taken for a folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.what(), file.string() + ": exists and is not a folder");
  }
}

}  // namespace
}  // namespace crux
