#pragma once
// Table I as text, ours beside the paper's (section IV) for training and transfer.

#include <string>

#include "experiments/paper_experiment.hpp"

namespace crux {

std::string table_one_text(const ExperimentResult& result, const ExperimentParameters& parameters);

}  // namespace crux
