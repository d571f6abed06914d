#include "learning/action_selection.hpp"

#include <gtest/gtest.h>

#include <set>

namespace crux {
namespace {

constexpr StateCouple kState{5, 50};

// `action` taken in `state`, with value `value`.
void taken(QTable& table, StateCode state, ActionCode action, double value) {
  table.set_value(state, action, value);
  table.add_visit(state, action);
}

// Candidates: wall actions 0..3 in grid tiles 10, 10, 11, none; hold 1 represents tile
// 10, hold 2 tile 11.
const ActionCandidate kCandidates[4] = {{0, 10, false}, {1, 10, true}, {2, 11, true}, {3, kNoAction, false}};

TEST(ActionSelection, WGreedyWhenTheBestWallActionWasTaken) {
  QTable wall(4), grid(40);
  taken(wall, 5, 2, 3.0);
  const SelectionStreams streams(1);
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, 0);
  EXPECT_EQ(c.regime, Regime::WGreedy);
  EXPECT_EQ(c.candidate, 2u);
}

TEST(ActionSelection, GGreedyWhenTheBestWallActionIsNewButTheBestGridActionWasTaken) {
  QTable wall(4), grid(40);
  wall.set_value(5, 0, 1.0);  // best for Q_wall, never taken
  taken(grid, 50, 10, 7.0);
  const SelectionStreams streams(1);
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, 0);
  EXPECT_EQ(c.regime, Regime::GGreedy);
  EXPECT_EQ(c.candidate, 1u) << "tile 10 maps back to its representative, hold 1";
}

TEST(ActionSelection, RandomWhenNeitherBestWasTaken) {
  QTable wall(4), grid(40);
  wall.set_value(5, 0, 1.0);
  grid.set_value(50, 11, 1.0);
  const SelectionStreams streams(1);
  std::set<std::size_t> seen;
  for (int i = 0; i < 200; ++i) {
    const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, i);
    EXPECT_EQ(c.regime, Regime::Random);
    seen.insert(c.candidate);
  }
  EXPECT_EQ(seen.size(), 4u) << "random covers every possible action, inside the grid or not";
}

TEST(ActionSelection, EpsilonOneAlwaysExplores) {
  QTable wall(4), grid(40);
  taken(wall, 5, 2, 3.0);
  taken(grid, 50, 10, 7.0);
  const SelectionStreams streams(2);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 1.0, streams, i).regime, Regime::Random);
  }
}

TEST(ActionSelection, EpsilonSharesMatchTheAlgorithm) {
  // With both bests taken: P(w) = 1 - eps, P(g) = eps (1 - eps), P(random) = eps^2.
  QTable wall(4), grid(40);
  taken(wall, 5, 2, 3.0);
  taken(grid, 50, 10, 7.0);
  constexpr std::uint64_t seed = 3;
  const SelectionStreams streams(seed);
  int counts[kRegimeCount] = {0, 0, 0};
  constexpr int n = 100000;
  for (int i = 0; i < n; ++i) {
    ++counts[static_cast<int>(select_action(wall, grid, kState, kCandidates, 0.3, streams, i).regime)];
  }
  EXPECT_NEAR(counts[0] / double(n), 0.7, 0.01) << "seed " << seed;
  EXPECT_NEAR(counts[1] / double(n), 0.21, 0.01);
  EXPECT_NEAR(counts[2] / double(n), 0.09, 0.01);
}

TEST(ActionSelection, TiesAreBrokenUniformly) {
  QTable wall(4), grid(40);
  for (const ActionCode a : {1, 2}) {
    taken(wall, 5, a, 4.0);
  }
  constexpr std::uint64_t seed = 4;
  const SelectionStreams streams(seed);
  int first = 0;
  for (int i = 0; i < 10000; ++i)
    first += select_action(wall, grid, kState, kCandidates, 0.0, streams, i).candidate == 1;
  EXPECT_NEAR(first / 10000.0, 0.5, 0.03) << "seed " << seed;
}

TEST(ActionSelection, RandomActionIsUniformOverTheCandidates) {
  QTable wall(4), grid(40);
  constexpr std::uint64_t seed = 5;
  const SelectionStreams streams(seed);
  int counts[4] = {0, 0, 0, 0};
  constexpr int n = 40000;
  for (int i = 0; i < n; ++i) ++counts[select_action(wall, grid, kState, kCandidates, 1.0, streams, i).candidate];
  for (const int count : counts) EXPECT_NEAR(count / double(n), 0.25, 0.01) << "seed " << seed;
}

// Common random numbers: the random action at an iteration does not depend on the order
// in which the candidates are listed.
TEST(ActionSelection, TheRandomActionDependsOnlyOnWhatIsOffered) {
  QTable wall(4), grid(40);
  const SelectionStreams streams(6);
  const ActionCandidate reversed[4] = {kCandidates[3], kCandidates[2], kCandidates[1], kCandidates[0]};
  for (std::uint64_t i = 0; i < 200; ++i) {
    const ActionChoice a = select_action(wall, grid, kState, kCandidates, 1.0, streams, i);
    const ActionChoice b = select_action(wall, grid, kState, reversed, 1.0, streams, i);
    EXPECT_EQ(kCandidates[a.candidate].wall, reversed[b.candidate].wall) << "iteration " << i;
  }
}

