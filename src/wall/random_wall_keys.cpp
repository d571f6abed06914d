#include "wall/random_wall_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_random_wall_keys(FieldsFor<Parameters>& keys, Parameters& walls) {
  keys.insert(keys.end(),
              {
                  {"wall.columns", "Tiles across a random wall", &walls.columns, "", kWallTiles},
                  {"wall.rows", "Tiles up a random wall", &walls.rows, "", kWallTiles},
                  {"wall.tile_width", "Tile width of a random wall", &walls.tile_width, "m", kTileSize},
                  {"wall.tile_height", "Tile height of a random wall", &walls.tile_height, "m", kTileSize},
                  {"wall.sigma", "Standard deviation of hold displacement", &walls.sigma, "m", kHoldScatter},
                  {"wall.hold_radius", "Hold radius", &walls.hold_radius, "m", kHoldRadius},
                  {"wall.finish_height", "Finishing height of the centre of mass, measured along the wall",
                   &walls.finish_height, "m", kWallHeight},
                  {"wall.incline", "Incline of a random wall from vertical (> 0 overhanging, < 0 slab)",
                   &walls.incline_deg, "degrees", kOpenRightAngle},
              });
}

}  // namespace

void random_wall_keys(std::vector<ConfigField>& keys, RandomWallParameters& walls) {
  declare_random_wall_keys(keys, walls);
}
void random_wall_keys(std::vector<ConstConfigField>& keys, const RandomWallParameters& walls) {
  declare_random_wall_keys(keys, walls);
}

}  // namespace crux
