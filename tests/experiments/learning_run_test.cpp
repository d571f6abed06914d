#include "experiments/learning_run.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

// Common random numbers at the level of a run: transfer and control differ only in the
// starting Q_grid, so with the same seed they must take the same actions until the
// first iteration at which either makes a g-greedy choice, the only place where Q_grid
// enters.
TEST(LearningRun, TransferAndControlAgreeUntilTheFirstGGreedyChoice) {
  const BodyModel& model = testing::human_model();
  LearningParameters parameters;
  parameters.iterations = 400;
  const RunResult training = run_learning(model, generate_random_wall(2), parameters, 11);
  const Wall wall = generate_random_wall(3);
  int compared = 0;
  for (const std::uint64_t seed : {5, 6, 7, 8}) {
    const RunResult transfer = run_learning(model, wall, parameters, seed, &training.q_grid);
    const RunResult control = run_learning(model, wall, parameters, seed);
    for (std::size_t i = 0; i < transfer.iterations.size(); ++i) {
      const IterationRecord& t = transfer.iterations[i];
      const IterationRecord& c = control.iterations[i];
      if (t.regime == Regime::GGreedy || c.regime == Regime::GGreedy) break;
      ASSERT_EQ(t.hold_id, c.hold_id) << "seed " << seed << ", iteration " << i + 1;
      ASSERT_EQ(t.regime, c.regime) << "seed " << seed << ", iteration " << i + 1;
      ASSERT_EQ(t.success, c.success) << "seed " << seed << ", iteration " << i + 1;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0) << "some iterations came before a g-greedy choice";
  RecordProperty("iterations_compared", compared);
}

// The recorded climb is the last completed episode's: the start posture, then one
// posture per reached move, ending with the one that passes the finishing height.
TEST(LearningRun, LastClimbHoldsAPosturePerReachedMoveOfTheLastEpisodeUpToTheFinish) {
  const BodyModel& model = testing::human_model();
  LearningParameters parameters;
  parameters.iterations = 1500;
  const Wall wall = generate_random_wall(3);
  const RunResult run = run_learning(model, wall, parameters, 5);
  ASSERT_GE(run.episode_lengths.size(), 2u) << "seed 5 on wall 3 completes episodes within 1500 iterations";
  const int last = static_cast<int>(run.episode_lengths.size()) - 1;
  std::size_t reached = 0;
  for (const IterationRecord& r : run.iterations) reached += r.episode == last && r.success ? 1 : 0;
  ASSERT_EQ(run.last_climb.size(), 1 + reached);
  ClimbingMdp mdp(model, wall, parameters.climbing);
  EXPECT_EQ(run.last_climb.front(), mdp.start_posture());
  BodyData data(model);
  forward_kinematics(model, data, run.last_climb.back());
  EXPECT_GE(centre_of_mass(model, data).z(), wall.finish_height);
  forward_kinematics(model, data, run.last_climb[run.last_climb.size() - 2]);
  EXPECT_LT(centre_of_mass(model, data).z(), wall.finish_height);
}

TEST(LearningRun, PrioritizedSweepingSpendsAtMostTheBudget) {
  const BodyModel& model = testing::human_model();
  LearningParameters parameters;
  parameters.iterations = 300;
  parameters.dyna.planner = Planner::Prioritized;
  const RunResult run = run_learning(model, generate_random_wall(3), parameters, 5);
  EXPECT_GT(run.planning_updates, 0u);
  EXPECT_LE(run.planning_updates, 300u * 50u);
  parameters.dyna.planner = Planner::Uniform;
  EXPECT_EQ(run_learning(model, generate_random_wall(3), parameters, 5).planning_updates, 300u * 50u);
}

}  // namespace
}  // namespace crux
