#include "body/wall_penetration.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace crux {

Eigen::Vector3d deepest_point(const BodyVisual& visual, const JointPlacement& carrier) {
  const Eigen::Vector3d centre = carrier.origin + carrier.rotation * visual.translation;
  const Eigen::Matrix3d axes = carrier.rotation * visual.rotation;
  const Eigen::Vector3d& size = visual.size;
  // Towards +x along an axis a: the end whose x is larger (either, when a is parallel to the plane).
  const auto towards_x = [](double component) { return component >= 0.0 ? 1.0 : -1.0; };
  switch (visual.shape) {
    case VisualShape::Box: {
      Eigen::Vector3d point = centre;
      for (int i = 0; i < 3; ++i) point += 0.5 * size[i] * towards_x(axes(0, i)) * axes.col(i);
      return point;
    }
    case VisualShape::Cylinder: {
      const Eigen::Vector3d axis = axes.col(2);
      // The rim's deepest point lies along +x with the axis' part removed.
      const Eigen::Vector3d across = Eigen::Vector3d::UnitX() - axis.x() * axis;
      const double norm = across.norm();
      Eigen::Vector3d point = centre + 0.5 * size.y() * towards_x(axis.x()) * axis;
      if (norm > 1e-12) point += size.x() / norm * across;
      return point;
    }
    case VisualShape::Sphere:
      return centre + size.x() * Eigen::Vector3d::UnitX();
  }
  return centre;
}

bool counts_for_the_wall(const BodyModel& model, const BodyVisual& visual) {
  return std::none_of(model.grasp_points.begin(), model.grasp_points.end(),
                      [&](const AttachedPoint& p) { return p.joint == visual.joint; });
}

WallPenetration wall_penetration(const BodyModel& model, const BodyData& data) {
  WallPenetration deepest;
  for (std::size_t v = 0; v < model.visuals.size(); ++v) {
    const BodyVisual& visual = model.visuals[v];
    if (!counts_for_the_wall(model, visual)) continue;
    const double depth = deepest_point(visual, data.placements[visual.joint]).x();
    if (deepest.visual < 0 || depth > deepest.depth_m) deepest = {depth, static_cast<int>(v)};
  }
  return deepest;
}

void deepest_x_gradient(const BodyModel& model, const BodyData& data, int visual, Posture& gradient) {
  gradient.setZero();
  const BodyVisual& v = model.visuals[visual];
  const Eigen::Vector3d point = deepest_point(v, data.placements[v.joint]);
  for (int j = v.joint; j >= 0; j = model.joints[j].parent) {
    const JointPlacement& placement = data.placements[j];
    gradient[j] = model.joints[j].prismatic ? placement.axis.x() : placement.axis.cross(point - placement.origin).x();
  }
}

}  // namespace crux
