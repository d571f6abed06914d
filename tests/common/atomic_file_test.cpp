#include "common/atomic_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "common/input_error.hpp"

namespace crux {
namespace {

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  const auto dir = std::filesystem::temp_directory_path() / "crux-tests" / "atomic";
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
  const auto dir = std::filesystem::temp_directory_path() / "crux-tests" / "atomic-link";
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

}  // namespace
}  // namespace crux
