#include "simulation/simulated_climber.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "configurations/reachability.hpp"
#include "simulation/mjcf_model.hpp"
#include "support/test_models.hpp"
#include "wall/hold_support.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

// Placed at its start on three holds: the held hand grasps where its grasp point is, the
// other hand is free, each held foot stands on a footing facing its hold's support right
// under its contact sphere, and nothing else holds it.
TEST(SimulatedClimber, PlacedOnItsHoldsEachLimbTakesItsHoldWhereItIs) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  ReachabilityParameters reach;
  reach.ik.wall = WallRule::Avoid;
  BodyData data(model);
  const IkResult start = solve_start(model, data, wall, reach);
  ASSERT_TRUE(start.reached);
  PhysicsParameters physics;
  physics.model = PhysicsModel::Static;
  SimulatedClimber climber(model, wall, physics, motor_limits(model, StrengthProfile{}), start.posture,
                           ServoParameters{});
  const HoldConfiguration holds = start_configuration(wall).with(Limb::RightHand, kFree);
  climber.place(start.posture, holds);
  EXPECT_EQ(climber.data()->time, 0.0);
  EXPECT_FALSE(climber.grasp(Limb::RightHand).taken(climber.model()));
  EXPECT_TRUE(climber.grasp(Limb::LeftHand).taken(climber.model()));
  const int grasp = mj_name2id(climber.model(), mjOBJ_EQUALITY, mjcf_grasp_name(Limb::LeftHand).c_str());
  EXPECT_LT((Eigen::Vector3d(climber.model()->eq_data + mjNEQDATA * grasp + 3) -
             simulated_grasp_point(climber.layout(), climber.data(), Limb::LeftHand))
                .norm(),
            1e-12)
      << "anchored where the hand is (a vertical wall: world and wall coordinates agree)";
  for (const Limb foot : {Limb::RightFoot, Limb::LeftFoot}) {
    ASSERT_TRUE(climber.footing(foot).taken(climber.data()));
    const int body = mj_name2id(climber.model(), mjOBJ_BODY, mjcf_footing_name(foot).c_str());
    const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> frame(climber.data()->xmat + 9 * body);
    const Eigen::Vector3d support = support_direction(wall.holds[holds.hold(foot)], foot, physics.support_angle_deg);
    EXPECT_LT((frame.col(2) - support).norm(), 1e-12);
    const Eigen::Vector3d top(climber.data()->xpos + 3 * body);
    EXPECT_NEAR((simulated_grasp_point(climber.layout(), climber.data(), foot) - top).dot(support), kFootContactRadius,
                1e-12);
  }
  EXPECT_THROW(climber.grasp(Limb::LeftFoot), std::invalid_argument);
  EXPECT_THROW(climber.footing(Limb::LeftHand), std::invalid_argument);
  climber.place(start.posture, start_configuration(wall));
  EXPECT_TRUE(climber.grasp(Limb::RightHand).taken(climber.model()));
}

}  // namespace
}  // namespace crux
