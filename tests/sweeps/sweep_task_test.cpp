#include "sweeps/sweep_task.hpp"

#include <gtest/gtest.h>

#include "jobs/command_keys.hpp"
#include "outputs/iterations_file.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/run_folder.hpp"
#include "outputs/sweep_files.hpp"
#include "reports/plan_description.hpp"
#include "support/sweep_cells.hpp"
#include "support/test_models.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

TEST(SweepTask, ARunTaskWritesTheRunFolderThatCruxTrainWouldReplay) {
  const fs::path folder = fs::absolute(testing::sweep_scratch("task"));
  const ExperimentConfig config = testing::small_sweep_config(1, 300);
  const SweepPlan plan = plan_sweep({}, {testing::sweep_cell(config)});
  const std::size_t training = run_task_index(plan, 0, Condition::Training, 0);
  const std::size_t transfer = run_task_index(plan, 0, Condition::Transfer, 0);
  run_sweep_task(plan, training, testing::human_model(), folder);
  run_sweep_task(plan, transfer, testing::human_model(), folder);
  EXPECT_TRUE(fs::is_empty(folder / kPartialFolder)) << "the task folder was moved into place";

  const ExperimentResult paper = run_paper_experiment(testing::human_model(), config.settings);
  const RunFolder run = locate_run_folder(folder / "runs/c0/transfer_0");
  const std::vector<RunStep> steps = read_iterations_file(run.directory / "iterations.csv", run.iterations,
                                                          config.settings.learning.climbing.physics.model);
  const RunResult& expected = paper.conditions[static_cast<int>(Condition::Transfer)].runs[0];
  ASSERT_EQ(steps.size(), expected.iterations.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    ASSERT_EQ(steps[i].hold_id, expected.iterations[i].hold_id) << "iteration " << i + 1;
    ASSERT_EQ(steps[i].success, expected.iterations[i].success) << "iteration " << i + 1;
  }
  // Its config.toml names the transfer wall's seed, the run's learning seed and the
  // training run's Q_grid: crux transfer --config replays it.
  const ExperimentConfig recorded = read_run_config(run.config_file);
  EXPECT_EQ(recorded.wall_seed, paper.walls[1].seed);
  EXPECT_EQ(recorded.settings.seed, paper.conditions[static_cast<int>(Condition::Transfer)].learning_seeds[0]);
  EXPECT_EQ(recorded.q_grid, (folder / "runs/c0/training_0/q_grid.bin").string());
  EXPECT_FALSE(run.summary.contains("seconds")) << "the time would differ from worker to worker";
}

TEST(SweepTask, AWallTaskWritesTheWallAndItsFacts) {
  const fs::path folder = fs::absolute(testing::sweep_scratch("wall-task"));
  ExperimentConfig config = testing::small_sweep_config(1, 300, "[experiment]\nplan = true\nplan_max_solves = 300\n");
  const SweepPlan plan = plan_sweep({}, {testing::sweep_cell(config)});
  run_sweep_task(plan, 1, testing::human_model(), folder);  // the transfer wall
  const ExperimentWall drawn = draw_wall(testing::human_model(), config.settings, kTransferWalls, 0);
  EXPECT_EQ(load_wall((folder / "walls/g0/transfer_0/wall.json").string()).holds.size(), drawn.wall.holds.size());
  const nlohmann::json facts = read_sweep_wall_facts(folder / "walls/g0/transfer_0");
  EXPECT_EQ(facts.at("seed"), drawn.seed);
  EXPECT_EQ(facts.at("filtered_pairs"), filtered_pairs(drawn.wall, config.settings.learning.climbing.filter));
  const Plan plan_now =
      shortest_plan(testing::human_model(), drawn.wall, config.settings.learning.climbing, config.settings.plan_search);
  EXPECT_EQ(facts.at("plan"), nlohmann::json::parse(plan_json(drawn.wall, plan_now).dump()))
      << "experiment.plan asks for the exact climb";
}

}  // namespace
}  // namespace crux
