#include "experiments/performed_plan.hpp"

namespace crux {

ClimbToPerform climb_to_perform(const Wall& wall, const Plan& plan) {
  ClimbToPerform climb{plan.postures, plan.limbs, {}};
  for (const int id : plan.hold_ids) climb.holds.push_back(wall.index_of(id));
  return climb;
}

Plan plan_of_climb(const Wall& wall, const RecordedClimb& climb, PhysicsModel physics_model) {
  Plan plan;
  plan.physics_model = physics_model;
  plan.found = true;
  plan.postures = climb.postures;
  const std::vector<HoldConfiguration> configurations = climb_configurations(wall, climb);
  for (std::size_t k = 0; k + 1 < configurations.size(); ++k) {
    const Limb limb = static_cast<Limb>(k % kLimbCount);
    plan.limbs.push_back(limb);
    plan.hold_ids.push_back(wall.holds[configurations[k + 1].hold(limb)].id);
  }
  plan.length = static_cast<int>(plan.limbs.size());
  return plan;
}

PerformedPlan performed_plan(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                             const PlanParameters& search, const std::function<void()>& between_attempts) {
  const bool repairs = parameters.physics.model == PhysicsModel::Dynamic;
  PerformedPlan result;
  RefusedMoves refused;
  for (int attempt = 0;; ++attempt) {
    if (between_attempts) between_attempts();
    result.plan = shortest_plan(model, wall, parameters, search, refused);
    result.climb.reset();
    if (!result.plan.found) return result;
    const ClimbToPerform climb = climb_to_perform(wall, result.plan);
    result.climb = perform_climb(model, wall, parameters.physics, parameters.reachability, climb, parameters.perform);
    result.moves_simulated += static_cast<int>(result.climb->moves.size());
    const std::optional<int> failed = result.climb->first_failed_move();
    // A start that does not hold still leaves no move to refuse: no plan can do better.
    if (!repairs || !failed || !result.climb->start.performed()) return result;
    HoldConfiguration held = start_configuration(wall);
    for (int k = 0; k < *failed; ++k) held = held.with(climb.limbs[k], climb.holds[k]);
    const Limb limb = climb.limbs[*failed];
    refused.insert({encode(held.with(limb, kFree), wall.hold_count()), climb.holds[*failed]});
    result.failed_moves.push_back({attempt, *failed, limb, result.plan.hold_ids[*failed], result.climb->cause()});
    if (attempt == search.max_replans) {
      result.replan_cap_reached = true;
      return result;
    }
    ++result.replans;
  }
}

}  // namespace crux
