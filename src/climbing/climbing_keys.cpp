#include "climbing/climbing_keys.hpp"

#include "learning/learning_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_reward_keys(FieldsFor<Parameters>& keys, Parameters& rewards) {
  keys.insert(
      keys.end(),
      {
          {"reward.unreachable", "Reward of an unreachable 4-configuration", &rewards.unreachable, "", kRewardRange},
          {"reward.step", "Reward of a reachable 4-configuration", &rewards.step, "", kRewardRange},
          {"reward.finish", "Reward when the centre of mass passes the finishing height", &rewards.finish, "",
           kRewardRange},
          {"reward.effort",
           "Static model: subtracted from a reached move's reward per unit of its stance's effort (0: the paper's "
           "rewards)",
           &rewards.effort, "", kRewardWeight},
          {"reward.height",
           "Potential-based height shaping: weight per metre of the mean height of the held holds (0: the paper's "
           "rewards)",
           &rewards.height, "per m", kRewardWeight},
      });
}

template <typename Parameters>
void declare_fall_when_stuck_keys(FieldsFor<Parameters>& keys, Parameters& climbing) {
  keys.insert(
      keys.end(),
      {
          {"physics.fall_when_stuck",
           "A failed move also falls when no limb can move to another hold of the stance, every such move known "
           "unreachable (a trap that C27's dead ends miss)",
           &climbing.fall_when_stuck},
      });
}

}  // namespace

void reward_keys(std::vector<ConfigField>& keys, Rewards& rewards) { declare_reward_keys(keys, rewards); }
void reward_keys(std::vector<ConstConfigField>& keys, const Rewards& rewards) { declare_reward_keys(keys, rewards); }

void fall_when_stuck_keys(std::vector<ConfigField>& keys, ClimbingParameters& climbing) {
  declare_fall_when_stuck_keys(keys, climbing);
}
void fall_when_stuck_keys(std::vector<ConstConfigField>& keys, const ClimbingParameters& climbing) {
  declare_fall_when_stuck_keys(keys, climbing);
}

}  // namespace crux
