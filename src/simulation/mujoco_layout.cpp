#include "simulation/mujoco_layout.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>
#include <Eigen/Geometry>

#include "simulation/mjcf_model.hpp"
#include "wall/incline.hpp"

namespace crux {

namespace {

int require(const mjModel* mujoco, mjtObj type, const std::string& name) {
  const int id = mj_name2id(mujoco, type, name.c_str());
  if (id < 0) throw std::invalid_argument("the MuJoCo model has no '" + name + "'");
  return id;
}

}  // namespace

MujocoLayout mujoco_layout(const BodyModel& model, const mjModel_* mujoco, double incline_deg) {
  MujocoLayout layout;
  layout.to_world = wall_to_world(incline_deg);
  const int root = require(mujoco, mjOBJ_JOINT, kMjcfRoot);
  if (mujoco->jnt_type[root] != mjJNT_FREE) throw std::invalid_argument("the MuJoCo model's root is not free");
  layout.root_qpos = mujoco->jnt_qposadr[root];
  layout.root_dof = mujoco->jnt_dofadr[root];
  layout.root_body = require(mujoco, mjOBJ_BODY, kMjcfRoot);
  layout.qpos.fill(-1);
  layout.dof.fill(-1);
  layout.actuator.fill(-1);
  for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i) {
    const int joint = require(mujoco, mjOBJ_JOINT, model.joints[i].name);
    layout.qpos[i] = mujoco->jnt_qposadr[joint];
    layout.dof[i] = mujoco->jnt_dofadr[joint];
    layout.actuator[i] = require(mujoco, mjOBJ_ACTUATOR, model.joints[i].name);
  }
  for (int limb = 0; limb < kLimbCount; ++limb) {
    layout.grasp_site[limb] = require(mujoco, mjOBJ_SITE, model.grasp_frame_names[limb]);
    layout.limb_body[limb] = mujoco->site_bodyid[layout.grasp_site[limb]];
  }
  return layout;
}

void place_at_rest(const MujocoLayout& layout, const mjModel_* mujoco, mjData_* data, const Posture& g) {
  mj_resetData(mujoco, data);
  const Eigen::Vector3d root = layout.to_world * g.head<kRootDof>();
  const Eigen::Quaterniond turn(layout.to_world);
  for (int k = 0; k < 3; ++k) data->qpos[layout.root_qpos + k] = root[k];
  data->qpos[layout.root_qpos + 3] = turn.w();
  data->qpos[layout.root_qpos + 4] = turn.x();
  data->qpos[layout.root_qpos + 5] = turn.y();
  data->qpos[layout.root_qpos + 6] = turn.z();
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    if (layout.qpos[i] >= 0) data->qpos[layout.qpos[i]] = g[i];
  }
  mj_forward(mujoco, data);
}

Posture simulated_posture(const MujocoLayout& layout, const mjData_* data) {
  Posture g = Posture::Zero();
  g.head<kRootDof>() = layout.to_world.transpose() * Eigen::Vector3d(data->qpos + layout.root_qpos);
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    if (layout.qpos[i] >= 0) g[i] = data->qpos[layout.qpos[i]];
  }
  return g;
}

Eigen::Quaterniond root_orientation(const MujocoLayout& layout, const mjData_* data) {
  const double* q = data->qpos + layout.root_qpos + 3;
  const Eigen::Quaterniond world(q[0], q[1], q[2], q[3]);
  return Eigen::Quaterniond(layout.to_world).conjugate() * world;
}

double root_turn(const MujocoLayout& layout, const mjData_* data) {
  return root_orientation(layout, data).angularDistance(Eigen::Quaterniond::Identity());
}

Eigen::Vector3d simulated_grasp_point(const MujocoLayout& layout, const mjData_* data, Limb limb) {
  return layout.to_world.transpose() * Eigen::Vector3d(data->site_xpos + 3 * layout.grasp_site[static_cast<int>(limb)]);
}

}  // namespace crux
