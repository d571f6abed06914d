#include "agent_space/reach_sectors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "agent_space/agent_space_kind.hpp"

namespace crux {

int ReachSectors::cell_of(const Eigen::Vector3d& point) const {
  const Eigen::Vector2d offset(point.y() - base.x(), point.z() - base.y());
  const double ring = std::floor(offset.norm() / ring_width);
  if (!(ring >= 0 && ring < rings)) return kOutsideGrid;  // NaN is outside too
  double angle = std::atan2(offset.y(), offset.x());
  if (angle < 0) angle += 2 * std::numbers::pi;
  // min: an angle that rounds up to 2 pi belongs to the last sector.
  const int sector = std::min(static_cast<int>(angle / (2 * std::numbers::pi / sectors)), sectors - 1);
  return static_cast<int>(ring) * sectors + sector;
}

Eigen::Vector3d ReachSectors::cell_centre(int cell) const {
  const int ring = cell / sectors, sector = cell % sectors;
  const double radius = (ring + 0.5) * ring_width, angle = (sector + 0.5) * 2 * std::numbers::pi / sectors;
  return {0.0, base.x() + radius * std::cos(angle), base.y() + radius * std::sin(angle)};
}

}  // namespace crux
