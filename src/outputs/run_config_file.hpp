#pragma once
// The config.toml that `crux paper`, `train`, `transfer` and `perform` write into their output
// folder, read back: the one reader of it, through the parameter table's own rules
// (experiment_config), for the reports (a run's parameters) and the views (the grid).

#include <filesystem>

#include "experiments/experiment_config.hpp"

namespace crux {

// Every key, checked and finalized as a --config file is. crux writes every grid key,
// and a view cannot draw the grid from defaults, so each must be in the file, except
// grid.agent_space, which folders written before it lack (their space is the grid).
// InputError(file, problem), or InputError("<file>: line N: <key>", problem) for a
// value that finalize_config refuses.
ExperimentConfig read_run_config(const std::filesystem::path& file);

// The config.toml of a `crux perform` folder, read as read_run_config reads a run's, with
// no grid.
ExperimentConfig read_perform_config(const std::filesystem::path& file);

}  // namespace crux
