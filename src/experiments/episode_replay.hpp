#pragma once
// Any episode of a run, replayed: a run folder keeps the postures of its last completed
// climb and of its greedy climb only, so the postures of another episode are found again
// by stepping the run's real actions (iterations.csv) through the climbing MDP from the
// first iteration, with the run's own climbing parameters. The MDP is deterministic and
// its posture cache fills in the run's order, so every posture is the run's.

#include <span>
#include <string>
#include <vector>

#include "climbing/climbing_mdp.hpp"
#include "learning/action_selection.hpp"

namespace crux {

// A row of iterations.csv.
struct RunStep {
  int iteration = 0;  // from 1
  int episode = 0;
  Regime regime = Regime::Random;
  int hold_id = 0;
  bool success = false;
  double root_rise_cm = 0.0;
  double reward = 0.0;
  bool fell = false;  // always false in a file without the `fell` column
};

// A climb the run recorded, with the moves between its postures.
struct RecordedClimb {
  std::string kind;      // "last": the last completed episode; "greedy": the learnt policy's climb
  int episode = -1;      // its index from 0, as in iterations.csv; -1 for the greedy climb, or when no episode ended
  bool finished = true;  // false for a replayed episode that the run's iterations cut off
  std::vector<RunStep> steps;     // every move; a greedy move has iteration 0
  std::vector<Posture> postures;  // the start, then one per reached move
  // Which attempt of its episode it is, from 1: under the static model a fall takes the
  // climber back to the start, and the climb shown is the episode's last attempt.
  int attempt = 1;

  // A fall: the climber is back at the start, and what is shown is the next attempt (the
  // one place that counts them, for a replay through the MDP and for a run folder read back).
  void start_again() {
    steps.clear();
    postures.clear();
    ++attempt;
  }
};

// Episode `episode` (an index from 0, as in iterations.csv) of the run whose every step
// is `steps` (read from `steps_file`) on `wall`; the last episode may be unfinished.
// InputError naming `flag` for an episode the run does not have (numbered from 1 there,
// as the user gives it), or `steps_file` when its actions are not the MDP's.
RecordedClimb replay_episode(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                             std::span<const RunStep> steps, int episode, const std::string& steps_file,
                             const std::string& flag);

// The 4-configuration each posture of `climb` grasps on `wall`, in climb.postures' order:
// the start's, then each reached move's.
std::vector<HoldConfiguration> climb_configurations(const Wall& wall, const RecordedClimb& climb);

}  // namespace crux
