#include "sweeps/sweep_grid.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(SweepGrid, CellsAreTheProductReadAsNestedLoops) {
  const SweepGrid grid{{{"learning.alpha", 2}, {"learning.epsilon", 3}}};
  ASSERT_EQ(grid.cells(), 6u);
  // The first listed key varies slowest.
  const std::vector<std::pair<std::size_t, std::size_t>> expected{{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}};
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    const ListChoice choice = grid.choice(c);
    EXPECT_EQ(choice.at("learning.alpha"), expected[c].first) << "cell " << c;
    EXPECT_EQ(choice.at("learning.epsilon"), expected[c].second) << "cell " << c;
  }
}

TEST(SweepGrid, NoListIsOneCell) {
  const SweepGrid grid;
  EXPECT_EQ(grid.cells(), 1u);
  EXPECT_TRUE(grid.choice(0).empty());
}

}  // namespace
}  // namespace crux
