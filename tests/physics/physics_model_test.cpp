#include "physics/physics_model.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(PhysicsModel, TheKinematicModelIsTheDefaultAndBothParseByName) {
  EXPECT_EQ(PhysicsParameters{}.model, PhysicsModel::Kinematic);
  EXPECT_EQ(enum_choices<PhysicsModel>(), "kinematic or static");
  EXPECT_EQ(parse_enum<PhysicsModel>("static"), PhysicsModel::Static);
  EXPECT_FALSE(parse_enum<PhysicsModel>("dynamic"));
}

TEST(PhysicsModel, TheDefaultGripIsTheAdvancedClimbers) {
  EXPECT_DOUBLE_EQ(PhysicsParameters{}.grip, kAdvancedClimberGripN);
  EXPECT_EQ(find_climbing_level("advanced")->grip_n, kAdvancedClimberGripN);
}

}  // namespace
}  // namespace crux
