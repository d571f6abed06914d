#include "wall/random_wall.hpp"

#include <fmt/format.h>

#include "common/random.hpp"

namespace crux {

Wall generate_random_wall(std::uint64_t seed, const RandomWallParameters& p) {
  Random random(seed);
  Wall wall;
  wall.name = fmt::format("random wall, seed {}", seed);
  wall.finish_height = p.finish_height;
  wall.incline_deg = p.incline_deg;
  const int vertex_columns = p.columns + 1;
  for (int row = 0; row <= p.rows; ++row) {
    for (int column = 0; column < vertex_columns; ++column) {
      Hold hold;
      hold.id = row * vertex_columns + column + 1;
      const double dy = random.normal(0.0, p.sigma);
      const double dz = random.normal(0.0, p.sigma);
      hold.position = {0.0, column * p.tile_width + dy, row * p.tile_height + dz};
      hold.radius = p.hold_radius;
      wall.holds.push_back(hold);
    }
  }
  for (int limb = 0; limb < kLimbCount; ++limb) {
    wall.start[limb] = p.start_vertices[limb][1] * vertex_columns + p.start_vertices[limb][0];
  }
  return wall;
}

}  // namespace crux