TEST(ActionSelection, ATieBetweenTheSameActionsGoesTheSameWayWhateverElseIsOffered) {
  // Holds 1 and 2 tie for Q_wall in both runs; run 2 also offers hold 0 at a lower value.
  QTable wall(4), grid(40);
  for (const ActionCode a : {1, 2}) taken(wall, 5, a, 4.0);
  wall.set_value(5, 0, 1.0);
  const ActionCandidate two[2] = {kCandidates[1], kCandidates[2]};
  const SelectionStreams streams(7);
  for (std::uint64_t i = 0; i < 100; ++i) {
    const ActionChoice a = select_action(wall, grid, kState, two, 0.0, streams, i);
    const ActionChoice b = select_action(wall, grid, kState, kCandidates, 0.0, streams, i);
    EXPECT_EQ(two[a.candidate].wall, kCandidates[b.candidate].wall) << "iteration " << i;
  }
}

TEST(ActionSelection, AnExcludedCandidateIsPassedOverByGGreedyOnly) {
  QTable wall(4), grid(40);
  wall.set_value(5, 0, 1.0);  // best for Q_wall, never taken
  taken(grid, 50, 10, 7.0);
  taken(grid, 50, 11, 2.0);
  const SelectionStreams streams(1);
  const char excluded[4] = {0, 1, 0, 0};  // tile 10's representative
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, {true, true, excluded});
  EXPECT_EQ(c.regime, Regime::GGreedy);
  EXPECT_EQ(c.candidate, 2u) << "the next best tile, 11, through its representative";
  wall.add_visit(5, 1);
  wall.set_value(5, 1, 5.0);
  const ActionChoice w = select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, {true, true, excluded});
  EXPECT_EQ(w.regime, Regime::WGreedy) << "w-greedy ignores the exclusion";
  EXPECT_EQ(w.candidate, 1u);
}

TEST(ActionSelection, WithoutTheTakenTestAndGGreedyItIsEpsilonGreedyOnQWall) {
  QTable wall(4), grid(40);
  wall.set_value(5, 3, 2.0);  // never taken
  taken(grid, 50, 10, 7.0);
  const SelectionStreams streams(4);
  const SelectionRule rule{false, false, {}};
  int greedy = 0, random = 0;
  for (int i = 0; i < 2000; ++i) {
    const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.25, streams, i, rule);
    ASSERT_NE(c.regime, Regime::GGreedy) << "iteration " << i;
    if (c.regime == Regime::WGreedy) {
      EXPECT_EQ(c.candidate, 3u);
      ++greedy;
    } else {
      ++random;
    }
  }
  EXPECT_NEAR(random / 2000.0, 0.25, 0.03) << "stream seed 4";
  EXPECT_GT(greedy, 0);
}

TEST(ActionSelection, GridTakenOnlyPicksTheBestTakenTileOverABetterUntakenOne) {
  QTable wall(4), grid(40);
  grid.set_value(50, 10, 7.0);  // the best value, but never taken
  taken(grid, 50, 11, -3.0);
  const SelectionStreams streams(1);
  EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 0.0, streams, 0).regime, Regime::Random)
      << "Algorithm 3: the best tile was never taken";
  SelectionRule rule;
  rule.grid_taken_only = true;
  const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, rule);
  EXPECT_EQ(c.regime, Regime::GGreedy);
  EXPECT_EQ(c.candidate, 2u) << "tile 11, the only one taken";
}

// The ordered mode's rule: epsilon-greedy on Q_wall, w-greedy's ties broken by a table.
SelectionRule ordered_by(const QTable& order) {
  SelectionRule rule{false, false, {}};
  rule.wall_tie_order = &order;
  return rule;
}

// Every Q_wall value is 0 (all four untried): the tie goes to hold 2, whose tile 11 has
// the largest taken value of the order (-1 against tile 10's -5), at every iteration.
TEST(ActionSelection, TheTieOrderPicksTheTiedRepresentativeWithTheBestTakenValue) {
  QTable wall(4), grid(40), order(40);
  taken(order, 50, 10, -5.0);
  taken(order, 50, 11, -1.0);
  const SelectionStreams streams(1);
  std::set<std::size_t> unordered;
  for (int i = 0; i < 100; ++i) {
    const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, i, ordered_by(order));
    EXPECT_EQ(c.regime, Regime::WGreedy);
    EXPECT_EQ(c.candidate, 2u) << "iteration " << i;
    unordered.insert(select_action(wall, grid, kState, kCandidates, 0.0, streams, i, {false, false, {}}).candidate);
  }
  EXPECT_EQ(unordered.size(), 4u) << "without the order the tie is random";
}

