#include "ik/reach_target.hpp"

#include <algorithm>

namespace crux {

double grasp_residual(const std::array<Eigen::Vector3d, kOperationalPointCount>& points,
                      const ReachTarget& target) {
  double worst = 0.0;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    worst = std::max(worst, (points[operational_point(limb)] - target.hold_centres[limb]).norm());
  }
  return worst;
}

bool target_reached(const std::array<Eigen::Vector3d, kOperationalPointCount>& points,
                    const ReachTarget& target, const ReachTolerances& tolerances) {
  // Written as "within" tests so that a NaN posture never passes.
  if (!((points[0] - target.root).squaredNorm() <= tolerances.root_radius * tolerances.root_radius)) return false;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const double contact = tolerances.grasp_radius + target.hold_radii[limb];
    if (!((points[operational_point(limb)] - target.hold_centres[limb]).squaredNorm() <= contact * contact)) return false;
  }
  return true;
}

double tolerance_excess(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target,
                        const ReachTolerances& tolerances) {
  double worst = (points[0] - target.root).norm() - tolerances.root_radius;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    worst = std::max(worst, (points[operational_point(limb)] - target.hold_centres[limb]).norm() -
                                tolerances.grasp_radius - target.hold_radii[limb]);
  }
  return worst;
}

double reach_cost(const std::array<Eigen::Vector3d, kOperationalPointCount>& points,
                  const ReachTarget& target) {
  double cost = 0.5 * (points[0] - target.root).squaredNorm();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    cost += 0.5 * (points[operational_point(limb)] - target.hold_centres[limb]).squaredNorm();
  }
  return cost;
}

}  // namespace crux
