#include "wall/incline.hpp"

#include <numbers>

#include <Eigen/Geometry>

namespace crux {

Eigen::Matrix3d wall_to_world(double incline_deg) {
  // About y by -theta: x -> (cos, 0, sin), z -> (-sin, 0, cos).
  return Eigen::AngleAxisd(-incline_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

Eigen::Vector3d gravity_in_wall_frame(double incline_deg, double g) {
  return wall_to_world(incline_deg).transpose() * Eigen::Vector3d(0.0, 0.0, -g);
}

}  // namespace crux
