#include "agent_space/moving_grid.hpp"

#include <gtest/gtest.h>

#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

const GridParameters kGrid;

TEST(MovingGrid, EachLimbsAnchorTileIsCentredOnTheLimb) {
  const Eigen::Vector3d limb(0.0, 0.7, 1.9);
  for (int l = 0; l < kLimbCount; ++l) {
    const GridPlacement placement = place_grid(kGrid, static_cast<Limb>(l), limb);
    const int anchor = kGrid.anchors[l][1] * kGrid.columns + kGrid.anchors[l][0];
    EXPECT_EQ(placement.tile_of(limb), anchor) << enum_name(static_cast<Limb>(l));
    EXPECT_LT((placement.tile_centre(anchor) - limb).norm(), 1e-12);
  }
  // The right hand's anchor P_1 is at column 1, row 4 (docs/MODEL.md, choice C15): the grid spans
  // 1.5 tiles to the right of the hand and 3.5 to its left, 4.5 below and 2.5 above.
  const GridPlacement right_hand = place_grid(kGrid, Limb::RightHand, limb);
  EXPECT_NEAR(right_hand.origin.x(), 0.7 - 1.5 * 0.3, 1e-12);
  EXPECT_NEAR(right_hand.origin.y(), 1.9 - 4.5 * 0.5, 1e-12);
}

TEST(MovingGrid, TileEdgesAndCornersBelongToTheTileOfLargerCoordinates) {
  GridPlacement p;
  p.origin = {0.0, 0.0};  // exact binary edges: tiles are 0.3 x 0.5 but test on 0.5 multiples
  p.tile_width = 0.5;
  p.tile_height = 0.5;
  EXPECT_EQ(p.tile_of({0, 0.0, 0.0}), 0);             // the grid's own corner
  EXPECT_EQ(p.tile_of({0, 0.5, 0.0}), 1);             // vertical edge between tiles 0 and 1
  EXPECT_EQ(p.tile_of({0, 0.0, 0.5}), 5);             // horizontal edge between tiles 0 and 5
  EXPECT_EQ(p.tile_of({0, 0.5, 0.5}), 6);             // interior corner shared by 0, 1, 5, 6
  EXPECT_EQ(p.tile_of({0, 2.4999, 3.4999}), 34);      // just inside the far corner
  EXPECT_EQ(p.tile_of({0, 2.5, 1.0}), kOutsideGrid);  // the far edges are outside
  EXPECT_EQ(p.tile_of({0, 1.0, 3.5}), kOutsideGrid);
  EXPECT_EQ(p.tile_of({0, -1e-12, 1.0}), kOutsideGrid);
  EXPECT_EQ(p.tile_of({0, std::nan(""), 1.0}), kOutsideGrid);
}

TEST(MovingGrid, TileToHoldToTileRoundTrips) {
  const Wall wall = generate_random_wall(11);
  const GridPlacement placement = place_grid(kGrid, Limb::RightHand, wall.holds[wall.start[0]].position);
  int tiles_with_holds = 0;
  for (int tile = 0; tile < kGrid.tile_count(); ++tile) {
    const int hold = hold_in_tile(wall, placement, tile);
    if (hold < 0) continue;
    ++tiles_with_holds;
    EXPECT_EQ(placement.tile_of(wall.holds[hold].position), tile);
    // No other hold of the tile is nearer its centre.
    const Eigen::Vector3d centre = placement.tile_centre(tile);
    for (int other = 0; other < wall.hold_count(); ++other) {
      if (placement.tile_of(wall.holds[other].position) != tile) continue;
      EXPECT_GE((wall.holds[other].position - centre).norm(), (wall.holds[hold].position - centre).norm());
    }
  }
  EXPECT_GT(tiles_with_holds, 10);
}

TEST(MovingGrid, TileWithoutHoldMapsToNoHold) {
  const Wall wall = testing::wall_with_holds({{0.0, 0.0}, {0.3, 0.0}, {0.0, 0.5}, {0.3, 0.5}});
  const GridPlacement placement = place_grid(kGrid, Limb::RightHand, {0, 0.0, 0.5});
  EXPECT_EQ(hold_in_tile(wall, placement, 0), -1);
  EXPECT_EQ(hold_in_tile(wall, placement, 4 * 5 + 1), 2);  // the anchor tile holds hold index 2
}

TEST(MovingGrid, HoldsOutsideTheGridHaveNoTile) {
  const Wall wall = testing::grid_wall(10, 40, 0.3, 0.5);  // 20 m tall
  // Mid-wall, so that every tile lies over the layout (at the foot of the wall the
  // grid's lowest row would hang below the first row of holds).
  const Eigen::Vector3d left_foot = wall.holds[20 * 10 + 3].position;
  const GridPlacement placement = place_grid(kGrid, Limb::LeftFoot, left_foot);
  int inside = 0, outside = 0;
  for (const Hold& h : wall.holds) (placement.tile_of(h.position) == kOutsideGrid ? outside : inside)++;
  EXPECT_EQ(inside, kGrid.tile_count()) << "a regular 0.3 x 0.5 m layout puts one hold per tile";
  EXPECT_EQ(inside + outside, 400);
}

}  // namespace
}  // namespace crux
