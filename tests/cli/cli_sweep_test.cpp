// crux sweep end to end: the folder, resume after SIGKILL, and two MPI ranks.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <utility>

#include <nlohmann/json.hpp>

#include "support/held_folder_lock.hpp"
#include "support/run_crux.hpp"
#include "support/sweep_cells.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::folder_contents;
using testing::run_crux;

// Two cells of three wall pairs, 1500 iterations: 12 wall tasks... 6, and 18 runs.
fs::path sweep_file() {
  return testing::write_temporary(
      "sweep-" + std::to_string(::getpid()) + ".toml",
      "[experiment]\nwalls = 3\niterations = 1500\nplan = false\nbootstrap_resamples = 200\n"
      "[learning]\nepsilon = [0.1, 0.3]\n");
}

std::string sweep_arguments(const fs::path& out, int threads) {
  return "sweep --config " + sweep_file().string() + " --threads " + std::to_string(threads) + " -o " + out.string();
}

// Runs `arguments` and returns the folder's bytes, the folder moved away after (a sweep
// records the absolute path of the Q_grid its transfer runs start from, so sweeps are
// compared in the same place).
std::map<std::string, std::string> bytes_after(const std::string& command, const fs::path& out) {
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  auto contents = folder_contents(out);
  fs::remove_all(out);
  return contents;
}

void expect_same(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [file, bytes] : a) EXPECT_TRUE(b.contains(file) && b.at(file) == bytes) << file;
}

