#include "physics/physics_model.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(PhysicsModel, TheKinematicModelIsTheDefaultAndEachParsesByName) {
  EXPECT_EQ(PhysicsParameters{}.model, PhysicsModel::Kinematic);
  EXPECT_EQ(enum_choices<PhysicsModel>(), "kinematic, static or dynamic");
  EXPECT_EQ(parse_enum<PhysicsModel>("static"), PhysicsModel::Static);
  EXPECT_EQ(parse_enum<PhysicsModel>("dynamic"), PhysicsModel::Dynamic);
  EXPECT_FALSE(parse_enum<PhysicsModel>("quantum"));
}

TEST(PhysicsModel, TheStaticAndDynamicModelsCheckEachStance) {
  EXPECT_FALSE(checks_stances(PhysicsModel::Kinematic));
  EXPECT_TRUE(checks_stances(PhysicsModel::Static));
  EXPECT_TRUE(checks_stances(PhysicsModel::Dynamic));
}

TEST(PhysicsModel, TheDefaultGripIsTheAdvancedClimbers) {
  EXPECT_DOUBLE_EQ(PhysicsParameters{}.grip, kAdvancedClimberGripN);
  EXPECT_EQ(find_climbing_level("advanced")->grip_n, kAdvancedClimberGripN);
}

}  // namespace
}  // namespace crux
