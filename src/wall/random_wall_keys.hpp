#pragma once
// The [wall] keys of the random wall generator (RandomWallParameters), declared beside it
// and gathered by experiments/experiment_config, whose [training_wall] keys take the
// same bounds.

#include "common/config_field.hpp"
#include "wall/incline.hpp"
#include "wall/random_wall.hpp"
#include "wall/wall.hpp"

namespace crux {

// Tiles of a random wall: its holds, (columns + 1) x (rows + 1), are at most kMaxHoldCount.
inline constexpr Bounds kWallTiles = work_size(1, kMaxHoldCount);
// The holds' displacement: four times the body's span moves a hold anywhere on the wall.
inline constexpr Bounds kHoldScatter = closed_range(0, 10);
// A hold's radius: from a crimp to a 1 m ledge.
inline constexpr Bounds kHoldRadius{.min = 0, .max = 1, .min_open = true};
// A height on the wall: a random wall is at most kMaxHoldCount holds of at most 10 m tiles
// tall, but a finish higher than this is never reached by a body that climbs 0.5 m a move
// within the longest run's greedy climb.
inline constexpr Bounds kWallHeight = closed_range(-1000, 1000);
inline constexpr Bounds kOpenRightAngle{
    .min = -kMaxInclineDeg, .max = kMaxInclineDeg, .min_open = true, .max_open = true};

// The random wall generator's keys, wall.columns to wall.incline.
void random_wall_keys(std::vector<ConfigField>& keys, RandomWallParameters& walls);
void random_wall_keys(std::vector<ConstConfigField>& keys, const RandomWallParameters& walls);

}  // namespace crux
