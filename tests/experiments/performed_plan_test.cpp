#include "experiments/performed_plan.hpp"

#include <gtest/gtest.h>

#include "support/jug_ladder.hpp"

namespace crux {
namespace {

// The jug ladder with its finish just below the centre of mass of the stance with the
// right hand on the jug: one move, the right hand's, climbs it under the dynamic model.
struct OneMoveLadder {
  testing::JugLadder ladder;
  ClimbingParameters parameters;

  OneMoveLadder() {
    ladder.finish_after_one_move();
    parameters.reachability = ladder.reach;
    parameters.physics = ladder.physics;
    parameters.physics.model = PhysicsModel::Dynamic;
  }
};

PlanParameters replans(int cap) {
  PlanParameters search;
  search.max_replans = cap;
  return search;
}

TEST(PerformedPlan, APlanPerformedToTheTopNeedsNoReplan) {
  const OneMoveLadder one;
  const PerformedPlan performed = performed_plan(testing::human_model(), one.ladder.wall, one.parameters, replans(5));
  ASSERT_TRUE(performed.plan.found);
  EXPECT_EQ(performed.plan.hold_ids, std::vector<int>{5}) << "the jug (id 5, index 4)";
  EXPECT_EQ(performed.plan.physics_model, PhysicsModel::Dynamic);
  EXPECT_TRUE(performed.performed());
  EXPECT_EQ(performed.replans, 0);
  EXPECT_EQ(performed.moves_simulated, 1);
  EXPECT_TRUE(performed.failed_moves.empty());
}

// No time to settle after a move's path: every move times out in MuJoCo, whatever the
// static model says of its stances.
ClimbingParameters no_settling(ClimbingParameters parameters) {
  parameters.perform.move.settle_time_s = 0.0;
  return parameters;
}

// Each move that fails is refused, and the wall planned again without it, until no plan
// remains: here once the right hand's every move from the start has failed.
TEST(PerformedPlan, AMoveThatFailsIsRefusedAndTheWallPlannedAgain) {
  const OneMoveLadder one;
  const PerformedPlan performed =
      performed_plan(testing::human_model(), one.ladder.wall, no_settling(one.parameters), replans(5));
  ASSERT_GE(performed.failed_moves.size(), 1u);
  const FailedMove& first = performed.failed_moves[0];
  EXPECT_EQ(first.plan, 0);
  EXPECT_EQ(first.move, 0);
  EXPECT_EQ(first.limb, Limb::RightHand);
  EXPECT_EQ(first.hold_id, 5) << "the first plan's one move";
  for (std::size_t k = 0; k < performed.failed_moves.size(); ++k) {
    EXPECT_EQ(performed.failed_moves[k].plan, static_cast<int>(k)) << "one failed move per plan";
    EXPECT_EQ(performed.failed_moves[k].cause, MoveFailure::TimedOut);
    for (std::size_t j = 0; j < k; ++j) {
      const bool same = performed.failed_moves[j].move == performed.failed_moves[k].move &&
                        performed.failed_moves[j].hold_id == performed.failed_moves[k].hold_id &&
                        performed.failed_moves[j].limb == performed.failed_moves[k].limb;
      EXPECT_FALSE(same && performed.failed_moves[k].move == 0) << "a refused move is not tried again";
    }
  }
  EXPECT_FALSE(performed.plan.found) << "no way up remains";
  EXPECT_FALSE(performed.climb.has_value());
  EXPECT_FALSE(performed.replan_cap_reached);
  EXPECT_EQ(performed.replans, static_cast<int>(performed.failed_moves.size()));
  EXPECT_GE(performed.moves_simulated, static_cast<int>(performed.failed_moves.size()));
}

TEST(PerformedPlan, TheCapOnReplansStopsTheRepair) {
  const OneMoveLadder one;
  const PerformedPlan performed =
      performed_plan(testing::human_model(), one.ladder.wall, no_settling(one.parameters), replans(0));
  EXPECT_TRUE(performed.replan_cap_reached);
  EXPECT_EQ(performed.replans, 0);
  EXPECT_EQ(performed.failed_moves.size(), 1u);
  ASSERT_TRUE(performed.climb.has_value()) << "the plan performed, and failed";
  EXPECT_EQ(performed.climb->cause(), MoveFailure::TimedOut);
  EXPECT_FALSE(performed.performed());
}

// The static model performs its plan as planned, failed or not.
TEST(PerformedPlan, UnderTheStaticModelThePlanIsPerformedOnce) {
  OneMoveLadder one;
  one.parameters.physics.model = PhysicsModel::Static;
  const PerformedPlan performed =
      performed_plan(testing::human_model(), one.ladder.wall, no_settling(one.parameters), replans(5));
  ASSERT_TRUE(performed.climb.has_value());
  EXPECT_FALSE(performed.performed());
  EXPECT_EQ(performed.replans, 0);
  EXPECT_TRUE(performed.failed_moves.empty()) << "nothing refused: no repair";
  EXPECT_FALSE(performed.replan_cap_reached);
}

TEST(PerformedPlan, TheClimbToPerformIsThePlansStancesAndHoldIndices) {
  Plan plan;
  plan.postures = {Posture::Zero(), Posture::Ones()};
  plan.limbs = {Limb::LeftFoot};
  plan.hold_ids = {5};
  const ClimbToPerform climb = climb_to_perform(testing::JugLadder().wall, plan);
  EXPECT_EQ(climb.stances, plan.postures);
  EXPECT_EQ(climb.limbs, plan.limbs);
  EXPECT_EQ(climb.holds, std::vector<int>{4});
}

}  // namespace
}  // namespace crux
