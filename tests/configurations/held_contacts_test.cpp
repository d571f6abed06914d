#include "configurations/held_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "configurations/reachability.hpp"
#include "support/test_walls.hpp"
#include "wall/hold_support.hpp"

namespace crux {
namespace {

TEST(HeldContacts, EachHeldLimbPushesAlongItsHoldsSupportWithinTheGripOrUnbounded) {
  Wall wall = testing::wall_with_holds({{0.0, 1.8}, {0.4, 1.8}, {0.0, 0.5}, {0.4, 0.5}});
  wall.holds[1].support = Eigen::Vector3d(0.6, 0.0, 0.8);
  PhysicsParameters physics;
  physics.friction = 0.7;
  physics.grip = 400.0;
  std::array<PointContact, kLimbCount> out;
  const HoldConfiguration configuration = start_configuration(wall);
  const auto contacts = held_contacts(wall, configuration.with(Limb::LeftFoot, kFree), physics, out);
  ASSERT_EQ(contacts.size(), 3u);
  EXPECT_EQ(contacts[0].limb, Limb::RightHand);
  EXPECT_EQ(contacts[1].limb, Limb::LeftHand);
  EXPECT_EQ(contacts[2].limb, Limb::RightFoot);
  EXPECT_EQ(contacts[0].normal_force_limit, 400.0);
  EXPECT_EQ(contacts[1].normal_force_limit, 400.0);
  EXPECT_TRUE(std::isinf(contacts[2].normal_force_limit)) << "a foot is bounded by the legs' torques";
  for (const PointContact& contact : contacts) EXPECT_EQ(contact.friction, 0.7);
  EXPECT_EQ(contacts[1].support_direction, Eigen::Vector3d(0.6, 0.0, 0.8)) << "the wall file's own";
  EXPECT_EQ(contacts[0].support_direction, support_direction(wall.holds[0], Limb::RightHand, 45.0));
  EXPECT_EQ(contacts[2].support_direction, Eigen::Vector3d::UnitZ()) << "a foot stands on the hold's top";
}

}  // namespace
}  // namespace crux
