#include "jobs/perform_job.hpp"

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <string_view>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "experiments/run_inputs.hpp"
#include "jobs/command_keys.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/run_folder.hpp"
#include "outputs/trajectory_csv.hpp"
#include "reports/perform_description.hpp"

namespace crux {

namespace {

// The climb of the run folder config.run that config.climb names, on the run's wall and
// under the run's climbing parameters, which `config` then records: a key given with
// another value is refused rather than ignored.
struct RunClimb {
  Wall wall;
  RecordedClimb climb;
};
RunClimb run_climb(ExperimentConfig& config, std::optional<BodyModel>& model) {
  refuse_keys_off_default(config, {"wall."},
                          "crux perform --run performs the run's climb on the run's own wall: drop this key");
  refuse_keys_off_default(config,
                          {"experiment.plan_max_solves", "experiment.plan_check_moves", "experiment.plan_max_replans"},
                          "crux perform --run performs the run's climb, not a plan: drop this key");
  RunFolder folder = locate_run_folder(config.run);
  const ExperimentConfig recorded = read_run_config(folder.config_file);
  const std::vector<ConstConfigField> given = config_fields(std::as_const(config));
  const std::vector<ConstConfigField> ran = config_fields(recorded);
  for (std::size_t i = 0; i < given.size(); ++i) {
    const std::string& key = given[i].key;
    const bool climbing_key = key.starts_with("ik.") || key.starts_with("physics.") || key.starts_with("filter.");
    if (!climbing_key || !config.given.contains(key)) continue;
    if (field_value_text(given[i]) != field_value_text(ran[i])) {
      throw InputError(key, fmt::format("the run's climb is performed under the run's own {} ({}, its config.toml): "
                                        "drop this key",
                                        key, field_value_text(ran[i])));
    }
  }
  config.settings.learning.climbing = recorded.settings.learning.climbing;
  config.physics_strength = recorded.physics_strength;
  if (!config.urdf.empty() && !folder.urdf.empty() &&
      std::filesystem::absolute(config.urdf) != std::filesystem::absolute(folder.urdf)) {
    throw InputError(
        "experiment.urdf",
        fmt::format("the run's climb is performed on the run's own body ({}): drop this key", folder.urdf));
  }
  if (config.urdf.empty()) config.urdf = folder.urdf;
  model.emplace(load_configured_body(config));
  read_run_climb(folder, *model);
  RecordedClimb climb = climb_to_show(folder, *model, config.settings.learning.climbing,
                                      config.climb.empty() ? "greedy" : config.climb, "experiment.climb");
  if (climb.postures.size() < 2) {
    throw InputError("experiment.run",
                     fmt::format("{}: the run completed no climb, so there is no climb to perform", config.run));
  }
  return {std::move(folder.wall), std::move(climb)};
}

}  // namespace

ExperimentConfig perform_defaults() {
  ExperimentConfig defaults;
  defaults.settings.learning.climbing.physics.model = PhysicsModel::Static;
  return defaults;
}

PerformJobOutcome run_perform_job(PerformJob job, const JobHooks& hooks) {
  ExperimentConfig& config = job.config;
  if (job.output && job.wall) {
    throw InputError("wall",
                     "a perform folder replays from its config.toml: give the wall by the config (wall.file or "
                     "wall.seed) to write one");
  }
  if (config.run.empty() && !config.climb.empty()) {
    throw InputError("experiment.climb", "names a run's climb: give the run too (experiment.run)");
  }
  PerformJobOutcome outcome;
  std::optional<BodyModel> model;
  std::optional<RecordedClimb> recorded_climb;
  if (!config.run.empty()) {
    RunClimb run = run_climb(config, model);
    outcome.wall = std::move(run.wall);
    recorded_climb = std::move(run.climb);
  } else {
    model.emplace(load_configured_body(config));
    outcome.wall = job.wall ? std::move(*job.wall) : load_configured_wall(config);
  }
  Provenance provenance = record_provenance(config);
  provenance.produced_by = hooks.caller;
  if (!job.config_path.empty()) check_recorded_provenance(config, provenance, job.config_path);
  if (job.output) {
    check_output_folder(*job.output, {config.urdf, config.wall_file, config.run, job.config_path}, job.overwrite);
  }
  const ExperimentParameters& s = config.settings;
  const auto started = std::chrono::steady_clock::now();
  if (recorded_climb) {
    outcome.performed.plan = plan_of_climb(outcome.wall, *recorded_climb, s.learning.climbing.physics.model);
    outcome.performed.climb =
        perform_climb(*model, outcome.wall, s.learning.climbing.physics, s.learning.climbing.reachability,
                      climb_to_perform(outcome.wall, outcome.performed.plan), s.learning.climbing.perform);
    outcome.performed.moves_simulated = static_cast<int>(outcome.performed.climb->moves.size());
  } else {
    outcome.performed =
        performed_plan(*model, outcome.wall, s.learning.climbing, s.plan_search, hooks.interruption_point);
  }
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  outcome.record = performed_plan_json(outcome.wall, outcome.performed);
  outcome.record["climb"] = recorded_climb ? climb_description(*recorded_climb) : "the wall's exact plan";
  if (job.output) {
    const PerformedClimb empty;
    const PerformedClimb& climb = outcome.performed.climb ? *outcome.performed.climb : empty;
    write_perform_folder(*job.output, config_file_text(config, kPerformKeys, provenance), outcome.wall, outcome.record,
                         trajectory_csv(*model, climb.trajectory), climb.mjcf);
  }
  return outcome;
}

}  // namespace crux
