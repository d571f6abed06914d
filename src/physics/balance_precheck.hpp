#pragma once
// A necessary condition for static balance, far cheaper than the program (docs/PHYSICS.md,
// "Proven unbalanced without a program"): one projection of the six balance equations at a
// time, each a Farkas certificate that no contact forces balance the body.

#include <span>

#include <Eigen/Core>

#include "physics/contact_model.hpp"

namespace crux {

struct HeldContact {
  Eigen::Vector3d lever;  // the contact point less the point moments are taken about
  FrictionConeGenerators generators;
  double normal_force_limit = 0.0;  // newtons, may be +infinity
};

// True only when no forces, each a non-negative combination of its contact's generators
// whose weights sum to at most its normal force limit, sum to `force` with moments about
// the origin of the levers summing to `moment`. It projects the equations on the world
// axes, on `force`, and on the moment about each line through two contacts (on a flat wall,
// three holds fix their pulls: "Three holds on a plane"), and refuses only beyond a margin
// far wider than the program's own tolerance, so the program accepts nothing it refuses.
bool proven_unbalanced(std::span<const HeldContact> contacts, const Eigen::Vector3d& force,
                       const Eigen::Vector3d& moment);

}  // namespace crux
