#pragma once
// A hand or foot on its hold as static equilibrium sees it (docs/PHYSICS.md, "Static
// equilibrium"): a point contact whose force lies in a friction cone around the hold's
// support direction, linearised as a pyramid, with a bound on the normal component.

#include <array>
#include <string>

#include <Eigen/Core>

#include "body/limb.hpp"

namespace crux {

// Faces of the linearised friction cone: an inscribed pyramid, so every force it admits is
// one Coulomb friction admits; along its weakest direction it grants cos(pi / 4) = 0.71 of
// the cone's tangential force.
inline constexpr int kFrictionConeFaces = 4;

struct PointContact {
  Limb limb = Limb::RightHand;
  // Unit, out of the hold into the limb: the direction the hold pushes. A jug's points up.
  Eigen::Vector3d support_direction = Eigen::Vector3d::UnitZ();
  double friction = 1.0;  // Coulomb's coefficient, >= 0
  // The largest normal component, newtons: the limb's grip (hand) or push (foot) limit.
  // No default: crux has no cited grip strength (docs/MODEL.md, "Strength").
  double normal_force_limit = 0.0;
};

using FrictionConeGenerators = std::array<Eigen::Vector3d, kFrictionConeFaces>;

// The pyramid's edges n + mu (cos a_k t1 + sin a_k t2), a_k = 2 pi k / kFrictionConeFaces,
// each of normal component 1, so the normal force is the sum of their weights. t1 is world
// up (+z) projected onto the contact plane, or +x when the support direction is vertical:
// on a vertical wall the first edge holds the most weight per newton of grip.
FrictionConeGenerators friction_cone_generators(const PointContact& contact);

// True when `force` lies in the exact (round) cone, within `tolerance` newtons.
bool inside_friction_cone(const PointContact& contact, const Eigen::Vector3d& force, double tolerance);

// True when `force` is a combination of the pyramid's edges with weights >= 0, within
// `tolerance` newtons: its tangential components along the edges' two axes sum, in
// absolute value, to at most friction times its normal component (the four edges span
// that square pyramid). What the static model admits, and a simulated grasp keeps to.
bool inside_friction_pyramid(const PointContact& contact, const Eigen::Vector3d& force, double tolerance);

// A support direction that is not unit (within 1e-9), or a friction or normal force limit
// that is negative or not finite where it must be: InputError naming `source`. The normal
// force limit may be +infinity (no bound).
void check_contact(const PointContact& contact, const std::string& source);

}  // namespace crux