// Tiles 10 and 11 tie in the order too: the random tie-break chooses between their
// representatives, holds 1 and 2, and never a hold the order does not rank.
TEST(ActionSelection, TiesOfTheTieOrderGoToTheRandomTieBreak) {
  QTable wall(4), grid(40), order(40);
  for (const ActionCode tile : {10, 11}) {
    taken(order, 50, tile, -1.0);
  }
  const SelectionStreams streams(1);
  std::set<std::size_t> seen;
  for (int i = 0; i < 100; ++i) {
    seen.insert(select_action(wall, grid, kState, kCandidates, 0.0, streams, i, ordered_by(order)).candidate);
  }
  EXPECT_EQ(seen, (std::set<std::size_t>{1, 2}));
}

// Hold 2 was tried (Q_wall -2) and hold 1 was not (0): hold 1 stays Q_wall's best, whatever
// the order says of tile 11 (+9), and a tried move of higher value wins over untried ones.
TEST(ActionSelection, TheTieOrderNeverOverturnsQWall) {
  QTable wall(4), grid(40), order(40);
  taken(wall, 5, 2, -2.0);
  taken(wall, 5, 0, -3.0);
  taken(wall, 5, 3, -4.0);
  taken(order, 50, 11, 9.0);
  taken(order, 50, 10, -5.0);
  const SelectionStreams streams(1);
  EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, ordered_by(order)).candidate, 1u);
  wall.set_value(5, 3, 0.5);  // a tried move above the untried 0
  EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, ordered_by(order)).candidate, 3u);
}

// Tile 10's 7 was never taken, so it does not count: tile 11's taken -3 orders the tie.
TEST(ActionSelection, AnUntakenValueOfTheTieOrderDoesNotCount) {
  QTable wall(4), grid(40), order(40);
  order.set_value(50, 10, 7.0);
  taken(order, 50, 11, -3.0);
  const SelectionStreams streams(1);
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 0.0, streams, i, ordered_by(order)).candidate, 2u);
  }
}

// An empty order (ordered's control) chooses as epsilon-greedy on Q_wall (seeded's
// control) on the same streams, action and regime, even with a Q_grid that has learnt.
TEST(ActionSelection, AnEmptyTieOrderChoosesAsEpsilonGreedyOnQWall) {
  QTable wall(4), grid(40), order(40);
  taken(wall, 5, 2, -2.0);
  taken(grid, 50, 10, 7.0);
  const SelectionStreams streams(6);
  for (int i = 0; i < 2000; ++i) {
    const ActionChoice ordered = select_action(wall, grid, kState, kCandidates, 0.25, streams, i, ordered_by(order));
    const ActionChoice plain = select_action(wall, grid, kState, kCandidates, 0.25, streams, i, {false, false, {}});
    ASSERT_EQ(ordered.candidate, plain.candidate) << "iteration " << i;
    ASSERT_EQ(ordered.regime, plain.regime) << "iteration " << i;
  }
}

// The network mode's rule: epsilon-greedy on Q_wall, w-greedy's ties broken by scores.
SelectionRule scored_by(const std::vector<double>& scores) {
  SelectionRule rule{false, false, {}};
  rule.wall_tie_scores = scores;
  return rule;
}

// All four untried (Q_wall 0): the tie goes to candidate 3, the highest score, at every
// iteration; with candidates 1 and 3 scored equal, the random tie-break picks between them.
TEST(ActionSelection, TieScoresPickTheTiedCandidateWithTheHighestScore) {
  QTable wall(4), grid(40);
  const SelectionStreams streams(1);
  const std::vector<double> scores{0.5, -1.0, 0.2, 2.5};
  std::set<std::size_t> between_equals;
  for (int i = 0; i < 100; ++i) {
    const ActionChoice c = select_action(wall, grid, kState, kCandidates, 0.0, streams, i, scored_by(scores));
    EXPECT_EQ(c.regime, Regime::WGreedy);
    EXPECT_EQ(c.candidate, 3u) << "iteration " << i;
    between_equals.insert(
        select_action(wall, grid, kState, kCandidates, 0.0, streams, i, scored_by({0.0, 1.0, -1.0, 1.0})).candidate);
  }
  EXPECT_EQ(between_equals, (std::set<std::size_t>{1, 3}));
}

// Hold 1 untried (0) is Q_wall's best over tried holds 0, 2 and 3, whatever their scores.
TEST(ActionSelection, TieScoresNeverOverturnQWall) {
  QTable wall(4), grid(40);
  taken(wall, 5, 0, -3.0);
  taken(wall, 5, 2, -2.0);
  taken(wall, 5, 3, -4.0);
  const SelectionStreams streams(1);
  const std::vector<double> scores{9.0, -9.0, 9.0, 9.0};
  EXPECT_EQ(select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, scored_by(scores)).candidate, 1u);
  const std::vector<double> too_few{1.0, 2.0};
  EXPECT_THROW(select_action(wall, grid, kState, kCandidates, 0.0, streams, 0, scored_by(too_few)),
               std::invalid_argument);
}

}  // namespace
}  // namespace crux
