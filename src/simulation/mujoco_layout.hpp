#pragma once
// Where crux's coordinates are in the MuJoCo model crux wrote (simulation/mjcf_model): the
// free root's place in qpos and qvel, each revolute joint's address and servo, each
// limb's grasp site, found by name once. The functions below read and write a simulation
// in crux's terms: wall coordinates, crux's coordinate order.

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "body/body_model.hpp"

struct mjModel_;
struct mjData_;

namespace crux {

struct MujocoLayout {
  int root_qpos = -1, root_dof = -1, root_body = -1;
  // Revolute coordinates only (-1 on the root's three).
  std::array<int, kConfigurationDof> qpos{}, dof{}, actuator{};
  std::array<int, kLimbCount> grasp_site{};
  // The body each grasp site rides on: a foot's contacts are those of its body's geoms.
  std::array<int, kLimbCount> limb_body{};
  Eigen::Matrix3d to_world = Eigen::Matrix3d::Identity();  // wall coordinates to MuJoCo's world
};

// std::invalid_argument when `mujoco` lacks a joint, servo or site of `model`: a model
// that crux did not write for this body.
MujocoLayout mujoco_layout(const BodyModel& model, const mjModel_* mujoco, double incline_deg);

// The body at posture `g` (wall coordinates, the torso unturned against the wall), at rest,
// then mj_forward.
void place_at_rest(const MujocoLayout& layout, const mjModel_* mujoco, mjData_* data, const Posture& g);

// The simulated posture in crux's coordinates: the root's position in wall coordinates and
// the joint angles (the root's rotation, which crux's model does not have, aside).
Posture simulated_posture(const MujocoLayout& layout, const mjData_* data);

// The root's rotation from its orientation on the wall, in wall coordinates (the identity
// while it has not turned).
Eigen::Quaterniond root_orientation(const MujocoLayout& layout, const mjData_* data);

// The angle, radians, by which the root has turned from its orientation on the wall.
double root_turn(const MujocoLayout& layout, const mjData_* data);

// A limb's grasp point, wall coordinates, as the last mj_forward or mj_step placed it.
Eigen::Vector3d simulated_grasp_point(const MujocoLayout& layout, const mjData_* data, Limb limb);

}  // namespace crux
