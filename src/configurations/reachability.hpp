#pragma once
// C-reachability of a 4-configuration (paper, III-A and III-C): the IK target it
// defines on a wall, and whether the body reaches it.

#include "configurations/hold_configuration.hpp"
#include "ik/ik_solver.hpp"
#include "ik/root_target.hpp"
#include "wall/wall.hpp"

namespace crux {

// How C-reachability is decided: the IK solver and its settings, the root heuristic,
// and whether unreachable verdicts are cached (spec item 11).
struct ReachabilityParameters {
  IkSettings ik;
  RootTargetParameters root;
  bool cache_unreachable = true;
};

// The four holds of a complete configuration and the root target H(C4).
ReachTarget reach_target(const BodyModel& model, const Wall& wall, const HoldConfiguration& complete,
                         const RootTargetParameters& root);

HoldConfiguration start_configuration(const Wall& wall);

// Solves the wall's start configuration from the standing posture placed at H(C4), as
// every episode begins.
IkResult solve_start(const BodyModel& model, BodyData& data, const Wall& wall, const IkSettings& settings,
                     const RootTargetParameters& root);

}  // namespace crux
