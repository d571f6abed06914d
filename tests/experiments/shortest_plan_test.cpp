#include "experiments/shortest_plan.hpp"

#include <gtest/gtest.h>

#include "configurations/reachability.hpp"
#include "support/planning_walls.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

// The plan must be a real climb: replaying its holds in the MDP finishes after exactly
// `length` actions, each reachable.
TEST(ShortestPlan, ReplaysAsAClimbOfItsLength) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);
  const ClimbingParameters parameters;
  const Plan plan = shortest_plan(model, wall, parameters);
  ASSERT_TRUE(plan.found);
  ASSERT_EQ(static_cast<int>(plan.hold_ids.size()), plan.length);
  ASSERT_EQ(static_cast<int>(plan.postures.size()), plan.length + 1) << "the start, then each action's stance";
  ClimbingMdp mdp(model, wall, parameters);
  EXPECT_EQ(plan.postures.front(), mdp.start_posture());
  for (int i = 0; i < plan.length; ++i) {
    EXPECT_EQ(mdp.configuration().free_limb(), plan.limbs[i]);
    const StepOutcome o = mdp.step(wall.index_of(plan.hold_ids[i]));
    ASSERT_TRUE(o.reached) << "action " << i;
    EXPECT_EQ(*o.posture, plan.postures[i + 1]) << "action " << i << ": the MDP's own stance";
    EXPECT_EQ(o.finished, i == plan.length - 1) << "action " << i;
  }
}

TEST(ShortestPlan, IsShortest) {
  // With the finishing height just above the start, one reachable move may finish;
  // breadth-first order must then return 1, and never more than a longer finish height.
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(3);
  const ClimbingParameters parameters;
  const Plan full = shortest_plan(model, wall, parameters);
  wall.finish_height = 1.0;
  const Plan low = shortest_plan(model, wall, parameters);
  ASSERT_TRUE(low.found);
  EXPECT_LE(low.length, full.length);
  EXPECT_GE(low.length, 1);
}

TEST(ShortestPlan, StopsAtItsBudgetOfSolves) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(3);  // its climb takes about 34000 solves to find
  PlanParameters settings;
  settings.max_ik_solves = 1000;
  const Plan plan = shortest_plan(model, wall, ClimbingParameters{}, settings);
  EXPECT_FALSE(plan.found);
  EXPECT_TRUE(plan.stopped_at_limit);
  EXPECT_EQ(plan.ik_solves, 1000u);
  EXPECT_TRUE(plan.hold_ids.empty());
}

TEST(ShortestPlan, AnExhaustedSearchIsNotALimit) {
  // Sixteen holds and a finish out of reach: every state is explored, within the budget.
  const BodyModel& model = testing::human_model();
  RandomWallParameters small;
  small.columns = 3;
  small.rows = 3;
  small.finish_height = 100.0;
  const Plan plan = shortest_plan(model, generate_random_wall(5, small), ClimbingParameters{});
  EXPECT_FALSE(plan.found);
  EXPECT_FALSE(plan.stopped_at_limit);
  EXPECT_GT(plan.expanded_states, 1u);
  EXPECT_LT(plan.ik_solves, static_cast<std::size_t>(PlanParameters{}.max_ik_solves));
}

using testing::low_finish_wall;
using testing::static_rules;

// Under the static model a move may reach a stance that holds while a posture on the way
// does not; checking the way (the replay's samples, on the three holds kept) refuses such
// moves, so the search can only find longer climbs, and on this wall it does (4 moves
// without the check, 7 with it: the cheapest such wall of seeds 1-12 with a finish at
// 1.2, 1.4 or 1.5 m, since the check costs ten times the search under the sanitizers).
TEST(ShortestPlan, CheckingTheMovesOnTheWayRefusesSomeAndLengthensTheClimb) {
  const BodyModel& model = testing::human_model();
  const Wall wall = low_finish_wall();
  const ClimbingParameters parameters = static_rules();
  const Plan stances_only = shortest_plan(model, wall, parameters);
  PlanParameters checked;
  checked.check_moves = true;
  const Plan on_the_way = shortest_plan(model, wall, parameters, checked);
  ASSERT_TRUE(stances_only.found);
  ASSERT_TRUE(on_the_way.found);
  EXPECT_FALSE(stances_only.checked_moves);
  EXPECT_EQ(stances_only.moves_refused_on_the_way, 0u);
  EXPECT_TRUE(on_the_way.checked_moves);
  EXPECT_GT(on_the_way.moves_refused_on_the_way, 0u);
  EXPECT_GT(on_the_way.length, stances_only.length);
}

// The dynamic model's repair refuses a move that failed in MuJoCo: the search never takes
// it again, and finds the next shortest climb without it.
TEST(ShortestPlan, ARefusedMoveIsNeverTaken) {
  const BodyModel& model = testing::human_model();
  const Wall wall = low_finish_wall();
  const ClimbingParameters parameters = static_rules();
  const Plan first = shortest_plan(model, wall, parameters);
  ASSERT_TRUE(first.found);
  const HoldConfiguration start = start_configuration(wall).with(Limb::RightHand, kFree);
  const RefusedMoves refused{{encode(start, wall.hold_count()), wall.index_of(first.hold_ids[0])}};
  const Plan again = shortest_plan(model, wall, parameters, {}, refused);
  ASSERT_TRUE(again.found);
  EXPECT_NE(again.hold_ids[0], first.hold_ids[0]) << "the right hand's first move from the start was refused";
  EXPECT_GE(again.length, first.length);
}

}  // namespace
}  // namespace crux
