#pragma once
// An inclined wall (docs/MODEL.md, choice C25). crux computes in wall coordinates: the
// wall is the plane x = 0, z runs up the wall, the climber is at x < 0. A wall inclined
// by theta degrees is that frame turned about y, its top leaning towards the climber
// when theta > 0 (an overhang) and away from it when theta < 0 (a slab). Holds, the body
// and the finishing height stay in wall coordinates; gravity and the drawings turn.

#include <Eigen/Core>

namespace crux {

// An incline must lie strictly between -kMaxInclineDeg and kMaxInclineDeg.
inline constexpr double kMaxInclineDeg = 90.0;

// The rotation that takes wall coordinates to the world's (z up): the wall's z axis is
// (-sin theta, 0, cos theta) in the world. Its transpose turns world gravity into wall
// coordinates, (-g sin theta, 0, -g cos theta): on an overhang part of it pulls the
// climber away from the wall (towards -x).
Eigen::Matrix3d wall_to_world(double incline_deg);

}  // namespace crux
