#pragma once
// Forward kinematics, operational-point Jacobians and the centre of mass, as free
// functions over (model, data): none allocates.

#include <Eigen/Geometry>

#include "body/body_data.hpp"
#include "body/body_model.hpp"

namespace crux {

// A workspace sized for another model is a programming error: std::invalid_argument,
// checked by the two forward kinematics that every other function follows.
void check_workspace(const BodyModel& model, const BodyData& data);

// Places every joint frame and the operational points e0..e4 for posture g.
void forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g);

// The same for the joints that move an operational point only (model.operational_joints),
// the same numbers for e0..e4 and their Jacobians; the other joints' placements are left
// as they were. What IK iterates on.
void operational_forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g);

// After operational_forward_kinematics(g), places the other joints for the same g: the
// two together place every joint as forward_kinematics(g) does, to the bit.
void remaining_forward_kinematics(const BodyModel& model, BodyData& data, const Posture& g);

// The five 3 x 35 Jacobians d e_i / d G at the posture of the last forward_kinematics.
void operational_jacobians(const BodyModel& model, BodyData& data);

// After forward_kinematics, the body turned by `rotation` about its root's frame (the
// frame after the root's translations): crux's root does not turn, but a free root in
// MuJoCo does. Every placement and operational point turns; the Jacobians do not.
void turn_about_root(BodyData& data, const Eigen::Quaterniond& rotation);

// Whole-body centre of mass at the posture of the last forward_kinematics; also stored
// in data.centre_of_mass.
const Eigen::Vector3d& centre_of_mass(const BodyModel& model, BodyData& data);

}  // namespace crux
