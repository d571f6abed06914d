#include "simulation/performed_move.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "configurations/reachability.hpp"
#include "ik/ik_solver.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/move_reference.hpp"
#include "support/jug_ladder.hpp"
#include "support/test_walls.hpp"

namespace crux {
namespace {

StrengthProfile human_limits() {
  const BodyModel& model = testing::human_model();
  return motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
}

using testing::JugLadder;

TEST(PerformedMove, TheRightHandMovesUpToAJugAndTheBodyHoldsStill) {
  const BodyModel& model = testing::human_model();
  const JugLadder move;
  SimulatedClimber climber(model, move.wall, move.physics, human_limits(), move.start, ServoParameters{});
  MoveReferences references(model, move.wall, move.physics, move.reach, 16);
  const HoldConfiguration start = start_configuration(move.wall);
  climber.place(move.start, start);
  const MoveParameters parameters;
  const MoveOutcome settled =
      hold_still(climber, move.start, start, references.holding(move.start, start).torques, 2.0, parameters);
  ASSERT_TRUE(settled.performed()) << enum_name(settled.failure);
  const MoveOutcome outcome =
      perform_move(climber, references.move(move.start, move.reached, move.before, 0, 4), parameters);
  EXPECT_TRUE(outcome.performed()) << enum_name(outcome.failure);
  EXPECT_TRUE(climber.grasp(Limb::RightHand).taken(climber.model())) << "the hand took the jug";
  EXPECT_LE(outcome.grasp_error_m, parameters.grasp_radius + move.wall.holds[4].radius);
  EXPECT_LE(outcome.max_torque_ratio, 1.0 + 1e-9) << "the motors clamp every torque at its limit";
  std::printf("move: %.2f s, torque ratio %.2f, joint error %.3f rad, turn %.3f rad, wall push %.1f N\n",
              outcome.seconds, outcome.max_torque_ratio, outcome.joint_error_rad, outcome.max_root_turn_rad,
              outcome.peak_wall_push_n);
}

// The same move with a grip of 60 N: the left hand alone cannot hold the body while the right
// one moves, and lets go; the move names the grip as its cause.
TEST(PerformedMove, AMoveThatAsksMoreThanTheGripFailsForTheGrip) {
  const BodyModel& model = testing::human_model();
  const JugLadder move;
  PhysicsParameters weak = move.physics;
  weak.grip = 60.0;
  SimulatedClimber climber(model, move.wall, weak, human_limits(), move.start, ServoParameters{});
  MoveReferences references(model, move.wall, weak, move.reach, 16);
  climber.place(move.start, start_configuration(move.wall));
  const MoveOutcome outcome =
      perform_move(climber, references.move(move.start, move.reached, move.before, 0, 4), MoveParameters{});
  EXPECT_EQ(outcome.failure, MoveFailure::GripExceeded);
  EXPECT_FALSE(climber.grasp(Limb::LeftHand).taken(climber.model())) << "the hand let go";
}

// A foot outside the hands' span, the other foot free: no forces in the contacts' cones
// hold the body (docs/PHYSICS.md, "Three holds on a plane"), and in MuJoCo it does not
// hold still either, with the least-squares feed-forward.
TEST(PerformedMove, ABarnDoorStanceThatTheStaticModelRefusesDoesNotHoldStill) {
  const BodyModel& model = testing::human_model();
  const Wall wall = testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.7, 0.45}, {0.15, 0.45}});
  const JugLadder rules;  // the static model's rules
  BodyData data(model);
  const IkResult start = solve_start(model, data, wall, rules.reach);
  ASSERT_TRUE(start.reached);
  const HoldConfiguration three = start_configuration(wall).with(Limb::LeftFoot, kFree);
  MoveReferences references(model, wall, rules.physics, rules.reach, 16);
  const HoldingTorques holding = references.holding(start.posture, three);
  EXPECT_FALSE(holding.balanced);
  SimulatedClimber climber(model, wall, rules.physics, human_limits(), start.posture, ServoParameters{});
  climber.place(start.posture, three);
  const MoveOutcome outcome = hold_still(climber, start.posture, three, holding.torques, 2.0, MoveParameters{});
  EXPECT_FALSE(outcome.performed());
  std::printf("barn door: %s after %.2f s, turn %.3f rad\n", std::string(enum_name(outcome.failure)).c_str(),
              outcome.seconds, outcome.max_root_turn_rad);
}

}  // namespace
}  // namespace crux
