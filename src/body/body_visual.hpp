#pragma once
// A primitive of the body's drawing, read from a URDF <visual>: crux's kinematics never
// uses it, the views (Fig. 1, the 3D replay) draw the body from it.

#include <array>
#include <string>

#include <Eigen/Core>

#include "common/enum_names.hpp"

namespace crux {

enum class VisualShape { Box, Cylinder, Sphere };

template <>
struct EnumNames<VisualShape> {
  static constexpr std::array<EnumName<VisualShape>, 3> entries{
      {{VisualShape::Box, "box"}, {VisualShape::Cylinder, "cylinder"}, {VisualShape::Sphere, "sphere"}}};
};

struct BodyVisual {
  std::string link;
  int joint = -1;  // the moving joint that carries the link (index into BodyModel::joints)
  // The primitive's frame in that joint's frame.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  VisualShape shape = VisualShape::Sphere;
  // Box: x, y, z lengths; cylinder (along its local z, centred): radius, length, 0;
  // sphere: radius, 0, 0.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::array<double, 4> rgba{0.7, 0.7, 0.7, 1.0};  // URDF's default when no colour is given
};

}  // namespace crux
