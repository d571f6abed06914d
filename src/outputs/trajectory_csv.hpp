#pragma once
// trajectory.csv of a `crux perform` folder (docs/OUTPUTS.md): one row per recorded
// sample of the simulated climb, its time, its move, the root's rotation (a quaternion
// from its orientation on the wall), each limb's force from its hold (N, wall
// coordinates), then the body's joints as posture_csv writes them.

#include <span>
#include <string>

#include "simulation/climb_trajectory.hpp"

namespace crux {

std::string trajectory_csv(const BodyModel& model, std::span<const TrajectorySample> samples);

}  // namespace crux
