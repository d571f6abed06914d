#include "ik/reach_target.hpp"

#include <algorithm>

namespace crux {

double grasp_residual(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target) {
  double worst = 0.0;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    worst = std::max(worst, (points[operational_point(limb)] - target.hold_centres[limb]).norm());
  }
  return worst;
}

bool target_reached(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target,
                    const ReachTolerances& tolerances) {
  // Written as "within" tests so that a NaN posture never passes.
  if (!((points[0] - target.root).squaredNorm() <= tolerances.root_radius * tolerances.root_radius)) return false;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const double contact = tolerances.grasp_radius + target.hold_radii[limb];
    if (!((points[operational_point(limb)] - target.hold_centres[limb]).squaredNorm() <= contact * contact))
      return false;
  }
  return true;
}

bool beyond_reach(const ReachEnvelope& envelope, const ReachTarget& target, const ReachTolerances& tolerances) {
  // Rounding slack, so that a target the termination test accepts is never ruled out.
  constexpr double kSlack = 1e-9;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const double farthest =
        tolerances.root_radius + envelope.radius[limb] + tolerances.grasp_radius + target.hold_radii[limb] + kSlack;
    const Eigen::Vector3d from_base = target.hold_centres[limb] - (target.root + envelope.chain_base[limb]);
    if (from_base.squaredNorm() > farthest * farthest) return true;
  }
  return false;
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

double reach_cost(const std::array<Eigen::Vector3d, kOperationalPointCount>& points, const ReachTarget& target) {
  double cost = 0.5 * (points[0] - target.root).squaredNorm();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    cost += 0.5 * (points[operational_point(limb)] - target.hold_centres[limb]).squaredNorm();
  }
  return cost;
}

}  // namespace crux
