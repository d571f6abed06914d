#include "learning/learning_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_dyna_keys(FieldsFor<Parameters>& keys, Parameters& dyna) {
  keys.insert(keys.end(),
              {
                  {"learning.alpha", "Q-learning step size alpha", &dyna.rates.alpha, "", kAboveZeroToOne},
                  {"learning.gamma", "Discount factor gamma", &dyna.rates.gamma, "", kZeroToBelowOne},
                  {"learning.epsilon", "Exploration rate of Algorithm 3", &dyna.epsilon, "", kUnitInterval},
                  {"learning.planning_steps", "Dyna planning updates per real step", &dyna.planning_steps, "",
                   work_size(0, kMaxPlanningSteps)},
                  {"learning.planner",
                   "Dyna planning: uniform (Algorithm 2) or prioritized (prioritized sweeping, same number of updates)",
                   choice_of(&dyna.planner)},
                  {"learning.priority_threshold", "Prioritized sweeping queues pairs whose |TD error| exceeds this",
                   &dyna.priority_threshold, "", closed_range(0, kMaxReward, "a TD error is on the rewards' scale")},
              });
}

template <typename Parameters>
void declare_transfer_keys(FieldsFor<Parameters>& keys, Parameters& dyna) {
  keys.insert(
      keys.end(),
      {
          {"experiment.transfer",
           "How transfer uses its Q_grid (docs/TRANSFER.md): paper is Algorithm 3; control follows the same rule from "
           "an "
           "empty Q_grid",
           choice_of(&dyna.transfer)},
      });
}

}  // namespace

void dyna_keys(std::vector<ConfigField>& keys, DynaParameters& dyna) { declare_dyna_keys(keys, dyna); }
void dyna_keys(std::vector<ConstConfigField>& keys, const DynaParameters& dyna) { declare_dyna_keys(keys, dyna); }

void transfer_keys(std::vector<ConfigField>& keys, DynaParameters& dyna) { declare_transfer_keys(keys, dyna); }
void transfer_keys(std::vector<ConstConfigField>& keys, const DynaParameters& dyna) {
  declare_transfer_keys(keys, dyna);
}

}  // namespace crux
