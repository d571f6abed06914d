#include "experiments/climb_stances.hpp"

namespace crux {

std::optional<ClimbStances> climb_stances(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                          const PhysicsParameters& physics) {
  std::optional<StanceCheck> loads_check = stance_check_for(model, wall, physics);
  if (!loads_check) return std::nullopt;
  std::optional<StanceCheck> effort_check = stance_check_for(model, wall, physics);
  ClimbStances stances;
  const std::vector<HoldConfiguration> configurations = climb_configurations(wall, climb);
  for (std::size_t k = 0; k < climb.postures.size(); ++k) {
    stances.loads.push_back(loads_check->loads(climb.postures[k], configurations[k]));
  }
  for (std::size_t k = 0; k < climb.postures.size(); ++k) {
    const HoldConfiguration& configuration = configurations[k];
    const Limb next = static_cast<Limb>(k % kLimbCount);
    stances.effort_on_four_holds.push_back(effort_check->solve(climb.postures[k], configuration).effort);
    stances.effort_on_three_holds.push_back(
        effort_check->solve(climb.postures[k], configuration.with(next, kFree)).effort);
  }
  return stances;
}

}  // namespace crux
