#pragma once
// A climb performed in MuJoCo as a job (crux perform, crux plan under physics.model =
// dynamic, crux.perform): a wall's exact plan performed from its start (under the dynamic
// model, repaired by performing it: experiments/performed_plan), and its folder written.

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "experiments/experiment_config.hpp"
#include "experiments/performed_plan.hpp"
#include "jobs/job_hooks.hpp"

namespace crux {

struct PerformJob {
  ExperimentConfig config;
  std::string config_path;  // the config file `config` was read from, if any (an input)
  // The folder to write (docs/OUTPUTS.md, "crux perform"); none: nothing is written.
  std::optional<std::filesystem::path> output;
  bool overwrite = false;
  // A wall given as an object (Python) instead of the config's; a folder replays from its
  // config.toml, so a job that writes one takes none.
  std::optional<Wall> wall;
};

struct PerformJobOutcome {
  Wall wall;
  PerformedPlan performed;
  nlohmann::ordered_json record;  // perform.json's contents
  double wall_s = 0.0;            // wall-clock time of the planning and the simulation
};

// crux perform's defaults (the CLI's and Python's): the static model.
ExperimentConfig perform_defaults();

// InputError naming the input for a bad one (a wall whose start does not hold among them),
// before the folder is touched.
PerformJobOutcome run_perform_job(PerformJob job, const JobHooks& hooks);

}  // namespace crux
