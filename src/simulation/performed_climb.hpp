#pragma once
// A climb performed in MuJoCo (docs/PHYSICS.md, "A climb performed"): the climber placed at
// rest in its start stance on the wall's four start holds, held still there, then each
// move performed from the simulated state the one before left (never from the planned
// stance), until a move fails or the last is performed.

#include <optional>
#include <string>
#include <vector>

#include "simulation/move_reference.hpp"

namespace crux {

// What to perform: the start stance, then the stance each move arrives at.
struct ClimbToPerform {
  std::vector<Posture> stances;  // the start, then one per move
  std::vector<Limb> limbs;       // the limb each move places
  std::vector<int> holds;        // the hold (index) each move takes
};

// Every setting of a performed climb (the perform.* keys of docs/OUTPUTS.md).
struct PerformParameters {
  MoveParameters move;
  ServoParameters servo;
  int path_samples = 16;            // IK postures along each move's path (the replay's)
  double force_margin = 0.5;        // the share of friction and grip the feed-forward leaves unused
  double lift = 0.1;                // m: how far the free limb's path bows away from the wall
  double start_time_s = 2.0;        // the start's time to come to rest before the first move
  double record_interval_s = 0.02;  // the trajectory's sampling interval
};

struct PerformedClimb {
  MoveOutcome start;               // the start stance held still
  std::vector<MoveOutcome> moves;  // the moves attempted, in order: all performed but perhaps the last
  int planned_moves = 0;
  std::vector<TrajectorySample> trajectory;
  std::string mjcf;  // the model it was performed in (simulation/mjcf_model), at the start stance

  int moves_performed() const;
  bool reached_top() const { return moves_performed() == planned_moves && start.performed(); }
  // The move that failed (0 when the start did not hold still); none when the climb reached the top.
  std::optional<int> first_failed_move() const;
  MoveFailure cause() const;        // the start's or the failed move's; None when it reached the top
  double max_torque_ratio() const;  // over the start and every move attempted
  double simulated_s() const;
};

// Performs `climb` on `wall` (its stances must lie on it: a plan's, a run's climb), a limb
// on its hold within reach.ik's grasp radius, as the IK has it (parameters.move's aside).
PerformedClimb perform_climb(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                             const ReachabilityParameters& reach, const ClimbToPerform& climb,
                             const PerformParameters& parameters);

}  // namespace crux
