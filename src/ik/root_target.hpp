#pragma once
// The root target heuristic H(C4) (paper, III-B; docs/MODEL.md, choice C8).

#include <array>

#include <Eigen/Core>

#include "body/body_model.hpp"

namespace crux {

struct RootTargetParameters {
  double distance_from_wall = 0.30;  // metres from the wall plane, on the climber's side (x < 0)
};

// y: midway between the two foot holds; z: the lowest foot hold plus the root's height
// above the soles when standing; x: -`distance_from_wall`, since the climber stands at
// x < 0 facing the wall.
Eigen::Vector3d root_target(const BodyModel& model, const std::array<Eigen::Vector3d, kLimbCount>& hold_centres,
                            const RootTargetParameters& parameters = {});

}  // namespace crux
