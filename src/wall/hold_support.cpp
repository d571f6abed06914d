#include "wall/hold_support.hpp"

#include <cmath>
#include <numbers>

namespace crux {

Eigen::Vector3d support_direction(const Hold& hold, Limb limb, double support_angle_deg) {
  if (hold.support) return *hold.support;
  if (!is_hand(limb)) return Eigen::Vector3d::UnitZ();
  const double angle = support_angle_deg * std::numbers::pi / 180.0;
  return {std::sin(angle), 0.0, std::cos(angle)};
}

}  // namespace crux
