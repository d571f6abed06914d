#include "simulation/performed_climb.hpp"

#include <gtest/gtest.h>

#include "support/jug_ladder.hpp"

namespace crux {
namespace {

using testing::JugLadder;

ClimbToPerform right_hand_to_the_jug(const JugLadder& ladder) {
  return {{ladder.start, ladder.reached}, {Limb::RightHand}, {4}};
}

TEST(PerformedClimb, AOneMoveClimbReachesTheTopAndRecordsItsTrajectory) {
  const JugLadder ladder;
  const PerformedClimb climb = perform_climb(testing::human_model(), ladder.wall, ladder.physics, ladder.reach,
                                             right_hand_to_the_jug(ladder), PerformParameters{});
  ASSERT_TRUE(climb.reached_top()) << enum_name(climb.cause());
  EXPECT_EQ(climb.moves_performed(), 1);
  EXPECT_FALSE(climb.first_failed_move().has_value());
  EXPECT_EQ(climb.cause(), MoveFailure::None);
  EXPECT_NEAR(climb.simulated_s(), climb.start.seconds + climb.moves[0].seconds, 1e-12);
  EXPECT_LE(climb.max_torque_ratio(), 1.0 + 1e-9);
  ASSERT_FALSE(climb.trajectory.empty());
  EXPECT_EQ(climb.trajectory.front().move, -1) << "the start settles first";
  EXPECT_EQ(climb.trajectory.back().move, 0);
  EXPECT_NEAR(climb.trajectory.back().time, climb.simulated_s(), PerformParameters{}.record_interval_s);
  EXPECT_GT(climb.trajectory.back().hold_forces[static_cast<int>(Limb::RightHand)].norm(), 1.0) << "on the jug";
  EXPECT_NE(climb.mjcf.find("<mujoco"), std::string::npos);
}

// A grip of 60 N: the left hand alone cannot hold the body while the right one moves.
TEST(PerformedClimb, AFailedMoveEndsTheClimbWithItsCause) {
  JugLadder ladder;
  ladder.physics.grip = 60.0;
  const PerformedClimb climb = perform_climb(testing::human_model(), ladder.wall, ladder.physics, ladder.reach,
                                             right_hand_to_the_jug(ladder), PerformParameters{});
  EXPECT_FALSE(climb.reached_top());
  EXPECT_EQ(climb.first_failed_move(), 0);
  EXPECT_EQ(climb.cause(), MoveFailure::GripExceeded);
  EXPECT_EQ(climb.moves_performed(), 0);
}

}  // namespace
}  // namespace crux
