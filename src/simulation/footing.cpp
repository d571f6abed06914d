#include "simulation/footing.hpp"

#include <stdexcept>

#include <mujoco/mujoco.h>
#include <Eigen/Geometry>

#include "simulation/mjcf_model.hpp"

namespace crux {

namespace {

int body_of(const mjModel_* model, Limb foot) {
  const int body = mj_name2id(model, mjOBJ_BODY, mjcf_footing_name(foot).c_str());
  if (body < 0 || model->body_mocapid[body] < 0) {
    throw std::invalid_argument("the MuJoCo model has no footing '" + mjcf_footing_name(foot) + "'");
  }
  return body;
}

}  // namespace

Footing::Footing(const mjModel_* model, Limb foot) : body_(body_of(model, foot)), mocap_(model->body_mocapid[body_]) {}

void Footing::take(mjData_* data, const Eigen::Vector3d& grasp_point, const Eigen::Vector3d& support) const {
  const Eigen::Vector3d top = grasp_point - kFootContactRadius * support;
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), support);
  for (int k = 0; k < 3; ++k) data->mocap_pos[3 * mocap_ + k] = top[k];
  data->mocap_quat[4 * mocap_] = turn.w();
  data->mocap_quat[4 * mocap_ + 1] = turn.x();
  data->mocap_quat[4 * mocap_ + 2] = turn.y();
  data->mocap_quat[4 * mocap_ + 3] = turn.z();
}

void Footing::release(mjData_* data) const {
  for (int k = 0; k < 3; ++k) data->mocap_pos[3 * mocap_ + k] = kParkedFooting[k];
  data->mocap_quat[4 * mocap_] = 1.0;
  for (int k = 1; k < 4; ++k) data->mocap_quat[4 * mocap_ + k] = 0.0;
}

bool Footing::taken(const mjData_* data) const {
  return (Eigen::Vector3d(data->mocap_pos + 3 * mocap_) - kParkedFooting).norm() > 1.0;
}

}  // namespace crux
