#pragma once
// iterations.csv of a learning run read back (docs/OUTPUTS.md): the one reader of the
// file, for the reports (a run's climbs and replays), the views (Fig. 3's regimes) and
// the sweeps (their analysis).

#include <filesystem>
#include <vector>

#include "experiments/episode_replay.hpp"
#include "physics/physics_model.hpp"

namespace crux {

inline constexpr const char* kIterationsHeader = "iteration,episode,regime,hold,success,root_rise_cm,reward";
// A run of the static model, where a climber can fall back to the start (docs/MODEL.md, C27).
inline constexpr const char* kIterationsHeaderWithFalls =
    "iteration,episode,regime,hold,success,root_rise_cm,reward,fell";

// Every row, each checked: the header of the run's physics `model` (the static model's adds
// `fell`: a static run's file without it is refused, as is the kinematic model's with it),
// 7 or 8 fields as it says, `fell` 0 or 1 and only after a failure, iterations numbered
// 1, 2, ... in
// order, episodes from 0 rising by 0 or 1, a known regime, success 0 or 1, integers and
// finite numbers, a newline after the last row, and `recorded_iterations` rows (the
// run's summary.json `iterations`), so that a file cut short is never read as a shorter
// run. InputError(file, "line N: problem" or the problem) otherwise.
std::vector<RunStep> read_iterations_file(const std::filesystem::path& file, int recorded_iterations,
                                          PhysicsModel model);

}  // namespace crux
