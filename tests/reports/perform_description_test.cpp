#include "reports/perform_description.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

Wall perform_wall() {
  Wall wall;
  wall.name = "w";
  return wall;
}

// A plan of two moves whose second hit the wall, after one replan.
PerformedPlan second_move_failed() {
  PerformedPlan performed;
  performed.plan.found = true;
  performed.plan.physics_model = PhysicsModel::Dynamic;
  performed.plan.length = 2;
  performed.plan.hold_ids = {7, 9};
  performed.plan.limbs = {Limb::RightHand, Limb::LeftHand};
  PerformedClimb climb;
  climb.planned_moves = 2;
  climb.start.seconds = 0.5;
  MoveOutcome first;
  first.seconds = 1.25;
  first.max_torque_ratio = 0.5;
  MoveOutcome second;
  second.failure = MoveFailure::HitWall;
  second.seconds = 0.75;
  second.max_torque_ratio = 0.875;
  climb.moves = {first, second};
  performed.climb = climb;
  performed.replans = 1;
  performed.moves_simulated = 3;
  performed.failed_moves = {{0, 0, Limb::RightHand, 4, MoveFailure::FootSlipped}};
  return performed;
}

TEST(PerformDescription, TheJsonNamesTheFailedMoveItsCauseAndTheRepair) {
  const auto json = performed_plan_json(perform_wall(), second_move_failed());
  EXPECT_EQ(json["physics_model"], "dynamic");
  EXPECT_EQ(json["holds"], nlohmann::ordered_json({7, 9}));
  EXPECT_EQ(json["replans"], 1);
  EXPECT_EQ(json["moves_simulated"], 3);
  EXPECT_EQ(json["failed_moves"][0]["cause"], "foot_slipped");
  EXPECT_EQ(json["failed_moves"][0]["hold"], 4);
  EXPECT_FALSE(json["reached_top"]);
  EXPECT_EQ(json["moves_performed"], 1);
  EXPECT_EQ(json["first_failed_move"], 1);
  EXPECT_EQ(json["cause"], "hit_wall");
  EXPECT_EQ(json["max_torque_ratio"], 0.875);
  EXPECT_EQ(json["simulated_s"], 2.5);
  ASSERT_EQ(json["moves"].size(), 2u);
  EXPECT_EQ(json["moves"][0]["limb"], "right_hand");
  EXPECT_TRUE(json["moves"][0]["cause"].is_null());
  EXPECT_EQ(json["moves"][1]["hold"], 9);
  EXPECT_EQ(json["moves"][1]["cause"], "hit_wall");
  EXPECT_NE(performed_plan_text(perform_wall(), second_move_failed())
                .find("performed in MuJoCo: 1 of 2 moves performed, move 2 failed: hit_wall"),
            std::string::npos)
      << performed_plan_text(perform_wall(), second_move_failed());
}

TEST(PerformDescription, AClimbToTheTopHasNoFailedMoveOrCause) {
  PerformedPlan performed = second_move_failed();
  performed.climb->moves[1].failure = MoveFailure::None;
  const auto json = performed_plan_json(perform_wall(), performed);
  EXPECT_TRUE(json["reached_top"]);
  EXPECT_TRUE(json["first_failed_move"].is_null());
  EXPECT_TRUE(json["cause"].is_null());
}

TEST(PerformDescription, NoPlanPerformsNothing) {
  PerformedPlan none;
  const auto json = performed_plan_json(perform_wall(), none);
  EXPECT_FALSE(json["found"]);
  EXPECT_FALSE(json["reached_top"]);
  EXPECT_EQ(json["moves_performed"], 0);
  EXPECT_TRUE(json["moves"].empty());
  EXPECT_TRUE(json["cause"].is_null());
  EXPECT_TRUE(json["start"].is_null()) << "nothing was placed, so nothing held still";
}

// A repair that ended with no plan still says which moves failed.
TEST(PerformDescription, ARepairThatLeftNoPlanListsTheMovesThatFailed) {
  PerformedPlan exhausted = second_move_failed();
  exhausted.plan = Plan{};
  exhausted.plan.physics_model = PhysicsModel::Dynamic;
  exhausted.climb.reset();
  const std::string text = performed_plan_text(perform_wall(), exhausted);
  EXPECT_EQ(text.rfind("no climb is left on 'w' under the dynamic model once the moves that failed in MuJoCo are "
                       "refused (0 states explored, 0 IK solves)\n",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("1 replan after moves failed in MuJoCo (3 moves simulated)"), std::string::npos) << text;
  EXPECT_NE(text.find("plan 1, move 1: right_hand -> hold 4 failed (foot_slipped)"), std::string::npos) << text;
  EXPECT_EQ(text.find("performed in MuJoCo:"), std::string::npos) << text;
}

}  // namespace
}  // namespace crux
