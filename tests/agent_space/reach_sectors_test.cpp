#include "agent_space/reach_sectors.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "agent_space/agent_descriptor.hpp"

namespace crux {
namespace {

// 8 sectors of 45 degrees, 4 rings of 0.3 m, around a shoulder at (y, z) = (1, 1).
GridParameters reach_grid() {
  GridParameters grid;
  grid.space = AgentSpaceKind::Reach;
  grid.columns = 8;
  grid.rows = 4;
  grid.tile_height = 0.3;
  return grid;
}

Eigen::Vector3d at(double y, double z) { return {0.0, y, z}; }

TEST(ReachSectors, CellsByHand) {
  const GridPlacement placement = place_reach_sectors(reach_grid(), at(1.0, 1.0));
  EXPECT_EQ(placement.tile_of(at(1.2, 1.0)), 0) << "0.2 m to the left: ring 0, sector 0";
  EXPECT_EQ(placement.tile_of(at(1.3, 1.0)), 8) << "0.3 m: a ring's edge belongs to the outer ring";
  EXPECT_EQ(placement.tile_of(at(1.0, 1.5)), 10) << "0.5 m up: ring 1, sector 2 (90 degrees)";
  EXPECT_EQ(placement.tile_of(at(0.6, 0.6)), 13) << "0.57 m down right: ring 1, sector 5 (225 degrees)";
  EXPECT_EQ(placement.tile_of(at(1.0, 0.0)), 30) << "1 m down: ring 3, sector 6 (270 degrees)";
  EXPECT_EQ(placement.tile_of(at(1.05, 0.95)), 7) << "just below +y: the last sector";
  EXPECT_EQ(placement.tile_of(at(2.3, 1.0)), kOutsideGrid) << "1.3 m: beyond the last ring";
  EXPECT_EQ(placement.tile_of(at(NAN, 1.0)), kOutsideGrid);
  // A cell's centre: middle radius, middle angle, and it lies in its cell.
  const Eigen::Vector3d centre = placement.tile_centre(10);
  EXPECT_NEAR(centre.y(), 1.0 + 0.45 * std::cos(2.5 * M_PI / 4), 1e-12);
  EXPECT_NEAR(centre.z(), 1.0 + 0.45 * std::sin(2.5 * M_PI / 4), 1e-12);
  for (int cell = 0; cell < 32; ++cell) EXPECT_EQ(placement.tile_of(placement.tile_centre(cell)), cell);
}

// The descriptor on an inline wall: the three held holds' cells around the free limb's
// base, and a cell maps back to the hold nearest its centre.
TEST(ReachSectors, DescribeStateOnAnInlineWall) {
  Wall wall;
  for (const auto& [y, z] : {std::pair{1.2, 1.0}, {1.0, 1.5}, {0.6, 0.6}, {1.0, 0.0}, {0.98, 1.58}}) {
    wall.holds.push_back({wall.hold_count() + 1, at(y, z)});
  }
  HoldConfiguration state;
  state.holds = {kFree, 0, 2, 3};  // the right hand free
  const GridParameters grid = reach_grid();
  const GridPlacement placement = place_reach_sectors(grid, at(1.0, 1.0));
  const AgentState described = describe_state(wall, state, placement);
  EXPECT_EQ(described.held_tiles, (std::array<int, 3>{0, 13, 30}));
  EXPECT_EQ(encode(described, grid), ((0u * 33 + 1) * 33 + 14) * 33 + 31) << "digits are cell + 1, base 33";
  ASSERT_EQ(placement.tile_of(wall.holds[4].position), 10);
  EXPECT_EQ(hold_in_tile(wall, placement, 10), 1) << "hold 1 lies nearer cell 10's centre than hold 4";
  EXPECT_EQ(hold_in_tile(wall, placement, 1), -1);
  EXPECT_NE(describe_grid(grid), describe_grid(GridParameters{})) << "q_grid.bin files tell the spaces apart";
}

}  // namespace
}  // namespace crux
