#include "simulation/perform_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(PerformKeys, DeclaresThePerformedClimbsParametersWithItsMovesAndServos) {
  PerformParameters perform;
  expect_key_declaration(perform, [](auto& keys, auto& p) { perform_keys(keys, p); }, {"perform"});
  std::vector<ConfigField> keys;
  perform_keys(keys, perform);
  *std::get<double*>(declared_field(keys, "perform.servo_damping_time").target) = 0.25;
  EXPECT_EQ(perform.servo.damping_time, 0.25);
  *std::get<double*>(declared_field(keys, "perform.slip_time").target) = 0.5;
  EXPECT_EQ(perform.move.slip_time_s, 0.5);
}

}  // namespace
}  // namespace crux
