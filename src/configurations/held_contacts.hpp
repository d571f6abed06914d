#pragma once
// The point contacts of a configuration's held limbs (docs/PHYSICS.md, "Static
// equilibrium"): each hold pushes along its support direction for the limb on it, within
// the friction cone of physics.friction; a hand's normal force is bounded by the grip, a
// foot's by the legs' torques alone. The static model's stance check and the simulated
// grasps both judge forces against these.

#include <array>
#include <span>

#include "configurations/hold_configuration.hpp"
#include "physics/contact_model.hpp"
#include "physics/physics_model.hpp"
#include "wall/wall.hpp"

namespace crux {

// `limb` on the hold of index `hold`.
PointContact held_contact(const Wall& wall, int hold, Limb limb, const PhysicsParameters& physics);

// One contact per held limb of `configuration`, in limb order, into `out`; the span of them.
std::span<const PointContact> held_contacts(const Wall& wall, const HoldConfiguration& configuration,
                                            const PhysicsParameters& physics,
                                            std::array<PointContact, kLimbCount>& out);

}  // namespace crux
