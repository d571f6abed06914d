#pragma once
// Which way a hold pushes on the limb that holds it (docs/PHYSICS.md, "Static equilibrium"):
// the static model's contact normal, and the normal of a foot's contact in MuJoCo.

#include <Eigen/Core>

#include "body/limb.hpp"
#include "wall/wall.hpp"

namespace crux {

// Unit, wall coordinates. The hold's own support direction when its wall file gives one;
// else a hand hooks the incut lip of a jug, which pushes it up and `support_angle_deg`
// into the wall (+x), and a foot stands on the hold's top, which pushes it straight up.
Eigen::Vector3d support_direction(const Hold& hold, Limb limb, double support_angle_deg);

}  // namespace crux
