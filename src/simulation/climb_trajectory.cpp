#include "simulation/climb_trajectory.hpp"

#include <mujoco/mujoco.h>

#include "simulation/simulated_climber.hpp"

namespace crux {

TrajectoryRecorder::TrajectoryRecorder(double interval_s) : interval_s_(interval_s) {}

void TrajectoryRecorder::record(const SimulatedClimber& climber) {
  const mjData* data = climber.data();
  // Half a step's slack: the steps' sum drifts from the interval's multiples by rounding.
  if (data->time < next_time_ - 0.5 * climber.model()->opt.timestep) return;
  next_time_ = (next_time_ < 0.0 ? data->time : next_time_) + interval_s_;
  TrajectorySample& sample = samples_.emplace_back();
  sample.time = data->time;
  sample.move = move_;
  sample.posture = simulated_posture(climber.layout(), data);
  sample.root_orientation = root_orientation(climber.layout(), data);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    sample.hold_forces[limb] = climber.layout().to_world.transpose() * climber.hold_force(static_cast<Limb>(limb));
  }
}

}  // namespace crux
