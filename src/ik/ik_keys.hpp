#pragma once
// The [ik] keys of the IK solvers' parameters (IkParameters), declared beside them and
// gathered by experiments/experiment_config (configurations/configuration_keys adds the
// section's keys of C-reachability).

#include "common/config_field.hpp"
#include "ik/ik_solver.hpp"

namespace crux {

// Iterations of one IK solve (the fast solver's cap, the paper's Delta_t / time step):
// 36 times the paper's 2750, so that one solve stays well under a second.
inline constexpr double kMaxIkIterations = 100000;

// The IK solvers' keys: ik.solver, their tolerances and iterations, ik.wall.
void ik_keys(std::vector<ConfigField>& keys, IkParameters& ik);
void ik_keys(std::vector<ConstConfigField>& keys, const IkParameters& ik);

}  // namespace crux
