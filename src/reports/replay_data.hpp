#pragma once
// The data of the report's 3D replay (docs/OUTPUTS.md, "The replay data"): the body's
// joints and visuals, the wall, and the frames of a climb the run recorded (its greedy
// climb or its last completed episode). Between two
// recorded postures the frames follow the path of the paper's gradient-descent IK
// (Algorithm 1) from the one towards the next, so the movement is continuous.

#include <string>

#include <nlohmann/json.hpp>

#include "climbing/stance_check.hpp"
#include "configurations/reachability.hpp"
#include "outputs/run_folder.hpp"

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
  // Under the static model each stance (the start, and where each reached move ends)
  // carries what holds it: its contact forces and its joints' torque ratios.
  PhysicsParameters physics;
};

// `climb` is one of a folder read by read_run_climb with `model`, on `wall`. `reach`
// gives the root target and the IK settings (its solver is replaced by the paper's,
// whose small steps make a continuous movement). InputError naming `source` when a move
// names a hold the wall does not have. `climb_moves` is the climb's move count, `moves`
// those replayed (at most settings.max_moves).
nlohmann::ordered_json replay_data(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                   const ReachabilityParameters& reach, const std::string& title,
                                   const std::string& source, const ReplayOptions& settings = {});

// The body part of it: joints (parents first), visuals and grasp points.
nlohmann::ordered_json body_model_json(const BodyModel& model);

}  // namespace crux
