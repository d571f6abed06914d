#include "wall/incline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/LU>

namespace crux {
namespace {

Eigen::Vector3d gravity_in_wall_frame(double incline_deg) {
  return wall_to_world(incline_deg).transpose() * Eigen::Vector3d(0.0, 0.0, -9.81);
}

// A 40-degree overhang leans its top towards the climber (x < 0), and gravity, in wall
// coordinates, pulls partly away from the wall; a slab leans the other way.
TEST(Incline, AnOverhangLeansTowardsTheClimberAndGravityPullsAwayFromTheWall) {
  const double theta = 40.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d top = wall_to_world(40.0) * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(top.x(), -std::sin(theta), 1e-15);
  EXPECT_NEAR(top.z(), std::cos(theta), 1e-15);
  EXPECT_NEAR(top.y(), 0.0, 1e-15);
  const Eigen::Vector3d g = gravity_in_wall_frame(40.0);
  EXPECT_NEAR(g.x(), -9.81 * std::sin(theta), 1e-12);
  EXPECT_NEAR(g.z(), -9.81 * std::cos(theta), 1e-12);
  EXPECT_GT(gravity_in_wall_frame(-20.0).x(), 0.0) << "on a slab gravity presses the climber onto the wall";
  EXPECT_EQ(gravity_in_wall_frame(0.0), Eigen::Vector3d(0, 0, -9.81));
  EXPECT_NEAR((wall_to_world(25.0) * wall_to_world(25.0).transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(wall_to_world(25.0).determinant(), 1.0, 1e-15) << "a rotation: the frame stays right-handed";
}

}  // namespace
}  // namespace crux
