#pragma once
// What `crux paper`, `train` and `transfer` print when not asked for JSON.

#include <string>

#include "experiments/experiment_analysis.hpp"

namespace crux {

// Table I beside the paper's, episode lengths, the exact shortest climbs, and transfer
// against control with its clustered statistics, take-off and transfer's choices.
std::string experiment_text(const ExperimentResult& result, const ExperimentAnalysis& analysis,
                            const ExperimentParameters& parameters);

// One line: the condition, the wall, episodes, the greedy climb, the folder.
std::string run_text(const ExperimentResult& result, int iterations, const std::string& output);

}  // namespace crux
