#include "outputs/figure_tables.hpp"

#include <gtest/gtest.h>

#include "agent_space/agent_descriptor.hpp"

namespace crux {
namespace {

RunResult run_of(std::initializer_list<Regime> regimes, std::vector<int> episodes) {
  RunResult run;
  for (const Regime r : regimes) {
    IterationRecord record;
    record.regime = r;
    run.iterations.push_back(record);
  }
  run.episode_lengths = std::move(episodes);
  run.q_grid = QTable(GridParameters{}.tile_count());
  return run;
}

TEST(FigureTables, Fig3CountsActionsPerRegimeCumulativelyAveragedOverRuns) {
  ExperimentResult result;
  auto& training = result.conditions[static_cast<int>(Condition::Training)];
  training.runs.push_back(run_of({Regime::Random, Regime::WGreedy}, {2}));
  training.runs.push_back(run_of({Regime::Random, Regime::Random}, {}));
  // By hand: iteration 1 has 2 random actions over 2 runs (1.0); iteration 2 adds one
  // w-greedy and one random: w 0.5, random 1.5.
  EXPECT_EQ(fig3_csv(result, 2),
            "condition,iteration,w_greedy,g_greedy,random\n"
            "training,1,0,0,1\n"
            "training,2,0.5,0,1.5\n");
  EXPECT_EQ(fig4_csv(result), "condition,run,episode,length\ntraining,0,0,2\n");
}

// A mean is written as the shortest text that reads back to it: 0.3333333333333333, not
// the 17 digits 0.33333333333333331.
TEST(FigureTables, MeansAreTheShortestTextThatReadsBack) {
  ExperimentResult result;
  auto& training = result.conditions[static_cast<int>(Condition::Training)];
  training.runs = {run_of({Regime::WGreedy}, {}), run_of({Regime::Random}, {}), run_of({Regime::Random}, {})};
  EXPECT_EQ(fig3_csv(result, 1),
            "condition,iteration,w_greedy,g_greedy,random\n"
            "training,1,0.3333333333333333,0,0.6666666666666666\n");
}

TEST(FigureTables, QGridMapsSumEachFreeLimbsStatesPerTile) {
  const GridParameters grid;
  QTable q(grid.tile_count());
  AgentState left{};
  left.free_limb = Limb::LeftHand;
  AgentState left_elsewhere = left;
  left_elsewhere.held_tiles[0] = 3;
  AgentState right_foot{};
  right_foot.free_limb = Limb::RightFoot;
  q.set_value(encode(left, grid), 4, 2.0);
  q.set_value(encode(left_elsewhere, grid), 4, 3.0);
  q.set_value(encode(right_foot, grid), 0, -1.0);
  const auto maps = q_grid_maps(q, grid);
  EXPECT_EQ(maps[4][static_cast<int>(Limb::LeftHand)], 5.0);
  EXPECT_EQ(maps[0][static_cast<int>(Limb::RightFoot)], -1.0);
  EXPECT_EQ(maps[4][static_cast<int>(Limb::RightHand)], 0.0);
}

}  // namespace
}  // namespace crux
