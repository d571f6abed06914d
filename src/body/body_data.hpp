#pragma once
// The mutable kinematic workspace of one thread (Pinocchio's Model/Data split): every
// buffer is sized once from the model, so the kinematic functions never allocate.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "body/body_model.hpp"

namespace crux {

using OperationalJacobian = Eigen::Matrix<double, 3, kConfigurationDof>;

struct JointPlacement {
  Eigen::Matrix3d rotation;  // joint frame in the world, after the joint's motion
  Eigen::Vector3d origin;    // joint frame origin in the world
  Eigen::Vector3d axis;      // joint axis in the world
};

// sin and cos of a joint's coordinate, kept with the coordinate's bits they were computed
// from: a solver's trial steps leave frozen and clamped joints where they were, and FK
// need not call sincos again for them.
struct JointTrigonometry {
  std::uint64_t angle_bits = 0;  // +0.0, whose sine and cosine these are
  double sine = 0.0, cosine = 1.0;
};

struct BodyData {
  explicit BodyData(const BodyModel& model);

  std::vector<JointPlacement> placements;       // one per joint of the model
  std::vector<JointTrigonometry> trigonometry;  // one per joint of the model
  // e0 (root) then the grasp points in limb order.
  std::array<Eigen::Vector3d, kOperationalPointCount> points;
  // d e_i / d G; columns outside model.chains[i] stay zero.
  std::array<OperationalJacobian, kOperationalPointCount> jacobians;
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();
};

}  // namespace crux
