#include "climbing/climbing_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(ClimbingKeys, DeclaresTheRewardsAndTheFallWhenStuck) {
  Rewards rewards;
  expect_key_declaration(rewards, [](auto& keys, auto& p) { reward_keys(keys, p); }, {"reward"});
  ClimbingParameters climbing;
  expect_key_declaration(climbing, [](auto& keys, auto& p) { fall_when_stuck_keys(keys, p); }, {"physics"});
}

TEST(ClimbingKeys, AShapingWeightIsNeverNegative) {
  Rewards rewards;
  std::vector<ConfigField> keys;
  reward_keys(keys, rewards);
  EXPECT_FALSE(declared_field(keys, "reward.height").bounds.contains(-1));
  EXPECT_TRUE(declared_field(keys, "reward.unreachable").bounds.contains(-1));
}

}  // namespace
}  // namespace crux
