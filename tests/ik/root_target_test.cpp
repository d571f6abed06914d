#include "ik/root_target.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

// Midway between the feet, above the lowest, and off the wall on the climber's side (x < 0).
TEST(RootTarget, MidwayBetweenFeetAboveTheLowestFoot) {
  const BodyModel& model = testing::human_model();
  const std::array<Eigen::Vector3d, kLimbCount> holds{Eigen::Vector3d(0, 0.2, 2.0), Eigen::Vector3d(0, 0.8, 2.1),
                                                      Eigen::Vector3d(0, 0.1, 0.7), Eigen::Vector3d(0, 0.5, 0.4)};
  const Eigen::Vector3d target = root_target(model, holds, {0.25});
  EXPECT_DOUBLE_EQ(target.x(), -0.25);
  EXPECT_DOUBLE_EQ(target.y(), 0.3);
  EXPECT_DOUBLE_EQ(target.z(), 0.4 + model.root_height_above_soles);
}

}  // namespace
}  // namespace crux
