#include "wall/hold_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace crux {
namespace {

TEST(HoldSupport, AHandHooksTheLipAndAFootStandsOnTheTop) {
  const Hold jug;
  const Eigen::Vector3d lip = support_direction(jug, Limb::LeftHand, 45.0);
  EXPECT_NEAR(lip.x(), std::sqrt(0.5), 1e-15) << "into the wall";
  EXPECT_NEAR(lip.z(), std::sqrt(0.5), 1e-15) << "and up";
  EXPECT_EQ(lip.y(), 0.0);
  EXPECT_EQ(support_direction(jug, Limb::RightHand, 0.0), Eigen::Vector3d::UnitZ());
  EXPECT_EQ(support_direction(jug, Limb::RightFoot, 45.0), Eigen::Vector3d::UnitZ());
  EXPECT_EQ(support_direction(jug, Limb::LeftFoot, 80.0), Eigen::Vector3d::UnitZ());
}

TEST(HoldSupport, AHoldsOwnDirectionServesEveryLimb) {
  Hold sloper;
  sloper.support = Eigen::Vector3d(0.6, 0.0, 0.8);
  for (const Limb limb : {Limb::RightHand, Limb::LeftHand, Limb::RightFoot, Limb::LeftFoot}) {
    EXPECT_EQ(support_direction(sloper, limb, 45.0), *sloper.support) << enum_name(limb);
  }
}

}  // namespace
}  // namespace crux
