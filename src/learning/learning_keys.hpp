#pragma once
// The keys of Dyna-Q's parameters (DynaParameters): [learning], and experiment.transfer,
// the use a transfer run makes of its Q_grid. Declared here, beside the struct, and
// gathered with every other layer's keys by experiments/experiment_config.

#include "common/config_field.hpp"
#include "learning/dyna_q.hpp"

namespace crux {

// A reward's magnitude: 5000 times the paper's finish reward, so that a run's sums of
// rewards and Q-values (at most |reward| / (1 - gamma)) stay finite; 1e308 overflowed.
inline constexpr double kMaxReward = 1e9;
inline constexpr Bounds kRewardRange =
    closed_range(-kMaxReward, kMaxReward, "a run's sums of rewards must stay finite");
inline constexpr Bounds kRewardWeight = closed_range(0, kMaxReward, "a run's sums of rewards must stay finite");
// Dyna's updates per real step: a run of ten million iterations then makes 1e11 updates,
// hours; the docs use 200.
inline constexpr int kMaxPlanningSteps = 10000;

// The [learning] keys: Q-learning's rates, exploration and Dyna's planning.
void dyna_keys(std::vector<ConfigField>& keys, DynaParameters& dyna);
void dyna_keys(std::vector<ConstConfigField>& keys, const DynaParameters& dyna);

// experiment.transfer: how a transfer run uses its Q_grid (docs/TRANSFER.md).
void transfer_keys(std::vector<ConfigField>& keys, DynaParameters& dyna);
void transfer_keys(std::vector<ConstConfigField>& keys, const DynaParameters& dyna);

}  // namespace crux
