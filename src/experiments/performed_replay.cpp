#include "experiments/performed_replay.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "common/input_error.hpp"

namespace crux {
namespace {

constexpr double kDecimals = 1e5;

double rounded(double value) { return std::round(value * kDecimals) / kDecimals; }

void add_frame(PerformedReplay& replay, const TrajectorySample& sample) {
  for (int i = 0; i < kConfigurationDof; ++i) replay.postures.push_back(rounded(sample.posture[i]));
  const Eigen::Quaterniond& q = sample.root_orientation;
  for (const double c : {q.x(), q.y(), q.z(), q.w()}) replay.root_rotations.push_back(rounded(c));
  for (const Eigen::Vector3d& force : sample.hold_forces) {
    for (int axis = 0; axis < 3; ++axis) replay.hold_forces.push_back(rounded(force[axis]));
  }
  replay.times.push_back(rounded(sample.time));
  ++replay.frame_count;
}

// The check frame's grasp points as the page computes them: forward kinematics on the
// rounded posture, then the rounded root rotation about the root's frame (the free joint's
// body in MuJoCo), which carries every other joint.
void add_check(PerformedReplay& replay, const BodyModel& model) {
  replay.check_frame = replay.frame_count / 2;
  const auto f = static_cast<std::size_t>(replay.check_frame);
  const Posture posture = Eigen::Map<const Posture>(replay.postures.data() + f * kConfigurationDof);
  const double* r = replay.root_rotations.data() + 4 * f;
  BodyData data(model);
  forward_kinematics(model, data, posture);
  turn_about_root(data, Eigen::Quaterniond(r[3], r[0], r[1], r[2]));
  for (int limb = 0; limb < kLimbCount; ++limb) {
    replay.check_grasp_points[limb] = data.points[operational_point(static_cast<Limb>(limb))];
  }
}

}  // namespace

PerformedReplay replay_performed_climb(const BodyModel& model, const Wall& wall, std::span<const AttemptedMove> moves,
                                       std::span<const TrajectorySample> trajectory, const std::string& source) {
  PerformedReplay replay;
  HoldConfiguration configuration = start_configuration(wall);
  for (const AttemptedMove& move : moves) {
    if (move.hold < 0 || move.hold >= static_cast<int>(wall.holds.size())) {
      throw InputError(source, fmt::format("a move takes hold index {}, which the wall does not have", move.hold));
    }
    if (move.performed) configuration = configuration.with(move.limb, move.hold);
    replay.moves.push_back({move, configuration, -1, -1});
  }
  int previous = -1, start_frames = 0;
  for (const TrajectorySample& sample : trajectory) {
    if (sample.move < previous || sample.move >= static_cast<int>(moves.size())) {
      throw InputError(source, fmt::format("sample {} belongs to move {}, after move {} and with {} attempted",
                                           replay.frame_count, sample.move, previous, moves.size()));
    }
    previous = sample.move;
    if (sample.move < 0) ++start_frames;
    if (sample.move >= 0) {
      PerformedReplayMove& move = replay.moves[sample.move];
      if (move.first_frame < 0) move.first_frame = replay.frame_count;
      move.last_frame = replay.frame_count;
    }
    add_frame(replay, sample);
  }
  // A move without a sample (shorter than the recording interval) sits on the frame before.
  int last = std::max(start_frames - 1, 0);
  for (PerformedReplayMove& move : replay.moves) {
    if (move.first_frame < 0) move.first_frame = move.last_frame = last;
    last = move.last_frame;
  }
  if (replay.frame_count > 0) add_check(replay, model);
  return replay;
}

}  // namespace crux
