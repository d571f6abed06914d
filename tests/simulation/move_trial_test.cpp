#include "simulation/move_trial.hpp"

#include <gtest/gtest.h>

#include "support/jug_ladder.hpp"

namespace crux {
namespace {

// The ladder's right hand, from the start placed at rest, up to the jug: performed, and the
// same again from rest (a trial does not depend on the one before it).
TEST(MoveTrials, AMoveFromRestIsPerformedTheSameEachTime) {
  const testing::JugLadder ladder;
  MoveTrials trials(testing::human_model(), ladder.wall, ladder.physics, ladder.reach, PerformParameters{});
  const int left_hold = start_configuration(ladder.wall).hold(Limb::RightHand);
  constexpr int kJug = 4;
  const MoveOutcome first = trials.perform(ladder.start, ladder.reached, ladder.before, left_hold, kJug);
  EXPECT_TRUE(first.performed()) << enum_name(first.failure);
  const MoveOutcome again = trials.perform(ladder.start, ladder.reached, ladder.before, left_hold, kJug);
  EXPECT_EQ(again.failure, first.failure);
  EXPECT_EQ(again.steps, first.steps);
  EXPECT_EQ(again.max_torque_ratio, first.max_torque_ratio);
}

}  // namespace
}  // namespace crux
