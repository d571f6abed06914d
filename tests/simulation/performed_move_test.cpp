#include "simulation/performed_move.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "configurations/reachability.hpp"
#include "ik/ik_solver.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/move_reference.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"

namespace crux {
namespace {

// Feet on two holds at knee height, hands on two jugs above the shoulders, and a jug 20 cm
// above the right hand: the right hand's move up to it.
Wall ladder_wall() {
  Wall wall = testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});
  wall.finish_height = 3.0;
  return wall;
}

ReachabilityParameters static_reach() {
  ReachabilityParameters reach;
  reach.ik.wall = WallRule::Avoid;
  return reach;
}

PhysicsParameters static_physics() {
  PhysicsParameters physics;
  physics.model = PhysicsModel::Static;
  return physics;
}

StrengthProfile human_limits() {
  const BodyModel& model = testing::human_model();
  return motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
}

// The ladder's start stance and the stance with the right hand on the jug above, as the IK
// solves them.
struct LadderMove {
  Wall wall = ladder_wall();
  Posture start, reached;
  HoldConfiguration before;
};

LadderMove ladder_move() {
  const BodyModel& model = testing::human_model();
  LadderMove move;
  BodyData data(model);
  const IkResult start = solve_start(model, data, move.wall, static_reach());
  EXPECT_TRUE(start.reached);
  move.start = start.posture;
  move.before = start_configuration(move.wall).with(Limb::RightHand, kFree);
  const ReachTarget target = reach_target(model, move.wall, move.before.with(Limb::RightHand, 4), static_reach().root);
  const IkResult reached = solve_ik(model, data, move.start, target, static_reach().ik);
  EXPECT_TRUE(reached.reached);
  move.reached = reached.posture;
  return move;
}

TEST(PerformedMove, TheRightHandMovesUpToAJugAndTheBodyHoldsStill) {
  const BodyModel& model = testing::human_model();
  const LadderMove move = ladder_move();
  SimulatedClimber climber(model, move.wall, static_physics(), human_limits(), move.start, ServoParameters{});
  MoveReferences references(model, move.wall, static_physics(), static_reach(), 16);
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
  const LadderMove move = ladder_move();
  PhysicsParameters weak = static_physics();
  weak.grip = 60.0;
  SimulatedClimber climber(model, move.wall, weak, human_limits(), move.start, ServoParameters{});
  MoveReferences references(model, move.wall, weak, static_reach(), 16);
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
  BodyData data(model);
  const IkResult start = solve_start(model, data, wall, static_reach());
  ASSERT_TRUE(start.reached);
  const HoldConfiguration three = start_configuration(wall).with(Limb::LeftFoot, kFree);
  MoveReferences references(model, wall, static_physics(), static_reach(), 16);
  const HoldingTorques holding = references.holding(start.posture, three);
  EXPECT_FALSE(holding.balanced);
  SimulatedClimber climber(model, wall, static_physics(), human_limits(), start.posture, ServoParameters{});
  climber.place(start.posture, three);
  const MoveOutcome outcome = hold_still(climber, start.posture, three, holding.torques, 2.0, MoveParameters{});
  EXPECT_FALSE(outcome.performed());
  std::printf("barn door: %s after %.2f s, turn %.3f rad\n", std::string(enum_name(outcome.failure)).c_str(),
              outcome.seconds, outcome.max_root_turn_rad);
}

}  // namespace
}  // namespace crux
