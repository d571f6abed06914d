#pragma once
// C-reachability of a 4-configuration (paper, III-A and III-C): the IK target it
// defines on a wall, and whether the body reaches it.

#include "configurations/hold_configuration.hpp"
#include "ik/ik_solver.hpp"
#include "ik/root_target.hpp"
#include "wall/wall.hpp"

namespace crux {

// Where the IK starts the solve of a 4-configuration (docs/MODEL.md, choice C30): from
// the posture the climber holds, as the paper does, or from the standing posture at the
// configuration's own root target H(C4), as the start is solved, so that the verdict
// depends on the configuration alone and not on the climb that led to it.
enum class IkGuess { Previous, Standing };
template <>
struct EnumNames<IkGuess> {
  static constexpr std::array<EnumName<IkGuess>, 2> entries{
      {{IkGuess::Previous, "previous"}, {IkGuess::Standing, "standing"}}};
};

// How C-reachability is decided: the IK solver and its settings, the root heuristic,
// whether unreachable verdicts are cached (docs/MODEL.md, choice C11), and where the
// IK starts.
struct ReachabilityParameters {
  IkParameters ik;
  RootTargetParameters root;
  bool cache_unreachable = true;
  IkGuess guess = IkGuess::Previous;
};

// The four holds of a complete configuration and the root target H(C4).
ReachTarget reach_target(const BodyModel& model, const Wall& wall, const HoldConfiguration& complete,
                         const RootTargetParameters& root);

HoldConfiguration start_configuration(const Wall& wall);

// The posture every episode's start configuration is solved from: standing, root at H(C4).
Posture start_guess(const BodyModel& model, const Wall& wall, const RootTargetParameters& root);

// Whether the wall's start configuration is C-reachable from start_guess: the one start
// check of crux (wall generate, wall show, the learning and the experiment's wall draws).
IkResult solve_start(const BodyModel& model, BodyData& data, const Wall& wall,
                     const ReachabilityParameters& parameters);

}  // namespace crux
