#include "wall/wall.hpp"

#include <gtest/gtest.h>

#include "support/test_walls.hpp"

namespace crux {
namespace {

// Ids need not follow the order of the holds: a wall file may list them in any order.
Wall scrambled_ids() {
  Wall wall;
  wall.holds = {{7, Eigen::Vector3d(0, 0.1, 0.2), 0.04},
                {3, Eigen::Vector3d(0, 0.4, 0.2), 0.04},
                {12, Eigen::Vector3d(0, 0.1, 0.9), 0.05}};
  return wall;
}

TEST(Wall, IndexOfFindsTheHoldWithThatId) {
  const Wall wall = scrambled_ids();
  EXPECT_EQ(wall.hold_count(), 3);
  EXPECT_EQ(wall.index_of(7), 0);
  EXPECT_EQ(wall.index_of(3), 1);
  EXPECT_EQ(wall.index_of(12), 2);
}

TEST(Wall, IndexOfAnUnknownIdIsMinusOne) {
  const Wall wall = scrambled_ids();
  EXPECT_EQ(wall.index_of(1), -1) << "an index is not an id";
  EXPECT_EQ(wall.index_of(0), -1) << "0 means no hold";
  EXPECT_EQ(wall.index_of(-1), -1);
  EXPECT_EQ(wall.index_of(13), -1);
  EXPECT_EQ(Wall{}.index_of(1), -1) << "a wall without holds";
  EXPECT_EQ(Wall{}.hold_count(), 0);
}

TEST(Wall, GridWallsNumberTheirHoldsFromOne) {
  const Wall wall = testing::grid_wall(4, 5, 0.3, 0.5);
  EXPECT_EQ(wall.hold_count(), 20);
  for (int i = 0; i < wall.hold_count(); ++i) EXPECT_EQ(wall.index_of(i + 1), i);
  EXPECT_EQ(wall.index_of(21), -1);
}

TEST(Wall, DefaultsAreThePapersHoldsAndFinishingHeight) {
  const Wall wall;
  EXPECT_EQ(wall.finish_height, 3.0);
  EXPECT_EQ(wall.start, (std::array<int, kLimbCount>{0, 0, 0, 0}));
  EXPECT_EQ(Hold{}.radius, 0.04) << "spheres with a 4 cm radius (section III-A)";
  EXPECT_EQ(Hold{}.id, 0);
}

}  // namespace
}  // namespace crux
