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

// Episode `episode` of `folder` (an index from 0, as in iterations.csv), whose climb was
// read (read_run_climb); the last episode may be unfinished. InputError naming `flag`
// for an episode the run does not have (numbered from 1 there, as the user gives it), or
// the folder's iterations.csv when its actions are not the MDP's.
RecordedClimb replay_episode(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                             int episode, const std::string& flag);

// The climb named by `choice`: "greedy", "last" (chosen_climb) or an episode number N,
// counted from 1 as the paper's Fig. 4 and crux's figures count episodes.
RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag);

// The 4-configuration each posture of `climb` grasps on `wall`, in climb.postures' order:
// the start's, then each reached move's.
std::vector<HoldConfiguration> climb_configurations(const Wall& wall, const RecordedClimb& climb);

// Which climb `shown` (climb_to_show's for `choice`) is and why it is the one, for the
// reader of a report: the greedy climb, or the last completed episode because the greedy
// policy did not reach the top within `greedy_cap` actions, or the episode `flag` asked
// for. With no climb to show (no postures), why there is none.
std::string shown_climb_reason(const RunFolder& folder, const RecordedClimb& shown, const std::string& choice,
                               int greedy_cap, const std::string& flag);

}  // namespace crux
