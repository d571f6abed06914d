#include "sweeps/sweep_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/input_error.hpp"
#include "support/sweep_cells.hpp"
#include "sweeps/sweep_task.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "x";
}

TEST(SweepFolder, ANewFolderIsMarkedAndKeepsTheSweepFile) {
  const fs::path folder = testing::sweep_scratch("new");
  prepare_sweep_folder(folder, "# sweep\n", {}, false);
  const auto contents = testing::folder_contents(folder);
  EXPECT_EQ(contents.at("sweep.toml"), "# sweep\n");
  EXPECT_TRUE(contents.contains("INCOMPLETE"));
  mark_sweep_complete(folder);
  EXPECT_FALSE(fs::exists(folder / "INCOMPLETE"));
}

TEST(SweepFolder, TheSameSweepResumesAndADifferentOneIsRefusedUnlessOverwritten) {
  const fs::path folder = testing::sweep_scratch("resume");
  prepare_sweep_folder(folder, "# sweep\n", {}, false);
  touch(folder / "runs/c0/training_0/iterations.csv");
  touch(folder / kPartialFolder / "3.host.42/iterations.csv");
  prepare_sweep_folder(folder, "# sweep\n", {}, false);
  EXPECT_TRUE(fs::exists(folder / "runs/c0/training_0/iterations.csv")) << "a finished task is kept";
  EXPECT_FALSE(fs::exists(folder / kPartialFolder)) << "a half-written task is cleared";
  try {
    prepare_sweep_folder(folder, "# another sweep\n", {}, false);
    FAIL() << "another sweep's folder was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), folder.string());
    EXPECT_NE(std::string(e.what()).find("holds another sweep"), std::string::npos) << e.what();
  }
  touch(folder / "notes.txt");
  prepare_sweep_folder(folder, "# another sweep\n", {}, true);
  EXPECT_FALSE(fs::exists(folder / "runs")) << "the other sweep's outputs are replaced";
  EXPECT_TRUE(fs::exists(folder / "notes.txt")) << "what crux did not write stays";
}

// A SIGKILL can leave temporaries of the sweep's files: a resume removes them, and a
// folder killed before its sweep.toml was in place starts afresh.
TEST(SweepFolder, TemporariesOfAKilledSweepAreRemoved) {
  const fs::path folder = testing::sweep_scratch("temporaries");
  touch(folder / "sweep.toml.tmp.0123456789abcdef");
  prepare_sweep_folder(folder, "# sweep\n", {}, false);
  EXPECT_FALSE(fs::exists(folder / "sweep.toml.tmp.0123456789abcdef"));
  touch(folder / "results.csv.tmp.00000000deadbeef");
  touch(folder / kPartialFolder / "1.host.2/iterations.csv");
  prepare_sweep_folder(folder, "# sweep\n", {}, false);
  EXPECT_FALSE(fs::exists(folder / "results.csv.tmp.00000000deadbeef"));
  mark_sweep_complete(folder);
  EXPECT_EQ(testing::folder_contents(folder).size(), 1u) << "sweep.toml alone: no marker, no .partial/";
  EXPECT_FALSE(fs::exists(folder / kPartialFolder));
}

TEST(SweepFolder, OverwritingReplacesAnotherCruxCommandsOutputs) {
  const fs::path folder = testing::sweep_scratch("paper-folder");
  touch(folder / "config.toml");
  touch(folder / "figures/fig3.svg");
  touch(folder / "notes.txt");
  EXPECT_THROW(prepare_sweep_folder(folder, "# sweep\n", {}, false), InputError);
  prepare_sweep_folder(folder, "# sweep\n", {}, true);
  EXPECT_FALSE(fs::exists(folder / "config.toml"));
  EXPECT_FALSE(fs::exists(folder / "figures"));
  EXPECT_TRUE(fs::exists(folder / "notes.txt"));
}

TEST(SweepFolder, AFolderThatHoldsOtherFilesOrAnInputIsRefused) {
  const fs::path folder = testing::sweep_scratch("busy");
  touch(folder / "notes.txt");
  EXPECT_THROW(prepare_sweep_folder(folder, "# sweep\n", {}, false), InputError);
  EXPECT_THROW(prepare_sweep_folder(folder, "# sweep\n", {(folder / "notes.txt").string()}, true), InputError);
}

TEST(SweepFolder, FinishedTasksAreThoseWhoseFolderIsInPlace) {
  const fs::path folder = testing::sweep_scratch("finished");
  const SweepPlan plan = plan_sweep({}, {testing::sweep_cell(testing::small_sweep_config(1, 100))});
  touch(folder / plan.tasks[3].folder / "iterations.csv");
  const std::vector<bool> finished = finished_tasks(plan, folder);
  ASSERT_EQ(finished.size(), plan.tasks.size());
  for (std::size_t t = 0; t < finished.size(); ++t) EXPECT_EQ(finished[t], t == 3) << "task " << t;
}

}  // namespace
}  // namespace crux
