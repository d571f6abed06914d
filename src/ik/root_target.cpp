#include "ik/root_target.hpp"

#include <algorithm>

namespace crux {

Eigen::Vector3d root_target(const BodyModel& model, const std::array<Eigen::Vector3d, kLimbCount>& hold_centres,
                            const RootTargetParameters& parameters) {
  const Eigen::Vector3d& right_foot = hold_centres[static_cast<int>(Limb::RightFoot)];
  const Eigen::Vector3d& left_foot = hold_centres[static_cast<int>(Limb::LeftFoot)];
  // The climber stands on its side of the wall plane, at x < 0 (docs/MODEL.md, "Frame").
  return {-parameters.distance_from_wall, 0.5 * (right_foot.y() + left_foot.y()),
          std::min(right_foot.z(), left_foot.z()) + model.root_height_above_soles};
}

}  // namespace crux
