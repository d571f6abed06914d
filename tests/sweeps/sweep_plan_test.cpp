#include "sweeps/sweep_plan.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "support/sweep_cells.hpp"

namespace crux {
namespace {

using testing::small_sweep_config;
using testing::sweep_cell;

TEST(SweepPlan, WallsFirstThenEachCellsRunsWithTransferAfterItsTraining) {
  std::vector<SweepCell> cells{sweep_cell(small_sweep_config(2, 100), {"0.1"}),
                               sweep_cell(small_sweep_config(2, 100), {"0.2"})};
  const SweepPlan plan = plan_sweep({"learning.epsilon"}, std::move(cells));
  // epsilon shapes no wall: one group of 2 training and 2 transfer walls.
  EXPECT_EQ(plan.wall_groups, 1u);
  ASSERT_EQ(plan.tasks.size(), 4u + 2 * 3 * 2);
  EXPECT_EQ(plan.run_tasks(), 12u);
  EXPECT_EQ(plan.tasks[0].kind, SweepTaskKind::Wall);
  EXPECT_EQ(plan.tasks[0].folder, "walls/g0/training_0");
  EXPECT_EQ(plan.tasks[3].folder, "walls/g0/transfer_1");
  for (std::size_t c = 0; c < 2; ++c) {
    for (const Condition condition : kConditions) {
      for (int r = 0; r < 2; ++r) {
        const SweepTask& task = plan.tasks[run_task_index(plan, c, condition, r)];
        EXPECT_EQ(task.kind, SweepTaskKind::Run);
        EXPECT_EQ(task.cell, c);
        EXPECT_EQ(task.condition, condition);
        EXPECT_EQ(task.index, r);
        EXPECT_EQ(task.folder.string(), fmt::format("runs/c{}/{}_{}", c, enum_name(condition), r));
        const int training = static_cast<int>(run_task_index(plan, c, Condition::Training, r));
        EXPECT_EQ(task.depends_on, condition == Condition::Transfer ? training : -1);
      }
    }
  }
}

TEST(SweepPlan, CellsThatDrawOtherWallsHaveTheirOwnWallGroup) {
  std::vector<SweepCell> cells;
  for (const char* sigma : {"0.05", "0.1"}) {
    for (const char* epsilon : {"0.1", "0.2"}) {
      cells.push_back(
          sweep_cell(small_sweep_config(1, 100, fmt::format("[wall]\nsigma = {}\n", sigma)), {epsilon, sigma}));
    }
  }
  const SweepPlan plan = plan_sweep({"learning.epsilon", "wall.sigma"}, std::move(cells));
  EXPECT_EQ(plan.wall_groups, 2u);
  EXPECT_EQ(plan.cells[0].wall_group, plan.cells[1].wall_group);
  EXPECT_EQ(plan.cells[2].wall_group, plan.cells[3].wall_group);
  EXPECT_NE(plan.cells[0].wall_group, plan.cells[2].wall_group);
  EXPECT_EQ(plan.tasks[plan.cells[2].wall_group * 2].cell, 2u) << "a group's walls are drawn with its first cell";
  EXPECT_TRUE(shapes_walls("experiment.seed"));
  EXPECT_TRUE(shapes_walls("ik.solver"));
  EXPECT_FALSE(shapes_walls("learning.epsilon"));
  EXPECT_FALSE(shapes_walls("grid.columns"));
}

// K training walls: a group draws each pair's K - 1 preceding training walls for its
// largest K (pair w's wall j is the same for every K above j); the training walls' own
// keys draw other walls.
TEST(SweepPlan, AGroupDrawsThePrecedingTrainingWallsOfItsLargestK) {
  std::vector<SweepCell> cells;
  for (const int k : {1, 3}) {
    cells.push_back(sweep_cell(small_sweep_config(2, 100, fmt::format("[experiment]\ntraining_walls = {}\n", k)),
                               {std::to_string(k)}));
  }
  const SweepPlan plan = plan_sweep({"experiment.training_walls"}, std::move(cells));
  EXPECT_EQ(plan.wall_groups, 1u);
  ASSERT_EQ(plan.tasks.size(), 2u * 2 + 2 * 2 + 2 * 3 * 2);
  EXPECT_EQ(plan.run_tasks(), 12u);
  EXPECT_EQ(plan.tasks[4].folder, "walls/g0/preceding_0_0");
  EXPECT_EQ(plan.tasks[4].preceding, 0);
  EXPECT_EQ(plan.tasks[7].folder, "walls/g0/preceding_1_1");
  EXPECT_EQ(plan.tasks[7].index, 1);
  EXPECT_EQ(plan.tasks[7].preceding, 1);
  EXPECT_EQ(plan.tasks[3].preceding, -1);
  EXPECT_EQ(plan.tasks[run_task_index(plan, 1, Condition::Training, 0)].preceding, -1);
  EXPECT_FALSE(shapes_walls("experiment.training_walls"));
  EXPECT_TRUE(shapes_walls("training_wall.sigma"));
}

TEST(SweepPlan, AGroupDrawsAsManyWallsAsItsLargestCell) {
  std::vector<SweepCell> cells{sweep_cell(small_sweep_config(1, 100), {"1"}),
                               sweep_cell(small_sweep_config(3, 100), {"3"})};
  const SweepPlan plan = plan_sweep({"experiment.walls"}, std::move(cells));
  EXPECT_EQ(plan.wall_groups, 1u);
  EXPECT_EQ(plan.tasks.size() - plan.run_tasks(), 6u);
  EXPECT_EQ(plan.run_tasks(), 3u + 9u);
}

TEST(SweepPlan, ASweepTooLargeIsRefused) {
  std::vector<SweepCell> cells{sweep_cell(small_sweep_config(10, 100))};
  EXPECT_THROW(plan_sweep({}, std::move(cells), 49), InputError);
}

}  // namespace
}  // namespace crux
