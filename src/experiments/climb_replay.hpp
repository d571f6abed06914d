#pragma once
// The movement of a recorded climb, for the report's 3D replay (docs/OUTPUTS.md, "The
// replay data"): between two recorded postures the frames follow the path of the paper's
// gradient-descent IK (Algorithm 1) from the one towards the next, so the movement is
// continuous; an unreachable move keeps the body still while the hold it tried is shown.

#include <array>
#include <string>
#include <vector>

#include "configurations/reachability.hpp"
#include "experiments/episode_replay.hpp"

namespace crux {

// How many of a climb's moves a replay shows: the first ones. A move is about 4 KB of the
// report page (its frames of 35 joint values and its description), so the default keeps
// a page near 8 MB and the bound near 80 MB, which a browser still opens; an unbounded
// 60,000-move episode made a 173 MB page and took 1.4 GB to build.
inline constexpr int kDefaultReplayMoves = 2000;
inline constexpr int kMaxReplayMoves = 20000;

struct ReplayOptions {
  int frames_per_move = 16;             // a reached move: IK path samples, ending on the recorded posture
  int frames_per_failure = 8;           // an unreachable move: the body stays, the tried hold is shown
  double decimals = 1e5;                // postures are rounded to 1e-5 (m, rad) to keep the report small
  int max_moves = kDefaultReplayMoves;  // the replay shows the climb's first max_moves moves
};

struct ReplayMove {
  RunStep step;
  Limb limb = Limb::RightHand;      // the free limb that moves
  HoldConfiguration configuration;  // after a reached move, else the one the body stays on
  int first_frame = 0, last_frame = 0;
  int posture = -1;  // a reached move: the index in the climb's postures of the one it ends on
};

struct ClimbReplay {
  std::string climb_kind;  // the RecordedClimb's kind
  double grasp_radius = 0.0;
  std::vector<double> frames;  // kConfigurationDof rounded values per frame, the start first
  int frame_count = 0;
  std::vector<ReplayMove> moves;  // the first max_moves of the climb's
  std::size_t climb_moves = 0;
  // A frame (-1: none) and its grasp points by forward kinematics, which the page's own
  // forward kinematics must reproduce on the rounded posture it reads.
  int check_frame = -1;
  std::array<Eigen::Vector3d, kLimbCount> check_grasp_points{};

  // Frame `index`'s posture, as rounded.
  Posture frame(int index) const {
    return Eigen::Map<const Posture>(frames.data() + static_cast<std::size_t>(index) * kConfigurationDof);
  }
};

// `climb` is one of a folder read with `model`, on `wall`. `reach` gives the root target
// and the IK settings (its solver is replaced by the paper's, whose small steps make a
// continuous movement). InputError naming `source` when a move names a hold the wall does
// not have, or the climb has more reached moves than postures.
ClimbReplay replay_climb(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                         const ReachabilityParameters& reach, const std::string& source,
                         const ReplayOptions& options = {});

}  // namespace crux
