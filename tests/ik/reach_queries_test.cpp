#include "ik/reach_queries.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::human_model;

TEST(ReachQueries, TheStartLayoutIsReachedWithTheDefaultSettings) {
  const Posture start = start_layout_posture(human_model(), IkParameters{});
  EXPECT_EQ(start.size(), kConfigurationDof);
}

// ik-compare with a root sphere of 5e-324 m stopped with "internal error": the settings
// are the user's, and so is the answer.
TEST(ReachQueries, SettingsThatCannotReachTheStartAreTheUsersInputError) {
  IkParameters settings;
  settings.tolerances.root_radius = 5e-324;
  try {
    start_layout_posture(human_model(), settings);
    FAIL() << "reached the start layout within a root sphere of 5e-324 m";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "ik");
  }
  EXPECT_THROW(climbing_reach_queries(human_model(), settings, 3, 1), InputError);
}

}  // namespace
}  // namespace crux
