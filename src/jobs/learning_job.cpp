#include "jobs/learning_job.hpp"

#include "common/input_error.hpp"
#include "experiments/run_checkpoint.hpp"
#include "experiments/run_inputs.hpp"
#include "jobs/command_keys.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/summary.hpp"

namespace crux {

namespace {

// Before any input is loaded: a transfer run starts from a Q_grid, the others from empty
// tables; the network mode's run from a policy file instead.
void check_starting_knowledge(const LearningJob& job, bool starts_from_q_grid) {
  const ExperimentConfig& config = job.config;
  if (starts_from_q_grid && !job.q_grid && config.q_grid.empty()) {
    throw InputError("experiment.q_grid", "give the Q_grid to transfer (q_grid.bin of a training run)");
  }
  if (!starts_from_q_grid && (job.q_grid || !config.q_grid.empty())) {
    throw InputError("experiment.q_grid", "only a transfer run starts from a Q_grid");
  }
  const bool network = config.settings.learning.dyna.transfer == TransferMode::Network;
  if (network && starts_from_q_grid) {
    throw InputError(
        "experiment.transfer",
        "network learns from a policy file, not a Q_grid: run crux train --transfer network --policy FILE");
  }
  if (network && config.policy.empty()) {
    throw InputError("experiment.policy",
                     "experiment.transfer = network orders exploration by a policy network: give its file "
                     "(examples/python/policy_baseline.py train writes one)");
  }
  if (!network && !config.policy.empty()) {
    throw InputError("experiment.policy", "only experiment.transfer = network uses a policy file");
  }
}

}  // namespace

LearningJobOutcome run_learning_job(LearningJob job, const JobHooks& hooks) {
  ExperimentConfig& config = job.config;
  const bool starts_from_q_grid = job.condition == Condition::Transfer || job.continues_training;
  check_starting_knowledge(job, starts_from_q_grid);
  const bool writes_folder = job.output.has_value();
  if (writes_folder && (job.wall || job.q_grid)) {
    throw InputError(job.wall ? "wall" : "q_grid",
                     "a run folder replays from its config.toml: give this input by the config (wall.file or "
                     "wall.seed, experiment.q_grid) to write one");
  }
  if (config.checkpoint_every != 0 && !writes_folder) {
    throw InputError("experiment.checkpoint_every", "a run that writes no folder keeps no checkpoint; leave it 0");
  }
  require_perform_keys_used(config, hooks.caller);
  std::optional<BodyModel> loaded_model;
  if (job.model == nullptr) loaded_model = load_configured_body(config);
  const BodyModel& model = job.model != nullptr ? *job.model : *loaded_model;
  Provenance provenance = record_provenance(config);
  provenance.produced_by = hooks.caller;
  if (!job.config_path.empty()) check_recorded_provenance(config, provenance, job.config_path);
  const Wall wall = job.wall ? std::move(*job.wall) : load_configured_wall(config);
  const GridParameters& grid = config.settings.learning.climbing.grid;
  std::optional<PolicyNetwork> policy;
  if (!config.policy.empty()) policy = load_checked_policy(config.policy, config.settings.learning.climbing.filter);
  std::optional<QTable> initial = std::move(job.q_grid);
  if (initial) {
    check_q_grid(*initial, grid, "q_grid");
  } else if (!config.q_grid.empty()) {
    initial = load_q_grid(config.q_grid, grid);
  }

  const ParameterSet& keys = starts_from_q_grid ? kTransferKeys : kTrainKeys;
  RunCheckpoints checkpoints{config.checkpoint_every, {}, {}, {}, {}};
  std::string config_toml;
  LearningJobOutcome outcome;
  if (writes_folder) {
    config_toml = config_file_text(config, keys, provenance);
    // A checkpoint resumes the run whose parameters and inputs it records, whatever its
    // checkpoint interval and whoever runs it.
    ParameterSet identity_keys = keys;
    identity_keys.exclude.push_back("experiment.checkpoint_every");
    Provenance identity_provenance = provenance;
    identity_provenance.produced_by.clear();
    const std::string identity = config_file_text(config, identity_keys, identity_provenance);
    const std::filesystem::path checkpoint_file = *job.output / kCheckpointFile;
    checkpoints.source = checkpoint_file.string();
    // What a SIGKILL left half-written is no output: a folder killed while it wrote its
    // first checkpoint starts again.
    remove_crux_temporaries(*job.output);
    if (!job.overwrite) checkpoints.resume = read_checkpoint(checkpoint_file, identity).value_or("");
    check_output_folder(*job.output, {config.urdf, config.wall_file, config.q_grid, config.policy, job.config_path},
                        job.overwrite || !checkpoints.resume.empty());
    checkpoints.save = [&job, identity](std::string state, int) {
      write_checkpoint(*job.output, checkpoint_file_bytes(identity, state));
    };
    checkpoints.resumed = [&](int iteration) {
      outcome.resumed_at = iteration;
      if (hooks.resumed) hooks.resumed(iteration);
    };
  }
  const auto progress = [&hooks](int done) {
    if (hooks.interruption_point) hooks.interruption_point();
    if (hooks.progress) hooks.progress(done);
  };
  RunResult run = run_learning(model, wall, config.settings.learning, config.settings.seed,
                               initial ? &*initial : nullptr, progress, &checkpoints, policy ? &*policy : nullptr);
  outcome.result = single_run_result(std::move(run), wall, config.wall_seed, config.settings.seed, job.condition);
  outcome.summary = summary_json(outcome.result, nullptr, config.settings, provenance);
  if (writes_folder) write_run_folder(*job.output, outcome.result, model, grid, config_toml, outcome.summary);
  return outcome;
}

}  // namespace crux
