#include "common/input_file.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

// The InputError of reading `path`, or a failure if there is none.
InputError error_of(const std::string& path, std::string_view kind) {
  try {
    read_input_file(path, kind);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "read " << path << " without an error";
  return InputError("", "");
}

TEST(InputFile, ReturnsTheBytesUnchanged) {
  // A NUL, CR LF, a byte that is not UTF-8 and no final newline: read in binary.
  const std::string bytes = std::string("line 1\r\nnul:") + '\0' + "\xff\xfe end";
  const auto path = testing::write_temporary("input_file_bytes.bin", bytes);
  const std::string read = read_input_file(path.string(), "Q-table file");
  EXPECT_EQ(read.size(), bytes.size());
  EXPECT_EQ(read, bytes);
}

TEST(InputFile, AnEmptyFileIsAnEmptyString) {
  const auto path = testing::write_temporary("input_file_empty.txt", "");
  EXPECT_EQ(read_input_file(path.string(), "wall file"), "");
}

TEST(InputFile, ALinkReadsItsTarget) {
  const auto target = testing::write_temporary("input_file_target.txt", "through the link");
  const auto link = testing::temporary_path("input_file_link.txt");
  std::filesystem::create_symlink(target, link);
  EXPECT_EQ(read_input_file(link.string(), "wall file"), "through the link");
}

TEST(InputFile, ADirectoryIsAnErrorNamingThePathAndTheKindExpected) {
  const auto dir = testing::temporary_path("input_file_dir");
  std::filesystem::create_directories(dir);
  const InputError e = error_of(dir.string(), "wall file");
  EXPECT_EQ(e.source(), dir.string());
  EXPECT_EQ(e.problem(), "is a directory, not a wall file");
  EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory, not a wall file");
}

TEST(InputFile, AMissingFileIsAnErrorNamingThePath) {
  const auto path = testing::temporary_path("input_file_missing.json");
  const InputError e = error_of(path.string(), "config file");
  EXPECT_EQ(e.source(), path.string());
  EXPECT_EQ(e.problem(), "no such file");
  // Also under a folder that does not exist, and through a link to nowhere.
  EXPECT_EQ(error_of((path / "deeper.json").string(), "config file").problem(), "no such file");
  const auto dangling = testing::temporary_path("input_file_dangling");
  std::filesystem::create_symlink(path, dangling);
  EXPECT_EQ(error_of(dangling.string(), "config file").problem(), "no such file");
}

TEST(InputFile, AnUnreadableFileIsAnErrorNamingThePath) {
  if (geteuid() == 0) GTEST_SKIP() << "root reads any file";
  const auto path = testing::write_temporary("input_file_unreadable.txt", "secret");
  std::filesystem::permissions(path, std::filesystem::perms::none);
  const InputError e = error_of(path.string(), "URDF file");
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  EXPECT_EQ(e.source(), path.string());
  EXPECT_EQ(e.problem().rfind("cannot open the file: ", 0), 0u) << e.problem();
}

TEST(InputFile, AnEmptyNameIsAnErrorNamingTheKind) {
  const InputError e = error_of("", "wall file");
  EXPECT_EQ(e.source(), "wall file");
  EXPECT_EQ(e.problem(), "the file name is empty");
}

TEST(InputFile, ADeviceIsRefused) {
  const InputError e = error_of("/dev/null", "config file");
  EXPECT_EQ(e.source(), "/dev/null");
  EXPECT_EQ(e.problem(), "is not a regular file, so not a config file");
}

TEST(InputFile, AFifoIsRefusedWithoutWaitingForAWriter) {
  const auto fifo = testing::temporary_path("input_file_fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reading = std::async(std::launch::async, [&] { return error_of(fifo.string(), "wall file").problem(); });
  if (reading.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
    // Blocked on the FIFO: a writer releases it so that the test ends.
    const int writer = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (writer >= 0) ::close(writer);
    ADD_FAILURE() << "read_input_file waited on a FIFO";
  }
  EXPECT_EQ(reading.get(), "is not a regular file, so not a wall file");
}

TEST(InputFile, AFileLargerThanTheLimitIsRefusedBeforeReading) {
  // A sparse file: its size is on record without the bytes on disk.
  const auto path = testing::write_temporary("input_file_huge.bin", "");
  std::filesystem::resize_file(path, kMaxInputFileBytes + 1);
  const InputError e = error_of(path.string(), "Q-table file");
  std::filesystem::remove(path);
  EXPECT_EQ(e.source(), path.string());
  EXPECT_EQ(e.problem().rfind("is 1073741825 bytes", 0), 0u) << e.problem();
  EXPECT_NE(e.problem().find("at most 1073741824 bytes"), std::string::npos) << e.problem();
}

}  // namespace
}  // namespace crux
