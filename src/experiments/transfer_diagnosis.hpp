#pragma once
// Why transferred knowledge chooses badly: a profile of the actions of transfer's
// beginning window, by regime. For each action, the agent-space pair it tried (state,
// tile) is looked up in the evidence that built Q_grid's value for that pair: the real
// tries of it in the paired training run and earlier in the transfer run itself. The
// profile says how often the hold tried is the one the free limb just left (a move that
// goes nowhere), how often it was reachable, and how far the hold lies, inside its tile,
// from where the holds of that evidence lay: a tile of 0.3 m x 0.5 m names many holds,
// and Algorithm 3 takes the one nearest the tile's centre. It also counts the actions
// that try again the hold that failed at the iteration before; the evidence is measured
// on the other actions.

#include <array>

#include "experiments/paper_experiment.hpp"

namespace crux {

struct ChoiceProfile {
  int actions = 0, successes = 0;
  int back_to_left_hold = 0, back_to_left_hold_successes = 0;
  int repeats_of_failure = 0, repeats_of_failure_successes = 0;  // the hold that failed just before
  // The rest leave the repeats of a failure out: the (state, tile) pair had been tried
  // before, with that success, at that distance.
  int with_evidence = 0;
  double evidence_success_rate = 0;  // pooled success of those earlier tries
  int far = 0, far_successes = 0;    // the hold lies more than kFarFromEvidence from them
  int near = 0, near_successes = 0;
  double median_distance_cm = -1;  // over the actions with evidence; -1 if none
  double mean_root_rise_cm = 0;    // over the successful actions
};

inline constexpr double kFarFromEvidence = 0.10;  // m: beyond the 8 cm of a grasp

// Per regime (w-greedy, g-greedy, random), pooled over transfer runs, for the first
// `window` iterations.
std::array<ChoiceProfile, kRegimeCount> diagnose_transfer(const ExperimentResult& result, int window);

}  // namespace crux
