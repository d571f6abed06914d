#pragma once
// The generalised force that gravity exerts on each coordinate of G: the first term of a
// stance's static equilibrium (docs/MODEL.md, "Gravity forces").

#include <Eigen/Core>

#include "body/body_data.hpp"
#include "body/body_model.hpp"

namespace crux {

// One value per coordinate of G: newtons on the root translations, newton-metres on the
// revolute joints.
using GeneralisedForce = Eigen::Matrix<double, kConfigurationDof, 1>;

// Standard gravity along -z, the frame's up being +z; an inclined wall tilts it.
inline const Eigen::Vector3d kStandardGravity{0.0, 0.0, -9.81};

// tau_g = sum over segments of m_i J_com_i^T gravity at posture g: what gravity exerts,
// minus the gradient of the potential energy. The torques the joints must supply to hold
// the posture still are its negative (MuJoCo's qfrc_bias at rest). Places the body in
// `data` (forward_kinematics); allocates nothing.
GeneralisedForce gravity_forces(const BodyModel& model, BodyData& data, const Posture& g,
                                const Eigen::Vector3d& gravity = kStandardGravity);

}  // namespace crux
