#include "experiments/climb_replay.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "common/input_error.hpp"
#include "ik/ik_path.hpp"

namespace crux {
namespace {

void add_frame(ClimbReplay& replay, const Posture& posture, double decimals) {
  for (int i = 0; i < kConfigurationDof; ++i) replay.frames.push_back(std::round(posture[i] * decimals) / decimals);
  ++replay.frame_count;
}

}  // namespace

ClimbReplay replay_climb(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                         const ReachabilityParameters& reach, const std::string& source, const ReplayOptions& options) {
  ClimbReplay replay;
  replay.climb_kind = climb.kind;
  replay.grasp_radius = reach.ik.tolerances.grasp_radius;
  replay.climb_moves = climb.steps.size();
  IkParameters ik = reach.ik;
  ik.solver = IkSolverKind::Paper;
  BodyData data(model);
  if (!climb.postures.empty()) add_frame(replay, climb.postures.front(), options.decimals);
  HoldConfiguration configuration = start_configuration(wall).with(Limb::RightHand, kFree);
  std::size_t posture = 0;  // index into the climb of the body's current posture
  std::vector<Posture> path, samples;
  const std::size_t shown = std::min(climb.steps.size(), static_cast<std::size_t>(std::max(options.max_moves, 0)));
  for (const RunStep& step : std::span(climb.steps).first(shown)) {
    const Limb free = configuration.free_limb();
    const int hold = wall.index_of(step.hold_id);
    if (hold < 0) {
      throw InputError(source, fmt::format("a move tries hold {}, which the wall does not have", step.hold_id));
    }
    const HoldConfiguration complete = configuration.with(free, hold);
    ReplayMove move{step, free, step.success ? complete : configuration, replay.frame_count, 0, -1};
    if (step.success) {
      if (posture + 1 >= climb.postures.size()) throw InputError(source, "more reached moves than postures");
      const ReachTarget target = reach_target(model, wall, complete, reach.root);
      ik_path_samples(model, data, climb.postures[posture], climb.postures[posture + 1], target, ik,
                      options.frames_per_move, path, samples);
      for (const Posture& sample : samples) add_frame(replay, sample, options.decimals);
      ++posture;
      move.posture = static_cast<int>(posture);
      configuration = complete.with(next_free_limb(free), kFree);
    } else {
      for (int f = 0; f < options.frames_per_failure; ++f) add_frame(replay, climb.postures[posture], options.decimals);
    }
    move.last_frame = replay.frame_count - 1;
    replay.moves.push_back(move);
  }
  if (replay.frame_count > 0) {
    replay.check_frame = replay.frame_count / 2;
    forward_kinematics(model, data, replay.frame(replay.check_frame));
    for (int limb = 0; limb < kLimbCount; ++limb) {
      replay.check_grasp_points[limb] = data.points[operational_point(static_cast<Limb>(limb))];
    }
  }
  return replay;
}

}  // namespace crux
