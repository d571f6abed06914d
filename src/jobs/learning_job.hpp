#pragma once
// One learning run as a job (crux train, crux transfer, crux.run_learning, a run task of
// crux sweep): the one place where a run's inputs are loaded and checked, the run
// learnt (with its checkpoints when it writes a folder), summarised and its folder
// written. Callers bind their arguments into a LearningJob and print what it returns.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "experiments/experiment_config.hpp"
#include "experiments/paper_experiment.hpp"
#include "jobs/job_hooks.hpp"

namespace crux {

struct LearningJob {
  // Which of the paper's conditions the run is (a sweep runs all three); a transfer run
  // needs a Q_grid, the others start from empty tables.
  Condition condition = Condition::Training;
  // A training run over K > 1 walls (a sweep's task): its last run continues the Q_grid
  // of the preceding training walls, given as config.q_grid, and its config.toml is
  // crux transfer's, which replays that run.
  bool continues_training = false;
  ExperimentConfig config;
  // The config file `config` was read from, if any: an input, and its recorded
  // provenance is checked against the inputs used now.
  std::string config_path;
  // The run folder; none is written without one (Python without `output`).
  std::optional<std::filesystem::path> output;
  bool overwrite = false;
  // The body of config.urdf already loaded (a sweep's, Python's model object), so that
  // it is not loaded again.
  const BodyModel* model = nullptr;
  // Inputs given as objects rather than by the config (Python): each replaces the
  // config's, which then names none. A folder replays from its config.toml, so a job
  // that writes one takes neither.
  std::optional<Wall> wall;
  std::optional<QTable> q_grid;
};

struct LearningJobOutcome {
  ExperimentResult result;         // the one run, as single_run_result makes it, under the job's condition
  nlohmann::ordered_json summary;  // what summary.json holds
  int resumed_at = 0;              // the checkpoint's iteration it resumed from; 0 from the start
};

// Runs `job`. InputError naming the input for a bad one, before any long work; a folder
// holding a checkpoint of this very run resumes from it (unless overwrite).
LearningJobOutcome run_learning_job(LearningJob job, const JobHooks& hooks);

}  // namespace crux
