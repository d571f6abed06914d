#include "agent_space/moving_grid.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace crux {

GridPlacement place_grid(const GridParameters& grid, Limb free_limb, const Eigen::Vector3d& limb_position) {
  const auto& anchor = grid.anchors[static_cast<int>(free_limb)];
  GridPlacement placement;
  placement.tile_width = grid.tile_width;
  placement.tile_height = grid.tile_height;
  placement.columns = grid.columns;
  placement.rows = grid.rows;
  placement.anchor_tile = anchor[1] * grid.columns + anchor[0];
  // The anchor is the centre of its tile: half a tile in from that tile's corner.
  placement.origin = {limb_position.y() - (anchor[0] + 0.5) * grid.tile_width,
                      limb_position.z() - (anchor[1] + 0.5) * grid.tile_height};
  return placement;
}

GridPlacement place_reach_sectors(const GridParameters& grid, const Eigen::Vector3d& base) {
  GridPlacement placement;
  placement.columns = grid.columns;
  placement.rows = grid.rows;
  placement.reach = ReachSectors{{base.y(), base.z()}, grid.columns, grid.rows, grid.tile_height};
  return placement;
}

int GridPlacement::tile_of(const Eigen::Vector3d& point) const {
  if (reach) return reach->cell_of(point);
  const double column = std::floor((point.y() - origin.x()) / tile_width);
  const double row = std::floor((point.z() - origin.y()) / tile_height);
  if (!(column >= 0 && column < columns && row >= 0 && row < rows)) return kOutsideGrid;  // NaN is outside too
  return static_cast<int>(row) * columns + static_cast<int>(column);
}

Eigen::Vector3d GridPlacement::tile_centre(int tile) const {
  if (reach) return reach->cell_centre(tile);
  const int column = tile % columns, row = tile / columns;
  return {0.0, origin.x() + (column + 0.5) * tile_width, origin.y() + (row + 0.5) * tile_height};
}

double GridPlacement::squared_distance_to_centre(int tile, const Eigen::Vector3d& point) const {
  const Eigen::Vector3d centre = tile_centre(tile);
  return (Eigen::Vector2d(point.y(), point.z()) - Eigen::Vector2d(centre.y(), centre.z())).squaredNorm();
}

int hold_in_tile(const Wall& wall, const GridPlacement& placement, int tile) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < wall.hold_count(); ++i) {
    const Eigen::Vector3d& p = wall.holds[i].position;
    if (placement.tile_of(p) != tile) continue;
    const double distance = placement.squared_distance_to_centre(tile, p);
    if (distance < best_distance) {  // strict: ties keep the lower index
      best_distance = distance;
      best = i;
    }
  }
  return best;
}

std::string describe_grid(const GridParameters& grid) {
  if (grid.space == AgentSpaceKind::Reach) {
    return fmt::format("reach sectors: {} directions x {} rings of {} m around the free limb's shoulder or hip",
                       grid.columns, grid.rows, grid.tile_height);
  }
  std::string anchors;
  for (const auto& anchor : grid.anchors) anchors += fmt::format(" ({}, {})", anchor[0], anchor[1]);
  return fmt::format("a {} x {} moving grid of {} x {} m tiles, anchors{}", grid.columns, grid.rows, grid.tile_width,
                     grid.tile_height, anchors);
}

}  // namespace crux
