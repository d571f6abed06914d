#include "simulation/grasp.hpp"

#include <stdexcept>

#include <mujoco/mujoco.h>

namespace crux {

GraspVerdict grasp_verdict(const PointContact& contact, const Eigen::Vector3d& force, double tolerance) {
  if (force.dot(contact.support_direction) > contact.normal_force_limit + tolerance) return GraspVerdict::GripExceeded;
  if (!inside_friction_pyramid(contact, force, tolerance)) return GraspVerdict::OutsideFriction;
  return GraspVerdict::Held;
}

Grasp::Grasp(const mjModel_* model, const std::string& name) : id_(mj_name2id(model, mjOBJ_EQUALITY, name.c_str())) {
  if (id_ < 0 || model->eq_type[id_] != mjEQ_CONNECT) {
    throw std::invalid_argument("the MuJoCo model has no grasp constraint '" + name + "'");
  }
}

void Grasp::take(mjModel_* model, const Eigen::Vector3d& hold) const {
  // A connect's data: the anchor in its first body (the hand's grasp point), then in its
  // second, the world here.
  for (int k = 0; k < 3; ++k) model->eq_data[mjNEQDATA * id_ + 3 + k] = hold[k];
  model->eq_active[id_] = 1;
}

void Grasp::release(mjModel_* model) const { model->eq_active[id_] = 0; }

bool Grasp::taken(const mjModel_* model) const { return model->eq_active[id_] != 0; }

Eigen::Vector3d Grasp::force(const mjModel_* model, const mjData_* data) const {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  if (!taken(model)) return out;
  // The constraint's three rows, in x, y, z order: the force on its first body.
  int row = 0;
  for (int i = 0; i < data->nefc && row < 3; ++i) {
    if (data->efc_type[i] == mjCNSTR_EQUALITY && data->efc_id[i] == id_) out[row++] = data->efc_force[i];
  }
  return out;
}

}  // namespace crux
