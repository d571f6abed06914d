#pragma once
// Plans repaired by performing them (physics.model = dynamic; docs/PHYSICS.md, "Plans
// repaired in MuJoCo"), as lazy planners in robotics check their edges only on the path
// they return: the static model's exact plan is performed in MuJoCo; a move that fails is
// refused from then on (from its 3-configuration, to its hold), and the search starts again
// from the start, until a plan is performed to the top, no plan remains, or the cap on
// replans is reached.

#include <functional>
#include <optional>
#include <vector>

#include "experiments/episode_replay.hpp"
#include "experiments/shortest_plan.hpp"
#include "simulation/performed_climb.hpp"

namespace crux {

// A move that failed in MuJoCo and that the later plans refuse.
struct FailedMove {
  int plan = 0;  // the attempt it failed in (0: the first plan)
  int move = 0;  // its index in that plan
  Limb limb = Limb::RightHand;
  int hold_id = 0;
  MoveFailure cause = MoveFailure::None;
};

struct PerformedPlan {
  Plan plan;                            // the last search's: the plan performed to the top, if any; none found
  std::optional<PerformedClimb> climb;  // that plan performed (none when no plan was found)
  int replans = 0;                      // plans searched after the first
  int moves_simulated = 0;              // over every attempt
  bool replan_cap_reached = false;
  std::vector<FailedMove> failed_moves;  // in order
  bool performed() const { return climb && climb->reached_top(); }
};

// The plan's stances, limbs and holds as MuJoCo performs them.
ClimbToPerform climb_to_perform(const Wall& wall, const Plan& plan);

// A run's recorded climb as the plan of its moves (climb_configurations): posture k + 1
// reached by move k of the round robin from the right hand, under `physics_model`.
Plan plan_of_climb(const Wall& wall, const RecordedClimb& climb, PhysicsModel physics_model);

// The plan of `parameters` performed with its perform settings. Under the dynamic model it
// is repaired, with at most search.max_replans plans after the first; under the others it
// is performed as planned.
// `between_attempts`, when given, is called before each search (it may throw to stop).
PerformedPlan performed_plan(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                             const PlanParameters& search, const std::function<void()>& between_attempts = {});

}  // namespace crux
