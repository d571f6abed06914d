#include "wall/incline.hpp"

#include <numbers>

#include <Eigen/Geometry>

namespace crux {

Eigen::Matrix3d wall_to_world(double incline_deg) {
  // About y by -theta: x -> (cos, 0, sin), z -> (-sin, 0, cos).
  return Eigen::AngleAxisd(-incline_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

}  // namespace crux
