#include "sweeps/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "common/input_error.hpp"

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

// Issue 25: lists whose lengths multiply to 2^64 wrapped the count to 0 (a segfault);
// the count is refused as soon as it passes the bound, before it could overflow.
TEST(SweepGrid, MoreCellsThanTheBoundAreRefusedBeforeTheProductOverflows) {
  const auto problem = [](const SweepGrid& grid) {
    try {
      return std::to_string(grid.cells());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  const std::string refused =
      "sweep.toml: its lists make more than 100000 cells (the product of their lengths), the most a sweep may have";
  SweepGrid wrapping{{}, "sweep.toml"};
  for (int k = 0; k < 4; ++k) wrapping.keys.push_back({"key" + std::to_string(k), 65536});  // 2^64 cells
  EXPECT_EQ(problem(wrapping), refused);
  EXPECT_EQ(problem(SweepGrid{{{"experiment.seed", 1000000}}, "sweep.toml"}), refused);
  EXPECT_EQ(problem(SweepGrid{{{"learning.alpha", 2}, {"experiment.seed", SIZE_MAX}}, "sweep.toml"}), refused);
  EXPECT_EQ(problem(SweepGrid{{{"learning.alpha", 4}, {"experiment.seed", kMaxSweepCells / 4}}, "sweep.toml"}),
            std::to_string(kMaxSweepCells));
  EXPECT_EQ(problem(SweepGrid{{{"learning.alpha", 4}, {"experiment.seed", kMaxSweepCells / 4 + 1}}, "sweep.toml"}),
            refused);
}

}  // namespace
}  // namespace crux
