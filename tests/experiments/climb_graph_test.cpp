#include "experiments/climb_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "configurations/possible_actions.hpp"
#include "experiments/shortest_plan.hpp"
#include "support/planning_walls.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::low_finish_wall;
using testing::static_rules;

constexpr int kWholeWall = 1000000;

const GraphMove* move_to(const GraphState& state, int hold) {
  const auto it =
      std::find_if(state.moves.begin(), state.moves.end(), [&](const GraphMove& m) { return m.hold == hold; });
  return it == state.moves.end() ? nullptr : &*it;
}

TEST(ClimbGraph, TheStartsDistanceIsTheShortestPlansLength) {
  const BodyModel& model = testing::human_model();
  const Wall wall = low_finish_wall();
  for (const ClimbingParameters& parameters : {ClimbingParameters{}, static_rules()}) {
    const ClimbGraph graph = explore_climbs(model, wall, parameters, kWholeWall);
    const Plan plan = shortest_plan(model, wall, parameters);
    ASSERT_FALSE(graph.stopped_at_limit);
    ASSERT_TRUE(plan.found);
    EXPECT_EQ(graph.states[0].distance, plan.length);
    EXPECT_EQ(graph.states[0].configuration, start_configuration(wall).with(Limb::RightHand, kFree));
  }
}

// Every state on an optimal climb, in the MDP: each possible action is a move of the graph
// exactly when the MDP reaches it, to the graph's state; the optimal moves finish in the
// state's distance.
void expect_moves_as_the_mdp(const ClimbingParameters& parameters) {
  const BodyModel& model = testing::human_model();
  const Wall wall = low_finish_wall();
  const ClimbGraph graph = explore_climbs(model, wall, parameters, kWholeWall);
  ClimbingMdp mdp(model, wall, parameters);
  std::vector<int> route;
  int state = 0;
  while (true) {
    const GraphState& at = graph.states[state];
    ASSERT_EQ(mdp.configuration(), at.configuration);
    std::vector<int> possible(wall.hold_count());
    const int count = possible_actions(wall, at.configuration, parameters.filter, possible);
    for (int i = 0; i < count; ++i) {
      mdp.reset();
      for (const int hold : route) mdp.step(hold);
      const StepOutcome outcome = mdp.step(possible[i]);
      const GraphMove* move = move_to(at, possible[i]);
      ASSERT_EQ(outcome.reached, move != nullptr) << "hold " << possible[i] << " after " << route.size() << " moves";
      if (move == nullptr) continue;
      EXPECT_EQ(outcome.finished, move->target == kFinishState);
      if (!outcome.finished) {
        EXPECT_EQ(mdp.configuration(), graph.states[move->target].configuration);
      }
    }
    const std::vector<int> best = optimal_holds(graph, at);
    ASSERT_FALSE(best.empty());
    const GraphMove* next = move_to(at, best.front());
    route.push_back(next->hold);
    if (next->target == kFinishState) break;
    EXPECT_EQ(graph.states[next->target].distance, at.distance - 1);
    state = next->target;
    mdp.reset();
    for (const int hold : route) mdp.step(hold);
  }
  EXPECT_EQ(static_cast<int>(route.size()), graph.states[0].distance);
}

TEST(ClimbGraph, MovesAsTheMdpKinematic) { expect_moves_as_the_mdp(ClimbingParameters{}); }
TEST(ClimbGraph, MovesAsTheMdpStatic) { expect_moves_as_the_mdp(static_rules()); }

// Every state of a whole graph, dead ends and detours included: its distance is one more
// than the nearest its moves lead to (0 after a finish), and none exactly when no move
// leads to the finish or to a state with a distance.
TEST(ClimbGraph, EachDistanceIsOneMoreThanTheNearestMovesAfterIt) {
  const ClimbGraph graph = explore_climbs(testing::human_model(), low_finish_wall(), static_rules(), kWholeWall);
  ASSERT_FALSE(graph.stopped_at_limit);
  EXPECT_EQ(graph.expanded_states, graph.states.size());
  int dead_ends = 0;
  for (const GraphState& state : graph.states) {
    int nearest = kNoRoute;
    for (const GraphMove& move : state.moves) {
      const int after = move.target == kFinishState ? 0 : graph.states[move.target].distance;
      if (after != kNoRoute && (nearest == kNoRoute || after < nearest)) nearest = after;
    }
    EXPECT_EQ(state.distance, nearest == kNoRoute ? kNoRoute : nearest + 1);
    dead_ends += state.distance == kNoRoute;
  }
  EXPECT_GT(dead_ends, 0) << "the static model leaves stances from which no climb finishes";
}

TEST(ClimbGraph, OptimalHoldsAreTheMovesOneStepNearer) {
  ClimbGraph graph;
  graph.states.resize(4);
  // 0 -> 1 (hold 5) -> finish (hold 6); 0 -> 2 (hold 7) -> finish (hold 8); 0 -> 3 (hold 9), a dead end;
  // 0 -> finish is not offered.
  graph.states[0].moves = {{5, 1}, {7, 2}, {9, 3}};
  graph.states[1].moves = {{6, kFinishState}};
  graph.states[2].moves = {{4, 0}, {8, kFinishState}};
  graph.states[0].distance = 2;
  graph.states[1].distance = 1;
  graph.states[2].distance = 1;
  EXPECT_EQ(optimal_holds(graph, graph.states[0]), (std::vector<int>{5, 7}));
  EXPECT_EQ(optimal_holds(graph, graph.states[2]), (std::vector<int>{8}));
  EXPECT_TRUE(optimal_holds(graph, graph.states[3]).empty());
}

// Also the sanitized build's case of the search and of the distances (the whole graphs are
// release only): within 2000 solves the low wall's graph already has finishing moves.
TEST(ClimbGraph, StopsAtItsBudgetOfSolves) {
  const ClimbGraph graph = explore_climbs(testing::human_model(), low_finish_wall(), ClimbingParameters{}, 2000);
  EXPECT_TRUE(graph.stopped_at_limit);
  EXPECT_EQ(graph.ik_solves, 2000u);
  EXPECT_LT(graph.expanded_states, graph.states.size()) << "states found but never explored";
  const auto with_distance = std::count_if(graph.states.begin(), graph.states.end(),
                                           [](const GraphState& state) { return state.distance != kNoRoute; });
  EXPECT_GT(with_distance, 1) << "the distances' backward search ran";
}

}  // namespace
}  // namespace crux
