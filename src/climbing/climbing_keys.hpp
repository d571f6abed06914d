#pragma once
// The keys of the climbing MDP's parameters: [reward] (Rewards), and
// physics.fall_when_stuck (ClimbingParameters). Declared beside the structs and
// gathered by experiments/experiment_config.

#include "climbing/climbing_mdp.hpp"
#include "common/config_field.hpp"

namespace crux {

// The [reward] keys: the MDP's rewards and their shaping.
void reward_keys(std::vector<ConfigField>& keys, Rewards& rewards);
void reward_keys(std::vector<ConstConfigField>& keys, const Rewards& rewards);

// physics.fall_when_stuck: a failed move that leaves no way on also falls.
void fall_when_stuck_keys(std::vector<ConfigField>& keys, ClimbingParameters& climbing);
void fall_when_stuck_keys(std::vector<ConstConfigField>& keys, const ClimbingParameters& climbing);

}  // namespace crux
