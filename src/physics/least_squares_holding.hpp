#pragma once
// A stance's holding torques when the static model has none (docs/PHYSICS.md, "Performed
// in MuJoCo"): the smallest contact forces, in the least-squares sense, that balance the
// weight and its moment about the root, with no regard for friction cones, grips or torque
// limits, and the joint torques that then hold the posture still. What a simulated move
// applies as feed-forward on a stance the static program finds unbalanced.

#include <array>
#include <span>

#include "body/body_data.hpp"
#include "body/gravity_forces.hpp"
#include "physics/contact_model.hpp"

namespace crux {

struct LeastSquaresHolding {
  // The force each hold exerts on its limb, newtons, limb order; zero for free limbs.
  std::array<Eigen::Vector3d, kLimbCount> contact_forces;
  GeneralisedForce joint_torques = GeneralisedForce::Zero();
};

// The f_c of least total squared norm whose force and moment about the root cancel
// gravity's (the minimum-norm least-squares solution when the contacts cannot), and
// tau = -(tau_g + sum J_c^T f_c), zero on the root's translations. Places the body in `data`.
LeastSquaresHolding least_squares_holding(const BodyModel& model, BodyData& data, const Posture& g,
                                          std::span<const PointContact> contacts,
                                          const Eigen::Vector3d& gravity = kStandardGravity);

}  // namespace crux
