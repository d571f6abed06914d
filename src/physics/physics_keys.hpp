#pragma once
// The [physics] keys of the physics model and the static model's contacts and strength
// (PhysicsParameters), declared beside them and gathered by experiments/experiment_config.

#include <string>

#include "common/config_field.hpp"
#include "physics/physics_model.hpp"

namespace crux {

// The physics model's keys; physics.strength sets `strength_level`, a climbing level's name
// (empty: unset), which the experiment's config resolves into physics.grip.
void physics_keys(std::vector<ConfigField>& keys, PhysicsParameters& physics, std::string& strength_level);
void physics_keys(std::vector<ConstConfigField>& keys, const PhysicsParameters& physics,
                  const std::string& strength_level);

}  // namespace crux
