// What a writer leaves behind when it is interrupted or the disk fills: no temporaries,
// no summary, and the INCOMPLETE marker (docs/RELIABILITY.md).

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "common/atomic_file.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

fs::path interruption_scratch(const std::string& name) {
  const fs::path dir = testing::test_folder() / "interruption";
  fs::create_directories(dir);
  fs::remove_all(dir / name);
  return dir / name;
}

std::vector<fs::path> temporaries_under(const fs::path& folder) {
  std::vector<fs::path> found;
  if (!fs::exists(folder)) return found;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::size_t at = name.rfind(".tmp.");
    if (at != std::string::npos && name.size() == at + 5 + kTemporarySuffixDigits) found.push_back(entry.path());
  }
  return found;
}

// Runs crux with `arguments` (no shell) and returns its pid.
pid_t start_crux(const std::vector<std::string>& arguments) {
  std::vector<char*> argv{const_cast<char*>(CRUX_BINARY)};
  for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // Its output goes to a file of the test's own, not to the machine's /dev/null.
  const std::string log = interruption_scratch("crux.log").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execv(CRUX_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// SIGINT and SIGTERM while an experiment folder is being written, at staggered moments
// after its marker appears: every temporary is removed, and a folder that did not
// complete keeps its marker and has no summary.
TEST(Interruption, ASignalWhileWritingLeavesNoTemporaryAndAMarkedFolder) {
  int interrupted_while_writing = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const fs::path folder = interruption_scratch("signal_" + std::to_string(trial));
    const pid_t pid = start_crux({"paper", "--walls", "4", "--iterations", "600", "--plan", "false", "--threads", "1",
                                  "--bootstrap-resamples", "100", "-o", folder.string()});
    ASSERT_GT(pid, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!fs::exists(folder / "INCOMPLETE") && std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) FAIL() << "crux ended before writing, status " << status;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(3 * trial));
    const int signal = trial % 2 == 0 ? SIGINT : SIGTERM;
    ::kill(pid, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(temporaries_under(folder).empty()) << "trial " << trial << ": " << temporaries_under(folder).front();
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), signal) << "trial " << trial;
      ++interrupted_while_writing;
      EXPECT_TRUE(fs::exists(folder / "INCOMPLETE")) << "trial " << trial;
      EXPECT_FALSE(fs::exists(folder / "summary.json")) << "trial " << trial;
    } else {
      EXPECT_EQ(WEXITSTATUS(status), 0) << "trial " << trial;  // it finished before the signal
      EXPECT_FALSE(fs::exists(folder / "INCOMPLETE")) << "trial " << trial;
    }
  }
  EXPECT_GT(interrupted_while_writing, 0) << "no trial hit the writing phase";
  std::cout << interrupted_while_writing << " of 8 signals arrived while the folder was being written\n";
}

// SIGKILL cannot be caught: the folder keeps its marker, and the next command into it
// (with --overwrite) clears crux's outputs and their stale temporaries, and nothing else.
TEST(Interruption, AfterSigkillTheMarkerStaysAndOverwriteClearsStaleTemporaries) {
  const fs::path folder = interruption_scratch("sigkill");
  const pid_t pid = start_crux({"train", "--wall-seed", "3", "--iterations", "4000", "-o", folder.string()});
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(folder / "INCOMPLETE") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  if (!WIFSIGNALED(status)) GTEST_SKIP() << "the run finished before SIGKILL";
  EXPECT_TRUE(fs::exists(folder / "INCOMPLETE"));
  // What a kill in the middle of a write leaves, plus a file that is not crux's.
  for (const char* name : {"iterations.csv.tmp.0123456789abcdef", "summary.json.tmp.fedcba9876543210", "notes.txt",
                           "config.toml.tmp.backup"}) {
    std::ofstream(folder / name) << "x";
  }
  const auto again = testing::run_crux("train --wall-seed 3 --iterations 200 --overwrite -o " + folder.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(temporaries_under(folder).empty());
  EXPECT_FALSE(fs::exists(folder / "INCOMPLETE"));
  EXPECT_TRUE(fs::exists(folder / "summary.json"));
  EXPECT_TRUE(fs::exists(folder / "notes.txt")) << "a file that is not crux's stays";
  EXPECT_TRUE(fs::exists(folder / "config.toml.tmp.backup")) << "nor one that only looks like a temporary";
}

// A full disk, as a file-size limit: the write fails with one line naming the file, the
// folder keeps its marker, has no summary and no temporary.
TEST(Interruption, AFullDiskIsOneErrorLineAndAMarkedFolderWithoutSummary) {
  const fs::path folder = interruption_scratch("full_disk");
  const std::string command = "ulimit -f 40; trap '' XFSZ; exec " + std::string(CRUX_BINARY) +
                              " train --wall-seed 3 --iterations 2000 -o " + folder.string();
  const fs::path err = interruption_scratch("full_disk.err");
  const int status = std::system(
      ("bash -c \"" + command + "\" > " + interruption_scratch("full_disk.out").string() + " 2> " + err.string())
          .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream in(err);
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(testing::count_lines(message), 1) << message;
  EXPECT_NE(message.find("cannot write: File too large"), std::string::npos) << message;
  EXPECT_NE(message.find(folder.string()), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(folder / "INCOMPLETE"));
  EXPECT_FALSE(fs::exists(folder / "summary.json"));
  EXPECT_TRUE(temporaries_under(folder).empty());
}

}  // namespace
}  // namespace crux
