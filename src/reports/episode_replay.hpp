#pragma once
// Any episode of a run, replayed: a run folder keeps the postures of its last completed
// climb and of its greedy climb only, so the postures of another episode are found again
// by stepping the run's real actions (iterations.csv) through the climbing MDP from the
// first iteration, with the run's own climbing parameters. The MDP is deterministic and
// its posture cache fills in the run's order, so every posture is the run's.

#include <string>

#include "climbing/climbing_mdp.hpp"
#include "reports/run_folder.hpp"

namespace crux {

// Episode `episode` (from 0) of `folder`, whose climb was read (read_run_climb); the
// last episode may be unfinished. InputError naming `flag` for an episode the run does
// not have, or the folder's iterations.csv when its actions are not the MDP's.
RecordedClimb replay_episode(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                             int episode, const std::string& flag);

// The climb named by `choice`: "greedy", "last" (chosen_climb) or an episode number.
RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag);

}  // namespace crux
