#pragma once
// trajectory.csv of a `crux perform` folder (docs/OUTPUTS.md): one row per recorded
// sample of the simulated climb, its time, its move, the root's rotation (a quaternion
// from its orientation on the wall), each limb's force from its hold (N, wall
// coordinates), then the body's joints as posture_csv writes them. Its one writer and
// its one reader.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "simulation/climb_trajectory.hpp"

namespace crux {

std::string trajectory_csv(const BodyModel& model, std::span<const TrajectorySample> samples);

// The samples of `file`, whose joints must be `model`'s: InputError naming the file and the
// line for another header, a cell that is not a finite number, samples out of order in
// time or in move, a rotation that is not a unit quaternion, or a posture far off its wall.
std::vector<TrajectorySample> read_trajectory_csv(const BodyModel& model, const std::filesystem::path& file);

}  // namespace crux
