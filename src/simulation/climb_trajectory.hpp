#pragma once
// What a performed climb records (docs/OUTPUTS.md, `crux perform`): every interval of
// simulated time, the root's pose, the joint angles and each limb's force from its hold,
// in wall coordinates, so that a replay plays the simulated motion and not the IK's.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "body/body_model.hpp"

namespace crux {

class SimulatedClimber;

struct TrajectorySample {
  double time = 0.0;                  // s, from the start's placement
  int move = -1;                      // the move under way (its index in the climb); -1 while the start settles
  Posture posture = Posture::Zero();  // the root's position, the joint angles (crux's coordinates)
  Eigen::Quaterniond root_orientation = Eigen::Quaterniond::Identity();  // from its orientation on the wall
  std::array<Eigen::Vector3d, kLimbCount> hold_forces{};                 // N, on each limb from its hold (zero: none)
};

class TrajectoryRecorder {
 public:
  // One sample every `interval_s` of simulated time (> 0), the first at the first step.
  explicit TrajectoryRecorder(double interval_s);

  // The move the next samples belong to.
  void start_move(int move) { move_ = move; }
  // Called after each step: keeps a sample when its interval has passed.
  void record(const SimulatedClimber& climber);

  const std::vector<TrajectorySample>& samples() const { return samples_; }

 private:
  double interval_s_;
  double next_time_ = -1.0;
  int move_ = -1;
  std::vector<TrajectorySample> samples_;
};

}  // namespace crux
