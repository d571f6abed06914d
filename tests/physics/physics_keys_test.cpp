#include "physics/physics_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(PhysicsKeys, DeclaresThePhysicsModelsParametersAndTheStrengthLevelBesideThem) {
  PhysicsParameters physics;
  std::string level;
  expect_key_declaration(physics, [&level](auto& keys, auto& p) { physics_keys(keys, p, level); }, {"physics"},
                         {"physics.strength"});
}

TEST(PhysicsKeys, TheStrengthTakesAPublishedClimbingLevelOnly) {
  PhysicsParameters physics;
  std::string level;
  std::vector<ConfigField> keys;
  physics_keys(keys, physics, level);
  const auto& strength = std::get<ChoiceTarget<false>>(declared_field(keys, "physics.strength").target);
  EXPECT_EQ(strength.type->text(strength.target), "");  // unset
  EXPECT_FALSE(strength.type->parse(strength.target, "superhuman"));
  EXPECT_EQ(level, "");
  ASSERT_TRUE(strength.type->parse(strength.target, "elite"));
  EXPECT_EQ(level, "elite");
}

}  // namespace
}  // namespace crux
