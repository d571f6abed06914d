#pragma once
// The [grid] keys of the agent space (GridParameters), declared beside it and gathered
// by experiments/experiment_config.

#include "agent_space/moving_grid.hpp"
#include "common/config_field.hpp"

namespace crux {

// Tiles of the agent space: 1000 x 1000 cells hold far more than 32-bit agent-state
// codes allow (checked with the other keys), so the count itself never overflows.
inline constexpr Bounds kGridTiles = work_size(1, 1000);
// A tile of the agent space: an anchor is one (checked against columns and rows for the grid).
inline constexpr Bounds kAnchorTile = closed_range(0, 999, "a tile of the grid");

// The [grid] keys.
void grid_keys(std::vector<ConfigField>& keys, GridParameters& grid);
void grid_keys(std::vector<ConstConfigField>& keys, const GridParameters& grid);

}  // namespace crux
