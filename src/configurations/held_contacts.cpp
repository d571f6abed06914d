#include "configurations/held_contacts.hpp"

#include <limits>

#include "wall/hold_support.hpp"

namespace crux {

PointContact held_contact(const Wall& wall, int hold, Limb limb, const PhysicsParameters& physics) {
  PointContact contact;
  contact.limb = limb;
  contact.support_direction = support_direction(wall.holds[hold], limb, physics.support_angle_deg);
  contact.friction = physics.friction;
  contact.normal_force_limit = is_hand(limb) ? physics.grip : std::numeric_limits<double>::infinity();
  return contact;
}

std::span<const PointContact> held_contacts(const Wall& wall, const HoldConfiguration& configuration,
                                            const PhysicsParameters& physics,
                                            std::array<PointContact, kLimbCount>& out) {
  std::size_t count = 0;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = configuration.holds[limb];
    if (hold != kFree) out[count++] = held_contact(wall, hold, static_cast<Limb>(limb), physics);
  }
  return {out.data(), count};
}

}  // namespace crux
