#pragma once
// Random walls as in section III-A: holds at the vertices of a grid of tiles, each moved
// in the wall plane by a centred normal draw. Reproducible from a seed on any machine.

#include <cstdint>

#include "wall/wall.hpp"

namespace crux {

struct RandomWallParameters {
  int columns = 4;  // tiles across (y)
  int rows = 8;     // tiles up (z)
  double tile_width = 0.3;
  double tile_height = 0.5;
  double sigma = 0.08;  // standard deviation of each hold's displacement in y and in z
  double hold_radius = 0.04;
  double finish_height = 3.0;  // calibrated on the optimal climb length (docs/DESIGN.md)
  double incline_deg = 0.0;    // from vertical, > 0 overhanging (docs/MODEL.md, choice C25)
  // Start configuration as (column, row) vertices, columns from the climber's right,
  // rows from the bottom, limb order (docs/MODEL.md, choice C5).
  std::array<std::array<int, 2>, kLimbCount> start_vertices{{{1, 3}, {3, 3}, {1, 0}, {3, 0}}};
};

// Holds are numbered 1.. row by row from the bottom-right vertex (smallest y and z).
Wall generate_random_wall(std::uint64_t seed, const RandomWallParameters& parameters = {});

}  // namespace crux
