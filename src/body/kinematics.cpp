#include "body/kinematics.hpp"

#include <bit>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace crux {

BodyData::BodyData(const BodyModel& model) : placements(model.joints.size()), trigonometry(model.joints.size()) {
  for (auto& p : points) p.setZero();
  for (auto& j : jacobians) j.setZero();
}

namespace {

// Rotation about the unit vector `axis` by the angle of sine s and cosine c (Rodrigues'
// formula).
Eigen::Matrix3d axis_rotation(const Eigen::Vector3d& axis, double s, double c) {
  const double t = 1.0 - c;
  const double x = axis.x(), y = axis.y(), z = axis.z();
  Eigen::Matrix3d r;
  r << t * x * x + c, t * x * y - s * z, t * x * z + s * y,  //
      t * x * y + s * z, t * y * y + c, t * y * z - s * x,   //
      t * x * z - s * y, t * y * z + s * x, t * z * z + c;
  return r;
}

}  // namespace

namespace {

const JointTrigonometry& joint_trigonometry(BodyData& data, int i, double angle) {
  JointTrigonometry& cached = data.trigonometry[i];
  // Bits, not ==: sin(-0.0) is -0.0.
  if (std::bit_cast<std::uint64_t>(angle) != cached.angle_bits) {
    cached.angle_bits = std::bit_cast<std::uint64_t>(angle);
    cached.sine = std::sin(angle);
    cached.cosine = std::cos(angle);
  }
  return cached;
}

// Places joint i from its parent's placement (already placed) and coordinate g[i].
void place_joint(const BodyModel& model, BodyData& data, const Posture& g, int i) {
  const BodyJoint& joint = model.joints[i];
  JointPlacement& out = data.placements[i];
  Eigen::Matrix3d frame;
  if (joint.parent < 0) {
    frame = joint.origin_rotation;
    out.origin = joint.origin_translation;
  } else {
    const JointPlacement& parent = data.placements[joint.parent];
    if (joint.origin_rotation_is_identity) {
      frame = parent.rotation;
    } else {
      frame.noalias() = parent.rotation * joint.origin_rotation;
    }
    out.origin = parent.origin;
    out.origin.noalias() += parent.rotation * joint.origin_translation;
  }
  out.axis.noalias() = frame * joint.axis;
  if (joint.prismatic) {
    out.rotation = frame;
    out.origin += g[i] * out.axis;
  } else if (joint.principal_axis >= 0) {
    // Rotating about a coordinate axis k mixes only the two other columns.
    const int k = joint.principal_axis, a = (k + 1) % 3, b = (k + 2) % 3;
    const JointTrigonometry& trigonometry = joint_trigonometry(data, i, g[i]);
    const double s = joint.principal_sign * trigonometry.sine;
    const double c = trigonometry.cosine;
    out.rotation.col(k) = frame.col(k);
    out.rotation.col(a) = c * frame.col(a) + s * frame.col(b);
    out.rotation.col(b) = c * frame.col(b) - s * frame.col(a);
  } else {
    const JointTrigonometry& trigonometry = joint_trigonometry(data, i, g[i]);
    out.rotation.noalias() = frame * axis_rotation(joint.axis, trigonometry.sine, trigonometry.cosine);
  }
}

void place_operational_points(const BodyModel& model, BodyData& data) {
  data.points[0] = data.placements[kRootDof - 1].origin;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const AttachedPoint& grasp = model.grasp_points[limb];
    const JointPlacement& carrier = data.placements[grasp.joint];
    data.points[operational_point(limb)] = carrier.origin;
    data.points[operational_point(limb)].noalias() += carrier.rotation * grasp.offset;
  }
}

}  // namespace

void check_workspace(const BodyModel& model, const BodyData& data) {
  if (data.placements.size() != model.joints.size() || data.trigonometry.size() != model.joints.size()) {
    throw std::invalid_argument("BodyData was sized for another body model");
  }
}

void forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g) {
  check_workspace(model, data);
  const int n = static_cast<int>(model.joints.size());
  for (int i = 0; i < n; ++i) place_joint(model, data, g, i);
  place_operational_points(model, data);
}

void operational_forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g) {
  check_workspace(model, data);
  for (const int i : model.operational_joints) place_joint(model, data, g, i);
  place_operational_points(model, data);
}

void remaining_forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g) {
  // Both lists are increasing: walk them together and place the joints the first lacks.
  auto operational = model.operational_joints.begin();
  const int n = static_cast<int>(model.joints.size());
  for (int i = 0; i < n; ++i) {
    if (operational != model.operational_joints.end() && *operational == i) {
      ++operational;
    } else {
      place_joint(model, data, g, i);
    }
  }
}

void operational_jacobians(const BodyModel& model, BodyData& data) {
  for (int k = 0; k < kOperationalPointCount; ++k) {
    const Eigen::Vector3d& point = data.points[k];
    OperationalJacobian& jacobian = data.jacobians[k];
    for (const int i : model.chains[k]) {
      const JointPlacement& joint = data.placements[i];
      if (model.joints[i].prismatic) {
        jacobian.col(i) = joint.axis;
      } else {
        jacobian.col(i) = joint.axis.cross(point - joint.origin);
      }
    }
  }
}

void turn_about_root(BodyData& data, const Eigen::Quaterniond& rotation) {
  const Eigen::Matrix3d turn = rotation.normalized().toRotationMatrix();
  const Eigen::Vector3d pivot = data.placements[kRootDof - 1].origin;
  for (std::size_t i = kRootDof - 1; i < data.placements.size(); ++i) {
    JointPlacement& placement = data.placements[i];
    placement.origin = pivot + turn * (placement.origin - pivot);
    placement.rotation = turn * placement.rotation;
    placement.axis = turn * placement.axis;
  }
  for (Eigen::Vector3d& point : data.points) point = pivot + turn * (point - pivot);
}

const Eigen::Vector3d& centre_of_mass(const BodyModel& model, BodyData& data) {
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  const int n = static_cast<int>(model.joints.size());
  for (int i = 0; i < n; ++i) {
    const BodyJoint& joint = model.joints[i];
    if (joint.mass == 0.0) continue;
    const JointPlacement& placement = data.placements[i];
    weighted += joint.mass * (placement.origin + placement.rotation * joint.centre_of_mass_local);
  }
  data.centre_of_mass = weighted / model.total_mass;
  return data.centre_of_mass;
}

}  // namespace crux
