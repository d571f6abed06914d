#pragma once
// The keys of C-reachability (ReachabilityParameters: the [ik] section, its solver's
// keys with the root target, the cache and the guess) and of the geometric filter
// ([filter], FilterParameters), declared beside them and gathered by
// experiments/experiment_config.

#include "common/config_field.hpp"
#include "configurations/geometric_filter.hpp"
#include "configurations/reachability.hpp"

namespace crux {

// The [ik] section: the solver's keys (ik/ik_keys), then the root target's, the cache's and the guess's.
void reachability_keys(std::vector<ConfigField>& keys, ReachabilityParameters& reachability);
void reachability_keys(std::vector<ConstConfigField>& keys, const ReachabilityParameters& reachability);

// The [filter] keys.
void filter_keys(std::vector<ConfigField>& keys, FilterParameters& filter);
void filter_keys(std::vector<ConstConfigField>& keys, const FilterParameters& filter);

}  // namespace crux
