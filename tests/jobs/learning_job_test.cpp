#include "jobs/learning_job.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/input_error.hpp"
#include "learning/q_table_file.hpp"
#include "support/sweep_cells.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

LearningJob small_job(std::optional<fs::path> output, int iterations = 300) {
  LearningJob job;
  job.config.wall_seed = 3;
  job.config.settings.seed = 5;
  job.config.settings.learning.iterations = iterations;
  finalize_config(job.config);
  job.output = output;
  job.model = &testing::human_model();
  return job;
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Interrupted {};

TEST(LearningJob, WritesTheRunFolderAndNamesItsCaller) {
  const fs::path folder = testing::sweep_scratch("job-folder");
  const LearningJobOutcome outcome = run_learning_job(small_job(folder), {"a test", {}, {}, {}});
  EXPECT_EQ(outcome.result.conditions[static_cast<int>(Condition::Training)].runs.size(), 1u);
  EXPECT_EQ(outcome.resumed_at, 0);
  for (const char* file : {"config.toml", "summary.json", "wall.json", "iterations.csv", "q_grid.bin"}) {
    EXPECT_TRUE(fs::exists(folder / file)) << file;
  }
  EXPECT_EQ(file_text(folder / "summary.json"), outcome.summary.dump(2) + "\n");
  EXPECT_NE(file_text(folder / "config.toml").find("produced_by = \"a test\""), std::string::npos);
  EXPECT_EQ(outcome.summary.at("provenance").at("produced_by"), "a test");
  // Without a folder it learns the same run.
  const LearningJobOutcome unwritten = run_learning_job(small_job({}), {"a test", {}, {}, {}});
  EXPECT_EQ(unwritten.summary, outcome.summary);
}

TEST(LearningJob, OnlyATransferRunTakesAQGridAndAFolderlessRunKeepsNoCheckpoint) {
  const LearningJobOutcome trained = run_learning_job(small_job({}), {});
  LearningJob transfer = small_job({});
  transfer.condition = Condition::Transfer;
  EXPECT_THROW(run_learning_job(transfer, {}), InputError) << "a transfer run without a Q_grid";
  transfer.q_grid = trained.result.conditions[0].runs.front().q_grid;
  const LearningJobOutcome transferred = run_learning_job(transfer, {});
  EXPECT_EQ(transferred.result.conditions[static_cast<int>(Condition::Transfer)].runs.size(), 1u);
  EXPECT_TRUE(transferred.summary.at("episode_lengths").contains("transfer"));
  transfer.condition = Condition::Control;
  EXPECT_THROW(run_learning_job(transfer, {}), InputError) << "a control run given a Q_grid";
  // A folder replays from its config.toml, which cannot name an object.
  transfer.condition = Condition::Transfer;
  transfer.output = testing::sweep_scratch("job-transfer");
  try {
    run_learning_job(transfer, {});
    ADD_FAILURE() << "a folder written from a Q_grid object";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "q_grid");
  }
  EXPECT_FALSE(fs::exists(*transfer.output));

  LearningJob checkpointed = small_job({});
  checkpointed.config.settings.learning.iterations = 300;
  checkpointed.config.checkpoint_every = 100;
  try {
    run_learning_job(std::move(checkpointed), {});
    ADD_FAILURE() << "a run without a folder took a checkpoint interval";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "experiment.checkpoint_every");
  }
}

// Stopped after its first checkpoint, the job started again says where it resumes and
// ends with the folder of a run never stopped.
TEST(LearningJob, ResumesFromItsCheckpointAndSaysWhere) {
  const fs::path unbroken = testing::sweep_scratch("job-unbroken");
  const fs::path stopped = testing::sweep_scratch("job-stopped");
  LearningJob job = small_job(unbroken);
  job.config.checkpoint_every = 100;
  run_learning_job(job, {});
  job.output = stopped;
  int calls = 0;
  const auto stop_at_150 = [&calls] {
    if (++calls == 150) throw Interrupted{};
  };
  EXPECT_THROW(run_learning_job(job, {{}, {}, stop_at_150, {}}), Interrupted);
  ASSERT_TRUE(fs::exists(stopped / "checkpoint.bin"));
  int told = -1;
  const LearningJobOutcome resumed = run_learning_job(job, {{}, {}, {}, [&told](int iteration) { told = iteration; }});
  EXPECT_EQ(told, 100);
  EXPECT_EQ(resumed.resumed_at, 100);
  EXPECT_EQ(testing::folder_contents(stopped), testing::folder_contents(unbroken));
}

}  // namespace
}  // namespace crux
