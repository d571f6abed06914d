#include "sweeps/sweep_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "common/folder_lock.hpp"
#include "common/input_error.hpp"
#include "support/held_folder_lock.hpp"
#include "support/sweep_cells.hpp"
#include "support/test_models.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::folder_contents;
using testing::small_sweep_config;
using testing::sweep_cell;

// Two cells of two wall pairs, 100 iterations: 4 wall tasks (one group) and 12 runs.
SweepJob small_job(const fs::path& folder, int threads) {
  std::vector<SweepCell> cells{sweep_cell(small_sweep_config(2, 100, "[learning]\nepsilon = 0.1\n"), {"0.1"}),
                               sweep_cell(small_sweep_config(2, 100, "[learning]\nepsilon = 0.5\n"), {"0.5"})};
  SweepJob job;
  job.plan = plan_sweep({"learning.epsilon"}, std::move(cells));
  job.folder = fs::absolute(folder);
  job.sweep_toml = "# the sweep of the test\n";
  job.provenance = {{"test", true}};
  job.threads = threads;
  return job;
}

// The same job in the same folder (transfer runs record their input's absolute path):
// the earlier result is moved aside first.
std::map<std::string, std::string> sweep_bytes(const fs::path& folder, int threads) {
  const SweepOutcome outcome = run_sweep(small_job(folder, threads), testing::human_model(), nullptr);
  EXPECT_TRUE(outcome.coordinator);
  auto contents = folder_contents(folder);
  fs::remove_all(folder);
  return contents;
}

TEST(SweepRun, TheBytesDoNotDependOnTheThreads) {
  const fs::path folder = testing::sweep_scratch("threads");
  const auto one = sweep_bytes(folder, 1);
  const auto three = sweep_bytes(folder, 3);
  EXPECT_EQ(one.size(), 1u + 2 + 4 * 2 + 12 * 8 + 3)
      << "sweep.toml, results, 4 walls of 2 files, 12 runs of 8 files, and the report: a figure per cell and the page";
  ASSERT_EQ(one.size(), three.size());
  for (const auto& [file, bytes] : one) EXPECT_TRUE(three.at(file) == bytes) << file;
  EXPECT_FALSE(one.contains("INCOMPLETE"));
}

TEST(SweepRun, AResumedSweepKeepsFinishedTasksAndEndsWithTheSameBytes) {
  const fs::path folder = testing::sweep_scratch("resume");
  const auto whole = sweep_bytes(folder, 2);
  const SweepJob job = small_job(folder, 2);
  run_sweep(job, testing::human_model(), nullptr);
  // As a kill leaves it: some tasks missing (a training run and so its transfer too,
  // a control run, a wall), a half-written task under .partial/, no results.
  for (const char* gone : {"runs/c1/training_1", "runs/c1/transfer_1", "runs/c0/control_0", "walls/g0/transfer_0"}) {
    fs::remove_all(folder / gone);
  }
  fs::remove(folder / "results.csv");
  fs::remove(folder / "summary.json");
  fs::create_directories(folder / kPartialFolder / "7.host.1");
  const fs::file_time_type kept_time = fs::last_write_time(folder / "runs/c0/training_0/iterations.csv");
  const SweepOutcome outcome = run_sweep(job, testing::human_model(), nullptr);
  EXPECT_EQ(outcome.tasks, 16u);
  EXPECT_EQ(outcome.already_finished, 12u);
  EXPECT_EQ(fs::last_write_time(folder / "runs/c0/training_0/iterations.csv"), kept_time) << "finished runs are kept";
  const auto resumed = folder_contents(folder);
  ASSERT_EQ(resumed.size(), whole.size());
  for (const auto& [file, bytes] : whole) EXPECT_TRUE(resumed.at(file) == bytes) << file;
}

TEST(SweepRun, AFolderOfAnotherSweepIsRefusedBeforeAnyWork) {
  const fs::path folder = testing::sweep_scratch("other");
  SweepJob job = small_job(folder, 1);
  run_sweep(job, testing::human_model(), nullptr);
  const auto before = folder_contents(folder);
  job.sweep_toml = "# another sweep\n";
  EXPECT_THROW(run_sweep(job, testing::human_model(), nullptr), InputError);
  EXPECT_EQ(folder_contents(folder), before) << "nothing written";
  job.overwrite = true;
  run_sweep(job, testing::human_model(), nullptr);
  EXPECT_EQ(folder_contents(folder).at("sweep.toml"), job.sweep_toml);
}

// The test holds the folder's lock as another sweep would: a second sweep is refused
// before it writes anything, and runs once the first has ended.
TEST(SweepRun, ASweepIsRefusedWhileAnotherWritesItsFolder) {
  const fs::path folder = testing::sweep_scratch("locked");
  const SweepJob job = small_job(folder, 2);
  testing::HeldFolderLock other(folder);
  const auto before = folder_contents(folder);
  try {
    run_sweep(job, testing::human_model(), nullptr);
    FAIL() << "two sweeps wrote one folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "is being written by another crux sweep (pid " + std::to_string(::getpid()) +
                               "); wait until it ends, or choose another folder");
  }
  EXPECT_EQ(folder_contents(folder), before) << "nothing written";
  other.release();
  const SweepOutcome outcome = run_sweep(job, testing::human_model(), nullptr);
  EXPECT_EQ(outcome.already_finished, 0u);
  EXPECT_TRUE(fs::exists(folder / "results.csv"));
  EXPECT_FALSE(fs::exists(folder / kFolderLockFile)) << "the lock is not an output";
}

// A resume beside a running sweep would clear .partial/ under it: refused, the
// interrupted folder kept as it was, and resumed once the other sweep has ended.
TEST(SweepRun, AResumeIsRefusedWhileAnotherSweepWritesItsFolder) {
  const fs::path folder = testing::sweep_scratch("locked-resume");
  const auto whole = sweep_bytes(folder, 2);
  const SweepJob job = small_job(folder, 2);
  run_sweep(job, testing::human_model(), nullptr);
  fs::remove_all(folder / "runs/c1/training_1");
  fs::remove_all(folder / "runs/c1/transfer_1");
  fs::remove(folder / "results.csv");
  fs::remove(folder / "summary.json");
  fs::create_directories(folder / kPartialFolder / "7.host.1");
  std::ofstream(folder / kPartialFolder / "7.host.1" / "iterations.csv") << "half\n";
  testing::HeldFolderLock other(folder);
  const auto interrupted = folder_contents(folder);
  EXPECT_THROW(run_sweep(job, testing::human_model(), nullptr), InputError);
  EXPECT_EQ(folder_contents(folder), interrupted) << ".partial/ and every task kept";
  other.release();
  const SweepOutcome outcome = run_sweep(job, testing::human_model(), nullptr);
  EXPECT_EQ(outcome.already_finished, 14u);
  const auto resumed = folder_contents(folder);
  ASSERT_EQ(resumed.size(), whole.size()) << "no lock file among the outputs";
  for (const auto& [file, bytes] : whole) EXPECT_TRUE(resumed.at(file) == bytes) << file;
}

}  // namespace
}  // namespace crux
