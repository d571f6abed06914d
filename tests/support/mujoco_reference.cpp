#include "support/mujoco_reference.hpp"

#include <stdexcept>

namespace crux::testing {

namespace {

mjModel* load_mujoco_model(const std::string& urdf_path) {
  char error[1000] = "";
  mjModel* model = mj_loadXML(urdf_path.c_str(), nullptr, error, sizeof error);
  if (!model) throw std::runtime_error("MuJoCo refused " + urdf_path + ": " + error);
  return model;
}

Eigen::Vector3d vector_at(const mjtNum* values, int index) {
  return {values[3 * index], values[3 * index + 1], values[3 * index + 2]};
}

}  // namespace

MujocoReference::MujocoReference(const std::string& urdf_path, const BodyModel& model)
    : model_(load_mujoco_model(urdf_path)), data_(mj_makeData(model_)) {
  if (model_->nq != kConfigurationDof || model_->nv != kConfigurationDof) {
    throw std::runtime_error("MuJoCo sees " + std::to_string(model_->nq) + " coordinates in " + urdf_path);
  }
  for (int i = 0; i < kConfigurationDof; ++i) {
    const BodyJoint& joint = model.joints[i];
    const int id = mj_name2id(model_, mjOBJ_JOINT, joint.name.c_str());
    if (id < 0) throw std::runtime_error("MuJoCo has no joint " + joint.name);
    if (model_->jnt_type[id] != (joint.prismatic ? mjJNT_SLIDE : mjJNT_HINGE)) {
      throw std::runtime_error("MuJoCo reads joint " + joint.name + " as another type");
    }
    qpos_address_[i] = model_->jnt_qposadr[id];
    dof_address_[i] = model_->jnt_dofadr[id];
    body_[i] = model_->jnt_bodyid[id];
  }
}

MujocoReference::~MujocoReference() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

void MujocoReference::set_posture(const Posture& g) {
  for (int i = 0; i < kConfigurationDof; ++i) {
    data_->qpos[qpos_address_[i]] = g[i];
    data_->qvel[dof_address_[i]] = 0.0;
  }
  mj_forward(model_, data_);
}

Eigen::Vector3d MujocoReference::joint_origin(int joint) const { return vector_at(data_->xpos, body_[joint]); }

Eigen::Matrix3d MujocoReference::joint_rotation(int joint) const {
  // xmat is row-major.
  return Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>>(data_->xmat + 9 * body_[joint]);
}

Eigen::Vector3d MujocoReference::link_origin(const std::string& link) const {
  const int id = mj_name2id(model_, mjOBJ_BODY, link.c_str());
  if (id < 0) throw std::runtime_error("MuJoCo has no body " + link + " (fused away without fusestatic=\"false\"?)");
  return vector_at(data_->xpos, id);
}

Eigen::Vector3d MujocoReference::centre_of_mass() const { return vector_at(data_->subtree_com, 0); }

Posture MujocoReference::bias_forces() const {
  Posture out;
  for (int i = 0; i < kConfigurationDof; ++i) out[i] = data_->qfrc_bias[dof_address_[i]];
  return out;
}

Eigen::MatrixXd revolute_inertia(const mjModel* model, const mjData* data,
                                 const std::array<int, kConfigurationDof>& dof_address) {
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> full(model->nv, model->nv);
  mj_fullM(model, full.data(), data->qM);
  Eigen::MatrixXd out(kRevoluteDof, kRevoluteDof);
  for (int i = 0; i < kRevoluteDof; ++i) {
    for (int k = 0; k < kRevoluteDof; ++k) out(i, k) = full(dof_address[kRootDof + i], dof_address[kRootDof + k]);
  }
  return out;
}

double MujocoReference::total_mass() const { return mj_getTotalmass(model_); }

}  // namespace crux::testing
