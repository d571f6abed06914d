#include "configurations/possible_actions.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/allocation_counter.hpp"
#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

TEST(PossibleActions, AreExactlyTheFreeHoldsWhoseConfigurationPasses) {
  const FilterParameters parameters;
  for (const Wall& wall :
       {generate_random_wall(3), testing::grid_wall(10, 14, 0.2, 0.2), testing::grid_wall(10, 40, 0.3, 0.5)}) {
    std::vector<int> buffer(wall.hold_count());
    HoldConfiguration state;
    state.holds = wall.start;
    for (const Limb free : {Limb::RightHand, Limb::LeftHand, Limb::RightFoot, Limb::LeftFoot}) {
      HoldConfiguration s = state.with(free, kFree);
      const int count = possible_actions(wall, s, parameters, buffer);
      std::vector<int> expected;
      for (int hold = 0; hold < wall.hold_count(); ++hold) {
        const bool taken = std::find(s.holds.begin(), s.holds.end(), hold) != s.holds.end();
        if (!taken && passes_filter(wall, s.with(free, hold), parameters)) expected.push_back(hold);
      }
      EXPECT_EQ(std::vector<int>(buffer.begin(), buffer.begin() + count), expected)
          << wall.name << " " << enum_name(free);
      EXPECT_GT(count, 0);
    }
  }
}

TEST(PossibleActions, DoNotAllocate) {
  const Wall wall = generate_random_wall(4);
  std::vector<int> buffer(wall.hold_count());
  HoldConfiguration state;
  state.holds = wall.start;
  state.holds[0] = kFree;
  const long before = testing::allocation_count();
  int total = 0;
  for (int n = 0; n < 100; ++n) total += possible_actions(wall, state, FilterParameters{}, buffer);
  EXPECT_EQ(testing::allocation_count(), before);
  EXPECT_GT(total, 0);
}

}  // namespace
}  // namespace crux
