#pragma once
// One move performed alone in MuJoCo, from its planned stance placed at rest: the dynamic
// model's verdict for learning (physics.model = dynamic in crux train), where the MDP's
// state is a stance and not the simulated state a climb left (docs/PHYSICS.md, "Learning
// under the dynamic model").

#include <optional>

#include "simulation/performed_climb.hpp"
#include "simulation/simulated_climber.hpp"

namespace crux {

class MoveTrials {
 public:
  // The body, the wall and the controller's settings, as perform_climb takes them.
  MoveTrials(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
             const ReachabilityParameters& reach, const PerformParameters& parameters);

  // The climber placed at rest at `from` on the holds of `kept` (a 3-configuration) with
  // its free limb on `left_hold` (kFree: none), held still for at most perform.start_time,
  // then that limb moved to `hold`, arriving at the stance `to`. A start that does not hold
  // still is the move's failure.
  MoveOutcome perform(const Posture& from, const Posture& to, const HoldConfiguration& kept, int left_hold, int hold);

 private:
  const BodyModel& model_;
  const Wall& wall_;
  PhysicsParameters physics_;
  PerformParameters parameters_;
  MoveParameters move_;
  StrengthProfile limits_;
  MoveReferences references_;
  std::optional<SimulatedClimber> climber_;  // made at the first trial, at its stance
};

}  // namespace crux
