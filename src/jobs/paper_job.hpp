#pragma once
// The paper's experiment as a job (crux paper, crux.run_experiment): the one place where
// its inputs are loaded and checked, the experiment run, analysed, summarised and its
// folder written.

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "experiments/experiment_analysis.hpp"
#include "experiments/experiment_config.hpp"
#include "jobs/job_hooks.hpp"

namespace crux {

struct PaperJob {
  ExperimentConfig config;
  // The config file `config` was read from, if any (as LearningJob::config_path).
  std::string config_path{};
  std::optional<std::filesystem::path> output{};  // none: no folder written
  bool overwrite = false;
};

struct PaperJobOutcome {
  ExperimentResult result;
  ExperimentAnalysis analysis;
  nlohmann::ordered_json summary;
};

// Progress counts finished learning runs, out of learning_runs().
PaperJobOutcome run_paper_job(PaperJob job, const JobHooks& hooks);

}  // namespace crux
