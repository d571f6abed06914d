#pragma once
// Front view of a wall as a standalone SVG figure (paper, Fig. 2a): the holds with their
// ids, the start configuration, the finishing height and, optionally, the agent space's
// moving grid with the tile each hold lies in and the hold each tile projects onto.

#include <optional>
#include <string>

#include "agent_space/moving_grid.hpp"
#include "body/body_model.hpp"
#include "wall/wall.hpp"

namespace crux {

struct WallSvgOptions {
  double pixels_per_metre = 150;
  bool number_holds = true;           // hold ids next to each hold
  bool mark_start = true;             // each start hold marked with its limb (RH, LH, RF, LF) + legend
  std::optional<GridPlacement> grid;  // draw the moving grid (Fig. 2a)
  // Whose anchor tile to highlight, with a green dot at its centre (the P_i point). The
  // anchor tiles are those of docs/MODEL.md, choice C15 (GridParameters' defaults), as the
  // placement does not carry them.
  std::optional<Limb> grid_limb;
};

// A standalone SVG 1.1 document, drawn as the climber sees the wall: larger y (the
// climber's left) further left on screen, z up. Deterministic: the same wall and options
// give the same bytes. Throws std::invalid_argument for a non-positive scale.
std::string render_wall_svg(const Wall& wall, const WallSvgOptions& options = {});

}  // namespace crux
