#include "learning/action_selection.hpp"

#include <gtest/gtest.h>

#include <set>

namespace crux {
namespace {

constexpr StateCouple kState{5, 50};

// Candidates: wall actions 0..3 in grid tiles 10, 10, 11, none; hold 1 represents tile
// 10, hold 2 tile 11.
const ActionCandidate kCandidates[4] = {{0, 10, false}, {1, 10, true}, {2, 11, true}, {3, kNoAction, false}};

TEST(ActionSelection, WGreedyWhenTheBestWallActionWasTaken) {
  QTable wall(4), grid(40);
  wall.set_value(5, 2, 3.0);
  wall.add_visit(5, 2);
  Random random(1);
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, random);
  EXPECT_EQ(c.regime, Regime::WGreedy);
  EXPECT_EQ(c.candidate, 2u);
}

TEST(ActionSelection, GGreedyWhenTheBestWallActionIsNewButTheBestGridActionWasTaken) {
  QTable wall(4), grid(40);
  wall.set_value(5, 0, 1.0);  // best for Q_wall, never taken
  grid.set_value(50, 10, 7.0);
  grid.add_visit(50, 10);
  Random random(1);
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, random);
  EXPECT_EQ(c.regime, Regime::GGreedy);
  EXPECT_EQ(c.candidate, 1u) << "tile 10 maps back to its representative, hold 1";
}

TEST(ActionSelection, RandomWhenNeitherBestWasTaken) {
  QTable wall(4), grid(40);
  wall.set_value(5, 0, 1.0);
  grid.set_value(50, 11, 1.0);
  Random random(1);
  std::set<std::size_t> seen;
  for (int i = 0; i < 200; ++i) {
    const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, random);
    EXPECT_EQ(c.regime, Regime::Random);
    seen.insert(c.candidate);
  }
  EXPECT_EQ(seen.size(), 4u) << "random covers every possible action, inside the grid or not";
}

TEST(ActionSelection, EpsilonOneAlwaysExplores) {
  QTable wall(4), grid(40);
  wall.set_value(5, 2, 3.0);
  wall.add_visit(5, 2);
  grid.set_value(50, 10, 7.0);
  grid.add_visit(50, 10);
  Random random(2);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 1.0, random).regime, Regime::Random);
}

TEST(ActionSelection, EpsilonSharesMatchTheAlgorithm) {
  // With both bests taken: P(w) = 1 - eps, P(g) = eps (1 - eps), P(random) = eps^2.
  QTable wall(4), grid(40);
  wall.set_value(5, 2, 3.0);
  wall.add_visit(5, 2);
  grid.set_value(50, 10, 7.0);
  grid.add_visit(50, 10);
  constexpr std::uint64_t seed = 3;
  Random random(seed);
  int counts[kRegimeCount] = {0, 0, 0};
  constexpr int n = 100000;
  for (int i = 0; i < n; ++i) ++counts[static_cast<int>(select_action(wall, grid, kState, kCandidates, 0.3, random).regime)];
  EXPECT_NEAR(counts[0] / double(n), 0.7, 0.01) << "seed " << seed;
  EXPECT_NEAR(counts[1] / double(n), 0.21, 0.01);
  EXPECT_NEAR(counts[2] / double(n), 0.09, 0.01);
}

TEST(ActionSelection, TiesAreBrokenUniformly) {
  QTable wall(4), grid(40);
  for (const ActionCode a : {1, 2}) {
    wall.set_value(5, a, 4.0);
    wall.add_visit(5, a);
  }
  Random random(4);
  int first = 0;
  for (int i = 0; i < 10000; ++i) first += select_action(wall, grid, kState, kCandidates, 0.0, random).candidate == 1;
  EXPECT_NEAR(first / 10000.0, 0.5, 0.03);
}

}  // namespace
}  // namespace crux
