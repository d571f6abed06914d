#include "simulation/performed_climb.hpp"

#include <algorithm>

#include "simulation/mjcf_model.hpp"

namespace crux {

int PerformedClimb::moves_performed() const {
  return static_cast<int>(
      std::count_if(moves.begin(), moves.end(), [](const MoveOutcome& m) { return m.performed(); }));
}

std::optional<int> PerformedClimb::first_failed_move() const {
  if (!start.performed()) return 0;
  for (std::size_t k = 0; k < moves.size(); ++k) {
    if (!moves[k].performed()) return static_cast<int>(k);
  }
  return std::nullopt;
}

MoveFailure PerformedClimb::cause() const {
  if (!start.performed()) return start.failure;
  return moves.empty() ? MoveFailure::None : moves.back().failure;
}

double PerformedClimb::max_torque_ratio() const {
  double ratio = start.max_torque_ratio;
  for (const MoveOutcome& move : moves) ratio = std::max(ratio, move.max_torque_ratio);
  return ratio;
}

double PerformedClimb::simulated_s() const {
  double seconds = start.seconds;
  for (const MoveOutcome& move : moves) seconds += move.seconds;
  return seconds;
}

PerformedClimb perform_climb(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                             const ReachabilityParameters& reach, const ClimbToPerform& climb,
                             const PerformParameters& parameters) {
  const StrengthProfile limits =
      motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
  SimulatedClimber climber(model, wall, physics, limits, climb.stances.front(), parameters.servo);
  MoveReferences references(model, wall, physics, reach, parameters.path_samples, parameters.force_margin,
                            parameters.lift);
  TrajectoryRecorder recorder(parameters.record_interval_s);
  // A limb is on its hold as the IK's termination test has it.
  MoveParameters move = parameters.move;
  move.grasp_radius = reach.ik.tolerances.grasp_radius;
  PerformedClimb performed;
  performed.planned_moves = static_cast<int>(climb.limbs.size());
  HoldConfiguration held = start_configuration(wall);
  climber.place(climb.stances.front(), held);
  performed.start =
      hold_still(climber, climb.stances.front(), held, references.holding(climb.stances.front(), held).torques,
                 parameters.start_time_s, move, &recorder);
  for (int k = 0; k < performed.planned_moves && performed.start.performed(); ++k) {
    const Limb limb = climb.limbs[k];
    const MoveReference reference = references.move(climb.stances[k], climb.stances[k + 1], held.with(limb, kFree),
                                                    held.hold(limb), climb.holds[k]);
    recorder.start_move(k);
    performed.moves.push_back(perform_move(climber, reference, move, &recorder));
    if (!performed.moves.back().performed()) break;
    held = held.with(limb, climb.holds[k]);
  }
  performed.trajectory = recorder.samples();
  performed.mjcf = climber.mjcf();
  return performed;
}

}  // namespace crux
