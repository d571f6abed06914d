#pragma once
// The data of the report's 3D replay (docs/OUTPUTS.md, "The replay data") as the page
// reads it: the body's joints and visuals, the wall, and the frames of a climb the run
// recorded (its greedy climb or its last completed episode), computed by
// experiments/climb_replay, with what holds each stance under the static model; or those
// of a climb performed in MuJoCo (experiments/performed_replay).

#include <string>

#include <nlohmann/json.hpp>

#include "experiments/climb_replay.hpp"
#include "experiments/climb_stances.hpp"
#include "experiments/performed_replay.hpp"

namespace crux {

// `replay` is a climb's movement on `wall` (replay_climb), `stances` what holds each of
// its stances under the static model (climb_stances; null under the kinematic model).
nlohmann::ordered_json replay_data(const BodyModel& model, const Wall& wall, const ClimbReplay& replay,
                                   const ClimbStances* stances, const std::string& title);

// The same data for a climb performed in MuJoCo (replay_performed_climb): "performed" is
// true and each frame adds the root's rotation, the hold forces and the time; each move
// its outcome and cause. `planned_moves` is the climb's length, `grasp_radius` the one it
// was performed with.
nlohmann::ordered_json performed_replay_data(const BodyModel& model, const Wall& wall, const PerformedReplay& replay,
                                             int planned_moves, double grasp_radius, const std::string& title);

// The body part of it: joints (parents first), visuals and grasp points.
nlohmann::ordered_json body_model_json(const BodyModel& model);

}  // namespace crux
