#include "simulation/move_trial.hpp"

#include "simulation/mjcf_model.hpp"

namespace crux {

MoveTrials::MoveTrials(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                       const ReachabilityParameters& reach, const PerformParameters& parameters)
    : model_(model),
      wall_(wall),
      physics_(physics),
      parameters_(parameters),
      move_(parameters.move),
      limits_(motor_limits(model, published_strength_profile(model, model.total_mass, model.stature))),
      references_(model, wall, physics, reach, parameters.path_samples, parameters.force_margin, parameters.lift) {
  // A limb is on its hold as the IK's termination test has it.
  move_.grasp_radius = reach.ik.tolerances.grasp_radius;
}

MoveOutcome MoveTrials::perform(const Posture& from, const Posture& to, const HoldConfiguration& kept, int left_hold,
                                int hold) {
  if (!climber_) climber_.emplace(model_, wall_, physics_, limits_, from, parameters_.servo);
  const Limb limb = kept.free_limb();
  const HoldConfiguration held = kept.with(limb, left_hold);
  climber_->place(from, held);
  references_.forget_warm_start();
  const MoveOutcome settled =
      hold_still(*climber_, from, held, references_.holding(from, held).torques, parameters_.start_time_s, move_);
  if (!settled.performed()) return settled;
  return perform_move(*climber_, references_.move(from, to, kept, left_hold, hold), move_);
}

}  // namespace crux
