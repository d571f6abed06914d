#include "body/gravity_forces.hpp"

#include <array>

#include "body/kinematics.hpp"

namespace crux {

GeneralisedForce gravity_forces(const BodyModel& model, BodyData& data, const Posture& g,
                                const Eigen::Vector3d& gravity) {
  forward_kinematics(model, data, g);
  // A joint's Jacobian column is the same for every point it carries (axis x (p - origin),
  // or the axis when it slides), so the sum over segments needs only the mass each joint
  // carries and that mass's first moment: accumulated leaves first, every parent coming
  // before its children in model.joints.
  const int n = static_cast<int>(model.joints.size());
  std::array<double, kConfigurationDof> carried_mass{};
  std::array<Eigen::Vector3d, kConfigurationDof> carried_moment;
  for (int i = 0; i < n; ++i) {
    const BodyJoint& joint = model.joints[i];
    const JointPlacement& placement = data.placements[i];
    carried_mass[i] = joint.mass;
    carried_moment[i] = joint.mass * (placement.origin + placement.rotation * joint.centre_of_mass_local);
  }
  for (int i = n - 1; i >= 0; --i) {
    const int parent = model.joints[i].parent;
    if (parent < 0) continue;
    carried_mass[parent] += carried_mass[i];
    carried_moment[parent] += carried_moment[i];
  }
  GeneralisedForce forces;
  for (int i = 0; i < n; ++i) {
    const JointPlacement& placement = data.placements[i];
    if (model.joints[i].prismatic) {
      forces[i] = carried_mass[i] * placement.axis.dot(gravity);
    } else {
      // sum of m_k gravity . (axis x (p_k - origin)) = axis . ((sum of m_k p_k - M origin) x gravity)
      const Eigen::Vector3d lever_moment = carried_moment[i] - carried_mass[i] * placement.origin;
      forces[i] = placement.axis.dot(lever_moment.cross(gravity));
    }
  }
  return forces;
}

}  // namespace crux
