#pragma once
// The [perform] keys of climbs performed in MuJoCo (PerformParameters, with its moves'
// and servos' parameters; docs/PHYSICS.md, "A move performed"), declared beside them and
// gathered by experiments/experiment_config.

#include "common/config_field.hpp"
#include "simulation/performed_climb.hpp"

namespace crux {

// The [perform] keys.
void perform_keys(std::vector<ConfigField>& keys, PerformParameters& perform);
void perform_keys(std::vector<ConstConfigField>& keys, const PerformParameters& perform);

}  // namespace crux
