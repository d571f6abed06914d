#include "common/atomic_file.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "support/fifo_reader.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  const auto dir = testing::test_folder() / "atomic";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "result.csv";
  write_file_atomically(path, "a,b\n1,2\n");
  write_file_atomically(path, "a,b\n3,4\n");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "a,b\n3,4\n");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, MissingDirectoryIsAnInputErrorNamingTheFile) {
  try {
    write_file_atomically("/nonexistent-crux-dir/out.csv", "x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-crux-dir/out.csv"), std::string::npos);
  }
}

// The temporary is created exclusively under an unpredictable name: files or links
// planted at the names of earlier versions (<name>.tmp.<pid>) are never written through.
TEST(AtomicFile, APlantedLinkAtAPredictableTemporaryNameIsNotFollowed) {
  const auto dir = testing::test_folder() / "atomic-link";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto victim = dir / "victim.txt";
  std::ofstream(victim) << "untouched";
  const auto path = dir / "w.json";
  std::filesystem::create_symlink(victim, dir / ("w.json.tmp." + std::to_string(::getpid())));
  write_file_atomically(path, "{}");
  std::ifstream in(victim);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "untouched");
  EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::symlink_status(path)));
}

std::filesystem::path node_scratch(const std::string& name) {
  const auto dir = testing::test_folder() / "atomic-nodes";
  std::filesystem::create_directories(dir);
  std::filesystem::remove_all(dir / name);
  return dir / name;
}

struct stat node_of(const std::filesystem::path& path) {
  struct stat node {};
  ::stat(path.c_str(), &node);
  return node;
}

// A FIFO is written through as the shell's `>` would; a rename would have replaced it
// with a regular file.
TEST(AtomicFile, AFifoIsWrittenThroughAndStaysAFifo) {
  const auto fifo = node_scratch("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  EXPECT_EQ(output_node(fifo).target, OutputTarget::kStream);
  testing::FifoReader reader(fifo);
  ASSERT_TRUE(reader.opened());
  write_file_atomically(fifo, "a,b\n1,2\n");
  EXPECT_EQ(reader.text(), "a,b\n1,2\n");
  EXPECT_TRUE(S_ISFIFO(node_of(fifo).st_mode));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(fifo.parent_path()), {}), 1) << "no temporary left";
}

// On a copy of /dev/null's node (1, 3) that the test makes in its own folder, never on
// the machine's: only root may, and only where the folder is not mounted nodev.
TEST(AtomicFile, ACharacterDeviceIsWrittenThroughAndStaysTheSameDevice) {
  if (::geteuid() != 0) GTEST_SKIP() << "skipped the character device case: making a device node needs root";
  const auto device = node_scratch("null");
  if (::mknod(device.c_str(), S_IFCHR | 0600, ::makedev(1, 3)) != 0) {
    GTEST_SKIP() << "skipped the character device case: mknod failed: " << std::strerror(errno);
  }
  const int probe = ::open(device.c_str(), O_WRONLY);
  if (probe < 0) {
    GTEST_SKIP() << "skipped the character device case: " << device.parent_path()
                 << " does not allow devices (mounted nodev?): " << std::strerror(errno);
  }
  ::close(probe);
  EXPECT_EQ(output_node(device).target, OutputTarget::kStream);
  write_file_atomically(device, "discarded\n");
  const struct stat node = node_of(device);
  EXPECT_TRUE(S_ISCHR(node.st_mode));
  EXPECT_EQ(node.st_rdev, ::makedev(1, 3));
}

TEST(AtomicFile, ASocketOrAFolderIsRefusedAndKept) {
  const auto socket_path = node_scratch("socket");
  const int listener = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(listener, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(socket_path.string().size(), sizeof address.sun_path) << "TMPDIR too long for a socket path";
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0) << std::strerror(errno);
  try {
    write_file_atomically(socket_path, "x");
    ADD_FAILURE() << "a socket was written";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), socket_path.string());
    EXPECT_NE(e.problem().find("is a socket"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(S_ISSOCK(node_of(socket_path).st_mode));
  ::close(listener);

  const auto folder = node_scratch("folder");
  std::filesystem::create_directories(folder);
  EXPECT_THROW(write_file_atomically(folder, "x"), InputError);
  EXPECT_TRUE(std::filesystem::is_directory(folder));
}

}  // namespace
}  // namespace crux
