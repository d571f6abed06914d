#pragma once
// The data of the report's 3D replay (docs/OUTPUTS.md, "The replay data"): the body's
// joints and visuals, the wall, and the frames of a climb the run recorded (its greedy
// climb or its last completed episode). Between two
// recorded postures the frames follow the path of the paper's gradient-descent IK
// (Algorithm 1) from the one towards the next, so the movement is continuous.

#include <string>

#include <nlohmann/json.hpp>

#include "configurations/reachability.hpp"
#include "reports/run_folder.hpp"

namespace crux {

struct ReplayOptions {
  int frames_per_move = 16;    // a reached move: IK path samples, ending on the recorded posture
  int frames_per_failure = 8;  // an unreachable move: the body stays, the tried hold is shown
  double decimals = 1e5;       // postures are rounded to 1e-5 (m, rad) to keep the report small
};

// `climb` is one of a folder read by read_run_climb with `model`, on `wall`. `reach`
// gives the root target and the IK settings (its solver is replaced by the paper's,
// whose small steps make a continuous movement). InputError naming `source` when a move
// names a hold the wall does not have.
nlohmann::ordered_json replay_data(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                   const ReachabilityParameters& reach, const std::string& title,
                                   const std::string& source, const ReplayOptions& settings = {});

// The body part of it: joints (parents first), visuals and grasp points.
nlohmann::ordered_json body_model_json(const BodyModel& model);

}  // namespace crux
