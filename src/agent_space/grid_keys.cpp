#include "agent_space/grid_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_grid_keys(FieldsFor<Parameters>& keys, Parameters& grid) {
  keys.insert(
      keys.end(),
      {
          {"grid.agent_space",
           "Agent space (docs/TRANSFER.md): grid (the paper's moving grid) or reach (direction sectors = columns and "
           "distance rings of tile_height m = rows around the free limb's shoulder or hip)",
           choice_of(&grid.space)},
          {"grid.columns", "Columns of the moving grid", &grid.columns, "", kGridTiles},
          {"grid.rows", "Rows of the moving grid", &grid.rows, "", kGridTiles},
          {"grid.tile_width", "Tile width of the moving grid", &grid.tile_width, "m", kTileSize},
          {"grid.tile_height", "Tile height of the moving grid", &grid.tile_height, "m", kTileSize},
          {"grid.right_hand_anchor_column", "Right hand's anchor tile P_1: column", &grid.anchors[0][0], "",
           kAnchorTile},
          {"grid.right_hand_anchor_row", "Right hand's anchor tile P_1: row", &grid.anchors[0][1], "", kAnchorTile},
          {"grid.left_hand_anchor_column", "Left hand's anchor tile P_2: column", &grid.anchors[1][0], "", kAnchorTile},
          {"grid.left_hand_anchor_row", "Left hand's anchor tile P_2: row", &grid.anchors[1][1], "", kAnchorTile},
          {"grid.right_foot_anchor_column", "Right foot's anchor tile P_3: column", &grid.anchors[2][0], "",
           kAnchorTile},
          {"grid.right_foot_anchor_row", "Right foot's anchor tile P_3: row", &grid.anchors[2][1], "", kAnchorTile},
          {"grid.left_foot_anchor_column", "Left foot's anchor tile P_4: column", &grid.anchors[3][0], "", kAnchorTile},
          {"grid.left_foot_anchor_row", "Left foot's anchor tile P_4: row", &grid.anchors[3][1], "", kAnchorTile},
      });
}

}  // namespace

void grid_keys(std::vector<ConfigField>& keys, GridParameters& grid) { declare_grid_keys(keys, grid); }
void grid_keys(std::vector<ConstConfigField>& keys, const GridParameters& grid) { declare_grid_keys(keys, grid); }

}  // namespace crux
