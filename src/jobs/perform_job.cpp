#include "jobs/perform_job.hpp"

#include <chrono>

#include "common/input_error.hpp"
#include "experiments/run_inputs.hpp"
#include "jobs/command_keys.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/trajectory_csv.hpp"
#include "reports/perform_description.hpp"

namespace crux {

PerformJobOutcome run_perform_job(PerformJob job, const JobHooks& hooks) {
  const ExperimentConfig& config = job.config;
  if (job.output && job.wall) {
    throw InputError("wall",
                     "a perform folder replays from its config.toml: give the wall by the config (wall.file or "
                     "wall.seed) to write one");
  }
  const BodyModel model = load_configured_body(config);
  Provenance provenance = record_provenance(config);
  provenance.produced_by = hooks.caller;
  if (!job.config_path.empty()) check_recorded_provenance(config, provenance, job.config_path);
  PerformJobOutcome outcome;
  outcome.wall = job.wall ? std::move(*job.wall) : load_configured_wall(config);
  if (job.output) {
    check_output_folder(*job.output, {config.urdf, config.wall_file, job.config_path}, job.overwrite);
  }
  const ExperimentParameters& s = config.settings;
  const auto started = std::chrono::steady_clock::now();
  outcome.performed = performed_plan(model, outcome.wall, s.learning.climbing, s.plan_search, s.perform);
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  outcome.record = performed_plan_json(outcome.wall, outcome.performed);
  if (job.output) {
    ExperimentConfig recorded = config;
    const PerformedClimb empty;
    const PerformedClimb& climb = outcome.performed.climb ? *outcome.performed.climb : empty;
    write_perform_folder(*job.output, config_file_text(recorded, kPerformKeys, provenance), outcome.wall,
                         outcome.record, trajectory_csv(model, climb.trajectory), climb.mjcf);
  }
  return outcome;
}

}  // namespace crux