TEST(CliSweep, WritesEachRunAndTheResultsAndPrintsEachCell) {
  const fs::path out = testing::sweep_scratch("cli");
  const auto outcome = run_crux(sweep_arguments(out, 2));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("crux sweep: 2 cells (learning.epsilon)"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("cell 1 (learning.epsilon = 0.3): 3 walls x 1 seed"), std::string::npos);
  EXPECT_NE(outcome.out.find("0 of 24 tasks kept from an earlier start"), std::string::npos);
  for (const char* file : {"sweep.toml", "results.csv", "summary.json", "runs/c1/transfer_2/q_grid.bin",
                           "runs/c0/control_0/config.toml", "walls/g0/transfer_2/wall_facts.json",
                           "figures/c0_episode_lengths.svg", "figures/c1_episode_lengths.svg", "report.html"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  EXPECT_FALSE(fs::exists(out / "INCOMPLETE"));
  // The same command again resumes a finished sweep: nothing to run, the same results.
  const auto results = folder_contents(out);
  // One results.csv and one summary.json for the whole sweep, none per cell (a run folder
  // has the summary.json of a crux train folder).
  for (const auto& [file, bytes] : results) {
    const fs::path path(file);
    if (path.filename() == "results.csv") {
      EXPECT_EQ(file, "results.csv");
    }
    if (path.filename() == "summary.json" && file != "summary.json") {
      EXPECT_EQ(path.parent_path().parent_path().parent_path(), "runs") << file << " is not a run's summary";
    }
  }
  const std::string& report = results.at("report.html");
  ASSERT_NE(report.find("cell 1: learning.epsilon = 0.3"), std::string::npos);
  EXPECT_LT(report.find("cell 0: learning.epsilon = 0.1"), report.find("cell 1: learning.epsilon = 0.3"));
  EXPECT_NE(report.find("<svg"), std::string::npos) << "the cells' figures are inside the page";
  const auto again = run_crux(sweep_arguments(out, 1) + " --json");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(again.out).at("format"), "crux-sweep-summary");
  expect_same(results, folder_contents(out));
  // A run folder replays with crux transfer from its own config.toml.
  const fs::path replay = testing::sweep_scratch("replay");
  const auto replayed =
      run_crux("transfer --config " + (out / "runs/c1/transfer_2/config.toml").string() + " -o " + replay.string());
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  for (const char* file : {"iterations.csv", "episodes.csv", "q_grid.bin", "climb.csv", "greedy_climb.csv"}) {
    EXPECT_TRUE(folder_contents(replay).at(file) == results.at(std::string("runs/c1/transfer_2/") + file)) << file;
  }
  // A run's iterations.csv cut short is refused on resume, never analysed as a shorter run.
  const fs::path cut = out / "runs/c0/training_1/iterations.csv";
  const std::string whole = results.at("runs/c0/training_1/iterations.csv");
  const std::string without_last_row = whole.substr(0, whole.rfind('\n', whole.size() - 2) + 1);
  for (const std::string& text :
       {whole.substr(0, whole.size() - 5), whole.substr(0, whole.size() - 1), without_last_row}) {
    std::ofstream(cut, std::ios::trunc) << text;
    const auto resumed = run_crux(sweep_arguments(out, 1));
    EXPECT_EQ(resumed.exit_code, 2) << resumed.err;
    const std::string error = resumed.err.substr(std::min(resumed.err.find("crux: "), resumed.err.size()));
    EXPECT_EQ(testing::count_lines(error), 1) << resumed.err << "(after the progress line)";
    EXPECT_EQ(error.rfind("crux: " + cut.string() + ": ", 0), 0u) << resumed.err;
  }
}

// docs/TRANSFER.md's sweep, cut down by flags to one wall pair and a short run: one
// cell per mode, each analysed, and the report's table names every mode.
TEST(CliSweep, TheTransferModesExampleRunsACellPerMode) {
  const fs::path out = testing::sweep_scratch("modes");
  const auto outcome = run_crux("sweep --config " CRUX_SOURCE_DIR
                                "/examples/sweeps/transfer_modes.toml --walls 2 "
                                "--seeds-per-wall 1 --iterations 300 --json -o " +
                                out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto summary = nlohmann::json::parse(outcome.out);
  ASSERT_EQ(summary.at("cells").size(), 5u);
  const std::string report = folder_contents(out).at("report.html");
  for (const char* mode : {"paper", "informed", "prior", "seeded", "shaping"}) {
    EXPECT_NE(report.find(std::string("experiment.transfer = ") + mode), std::string::npos) << mode;
  }
  EXPECT_EQ(summary["cells"][4]["parameters"]["experiment.transfer"], "shaping");
}

TEST(CliSweep, BadListsAndAnotherSweepsFolderAreOneLineErrors) {
  const fs::path threads = testing::write_temporary("threads.toml", "[experiment]\nthreads = [1, 2]\n");
  auto outcome = run_crux("sweep --config " + threads.string() + " -o " + testing::sweep_scratch("bad").string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: " + threads.string() + ": line 2: experiment.threads takes one value, not a list\n");
  // K and the training walls' keys are axes like any other, and checked as crux paper checks them.
  const fs::path training_walls =
      testing::write_temporary("training_walls.toml", "[experiment]\ntraining_walls = [2, 0]\n");
  outcome = run_crux("sweep --config " + training_walls.string() + " -o " + testing::sweep_scratch("bad").string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("experiment.training_walls"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("must be from 1 to 1000"), std::string::npos) << outcome.err;
  const fs::path sigma = testing::write_temporary("sigma.toml", "[training_wall]\nsigma = [0.1, -0.1]\n");
  outcome = run_crux("sweep --config " + sigma.string() + " -o " + testing::sweep_scratch("bad").string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("training_wall.sigma"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("must be in [0, 10]"), std::string::npos) << outcome.err;
  outcome = run_crux("paper --config " + sweep_file().string() + " -o " + testing::sweep_scratch("paper").string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find("learning.epsilon must be one value; only crux sweep takes lists"), std::string::npos)
      << outcome.err;
  const fs::path out = testing::sweep_scratch("taken");
  ASSERT_EQ(run_crux(sweep_arguments(out, 2)).exit_code, 0);
  outcome = run_crux(sweep_arguments(out, 2) + " --learning-alpha 0.2");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("holds another sweep (its sweep.toml differs"), std::string::npos) << outcome.err;
}

TEST(CliSweep, ASweepOnAFolderThatAnotherSweepWritesIsOneLineError) {
  const fs::path out = testing::sweep_scratch("locked");
  testing::HeldFolderLock other(out);
  const auto outcome = run_crux(sweep_arguments(out, 2));
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: " + out.string() + ": is being written by another crux sweep (pid " +
                             std::to_string(::getpid()) + "); wait until it ends, or choose another folder\n");
  EXPECT_EQ(folder_contents(out).size(), 1u) << "the lock file alone";
}

// Issue 25: lists multiplying to 2^64 cells wrapped the count to 0 and crashed, and a
// million seeds were each built (re-reading the file) before the task cap: the cells are
// counted first and refused before any is built or the folder is made.
TEST(CliSweep, TooManyCellsAreRefusedBeforeAnyIsBuilt) {
  std::string million = "[experiment]\nseed = [";
  for (int s = 1; s <= 1000000; ++s) {
    if (s > 1) million += ',';
    million += std::to_string(s);
  }
  million += "]\n";
  std::string wrapping = "[learning]\n";
  for (const char* key : {"alpha", "gamma", "epsilon", "planning_steps"}) {
    wrapping += std::string(key) + " = [";
    for (int v = 0; v < 65536; ++v) wrapping += (v > 0 ? ",0." : "0.") + std::to_string(v + 1);
    wrapping += "]\n";
  }
  for (const auto& [name, text] : {std::pair{"million.toml", million}, std::pair{"wrapping.toml", wrapping}}) {
    const fs::path file = testing::write_temporary(name, text);
    const fs::path out = testing::sweep_scratch(name);
    const auto outcome = run_crux("sweep --config " + file.string() + " -o " + out.string());
    EXPECT_EQ(outcome.exit_code, 2) << name;
    EXPECT_EQ(outcome.err, "crux: " + file.string() +
                               ": its lists make more than 100000 cells (the product of their lengths), the most a "
                               "sweep may have\n");
    EXPECT_FALSE(fs::exists(out)) << name;
  }
}

TEST(CliSweep, ASweepKilledAtAnyMomentResumesToTheSameBytes) {
  const fs::path out = testing::sweep_scratch("killed");
  const std::string command =
      std::string(CRUX_BINARY) + " " + sweep_arguments(out, 2) + " > " + out.string() + ".log 2>&1";
  const auto whole = bytes_after(command, out);
  for (const int finished_runs : {2, 9}) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // SIGKILL once some runs are in place: others are half-written in .partial/.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    const auto runs_done = [&] {
      int n = 0;
      for (const char* cell : {"c0", "c1"}) {
        std::error_code error;
        for (auto it = fs::directory_iterator(out / "runs" / cell, error); !error && it != fs::directory_iterator();
             ++it)
          ++n;
      }
      return n;
    };
    while (runs_done() < finished_runs && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it was killed; status " << status;
    EXPECT_TRUE(fs::exists(out / "INCOMPLETE"));
    EXPECT_FALSE(fs::exists(out / "results.csv"));
    expect_same(whole, bytes_after(command, out));
  }
}

TEST(CliSweep, TwoMpiRanksWriteTheSingleProcessBytes) {
  const fs::path out = testing::sweep_scratch("mpi");
  const auto single =
      bytes_after(std::string(CRUX_BINARY) + " " + sweep_arguments(out, 2) + " > " + out.string() + ".single.log", out);
  // Open MPI's own allocations are not crux's leaks.
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
  const std::string mpirun = std::string(CRUX_MPIEXEC) + " -n 2 --oversubscribe --allow-run-as-root " + CRUX_BINARY +
                             " " + sweep_arguments(out, 1);
  const auto ranks = bytes_after(mpirun + " > " + (out.string() + ".log") + " 2>&1", out);
  expect_same(single, ranks);
  std::ifstream log(out.string() + ".log");
  const std::string printed((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_EQ(printed.find("crux sweep: 2 cells"), printed.rfind("crux sweep: 2 cells")) << "rank 0 alone prints";
}

// A task that fails on any rank ends the whole job with its error (no rank waits for it
// forever), and ranks given different sweeps refuse to start.
TEST(CliSweep, UnderMpirunAFailureEndsEveryRankAndDifferentSweepsAreRefused) {
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
  const fs::path out = testing::sweep_scratch("mpi-failure");
  ASSERT_EQ(
      std::system((std::string(CRUX_BINARY) + " " + sweep_arguments(out, 2) + " > " + out.string() + ".single.log 2>&1")
                      .c_str()),
      0);
  fs::remove_all(out / "runs/c0/control_1");
  std::ofstream(out / "runs/c0/control_1") << "not a folder";
  const std::string mpirun = "timeout 300 " + std::string(CRUX_MPIEXEC) + " --oversubscribe --allow-run-as-root ";
  const std::string log = out.string() + ".log";
  int status =
      std::system((mpirun + "-n 2 " + CRUX_BINARY + " " + sweep_arguments(out, 1) + " > " + log + " 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << "124: a rank hung";
  std::ifstream failed(log);
  const std::string failure((std::istreambuf_iterator<char>(failed)), std::istreambuf_iterator<char>());
  EXPECT_NE(failure.find("control_1: cannot move the finished task here"), std::string::npos) << failure;

  const fs::path other_file = testing::write_temporary("other-sweep.toml",
                                                       "[experiment]\nwalls = 3\niterations = 1500\n"
                                                       "plan = false\n[learning]\nepsilon = [0.1, 0.5]\n");
  const fs::path fresh = testing::sweep_scratch("mpi-mismatch");
  status = std::system((mpirun + "-n 1 " + CRUX_BINARY + " " + sweep_arguments(fresh, 1) + " : -n 1 " + CRUX_BINARY +
                        " sweep --config " + other_file.string() + " --threads 1 -o " + fresh.string() + " > " + log +
                        " 2>&1")
                           .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream refused(log);
  const std::string mismatch((std::istreambuf_iterator<char>(refused)), std::istreambuf_iterator<char>());
  EXPECT_NE(mismatch.find("crux: mpirun: another process of this sweep failed to read it, or was given another sweep"),
            std::string::npos)
      << mismatch;
  EXPECT_FALSE(fs::exists(fresh)) << "nothing written";
}

}  // namespace
}  // namespace crux
