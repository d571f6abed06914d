#pragma once
// MuJoCo loading the same URDF (mj_loadXML reads URDF): the independent dynamics that
// crux's kinematics and gravity forces are checked against in tests.

#include <array>
#include <string>

#include <mujoco/mujoco.h>
#include <Eigen/Core>

#include "body/body_data.hpp"
#include "body/body_model.hpp"

namespace crux::testing {

// The joint-space inertia matrix (mj_fullM) between the revolute joints, in crux's order,
// `dof_address` giving each coordinate's MuJoCo dof: it depends on every link's mass,
// centre and rotational inertia below each joint.
Eigen::MatrixXd revolute_inertia(const mjModel* model, const mjData* data,
                                 const std::array<int, kConfigurationDof>& dof_address);

class MujocoReference {
 public:
  // Throws std::runtime_error with MuJoCo's message if it refuses the file, or if its
  // joints are not crux's 35 coordinates (matched by name, not by order).
  MujocoReference(const std::string& urdf_path, const BodyModel& model);
  ~MujocoReference();
  MujocoReference(const MujocoReference&) = delete;
  MujocoReference& operator=(const MujocoReference&) = delete;

  // Puts MuJoCo at posture g with zero velocity and runs mj_forward; the queries below
  // answer for the last posture set.
  void set_posture(const Posture& g);

  // The world frame of the body that joint `joint` (crux's index) moves, after the
  // joint's motion: crux's placements[joint].origin and .rotation.
  Eigen::Vector3d joint_origin(int joint) const;
  Eigen::Matrix3d joint_rotation(int joint) const;
  // The origin of MuJoCo's body named after a URDF link (a grasp or head frame).
  Eigen::Vector3d link_origin(const std::string& link) const;
  // MuJoCo's whole-body centre of mass (subtree_com of the world), with its bounded masses.
  Eigen::Vector3d centre_of_mass() const;
  // qfrc_bias at zero velocity in crux's coordinate order: the generalised force that holds
  // the posture still against gravity, the negative of what gravity exerts.
  Posture bias_forces() const;

  // crux::testing::revolute_inertia at the last posture set.
  Eigen::MatrixXd revolute_inertia() const { return testing::revolute_inertia(model_, data_, dof_address_); }

  double total_mass() const;
  const mjModel& model() const { return *model_; }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::array<int, kConfigurationDof> qpos_address_{}, dof_address_{}, body_{};
};

}  // namespace crux::testing
