#pragma once
// The agent space's moving grid (paper, section III-D, Fig. 2a): 5 x 7 tiles of
// 0.3 m x 0.5 m placed so that the free limb's anchor P_i lies on that limb's current
// position. A hold is named by the tile it lies in; a tile maps back to the hold
// nearest its centre among the holds lying in it.

#include <array>
#include <optional>
#include <span>
#include <string>

#include <Eigen/Core>

#include "agent_space/agent_space_kind.hpp"
#include "agent_space/reach_sectors.hpp"
#include "body/body_model.hpp"
#include "wall/wall.hpp"

namespace crux {

struct GridParameters {
  int columns = 5;  // across (y), counted from the climber's right
  int rows = 7;     // up (z), counted from the bottom
  double tile_width = 0.3;
  double tile_height = 0.5;
  // Anchor tile (column, row) of each limb, whose centre is placed on that limb
  // (docs/MODEL.md, choice C15), limb order.
  std::array<std::array<int, 2>, kLimbCount> anchors{{{1, 4}, {3, 4}, {1, 1}, {3, 1}}};
  // Under the reach agent space (reach_sectors.hpp) the tiles are its cells: columns are
  // the direction sectors, rows the distance rings, tile_height the ring width; tile_width
  // and the anchors play no part. Every table, file and figure then keeps its shape.
  AgentSpaceKind space = AgentSpaceKind::Grid;

  int tile_count() const { return columns * rows; }
};

// The grid placed for a free limb at a position on the wall (only y and z matter).
struct GridPlacement {
  Eigen::Vector2d origin;  // (y, z) of the corner of tile (0, 0): smallest y and z
  double tile_width = 0.3, tile_height = 0.5;
  int columns = 5, rows = 7;
  int anchor_tile = kOutsideGrid;     // the tile whose centre is on the free limb
  std::optional<ReachSectors> reach;  // set under the reach agent space: tiles are its cells

  // Tile number (row * columns + column) containing the point, or kOutsideGrid.
  // Tiles are half-open: a point on the edge between two tiles belongs to the tile of
  // larger y (or larger z).
  int tile_of(const Eigen::Vector3d& point) const;
  Eigen::Vector3d tile_centre(int tile) const;  // on the wall plane x = 0
  // Squared distance, in the wall plane, from a point to a tile's centre: the measure
  // by which a tile maps back to a hold.
  double squared_distance_to_centre(int tile, const Eigen::Vector3d& point) const;
};

GridPlacement place_grid(const GridParameters& grid, Limb free_limb, const Eigen::Vector3d& limb_position);
// The reach agent space's cells around the free limb's shoulder or hip (`base`).
GridPlacement place_reach_sectors(const GridParameters& grid, const Eigen::Vector3d& base);

// The grid in words, shape, tile size and anchors: what a tile code means. Q_grid files
// record it, so that a table is only read back on the grid it was learnt on.
std::string describe_grid(const GridParameters& grid);

// Grid -> wall: the hold nearest the tile's centre among those lying in the tile, or -1
// when the tile holds none (docs/MODEL.md, choice C16). Distances are measured in the wall plane;
// ties go to the hold listed first.
int hold_in_tile(const Wall& wall, const GridPlacement& placement, int tile);

}  // namespace crux
