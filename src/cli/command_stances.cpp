// crux stances: which stances of kinematic climbs the static model holds, and why the
// others fail (docs/PHYSICS.md, "Which stances hold").

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "experiments/run_inputs.hpp"
#include "experiments/stance_survey.hpp"
#include "reports/stance_survey_description.hpp"

namespace crux::cli {

namespace {

// Random walls from wall.seed (wall i from a seed derived from it and i), the body, its
// IK and the static model's parameters.
const ParameterSet kStancesKeys{{"experiment.urdf", "wall", "ik", "physics", "filter", "stances", "output.progress"},
                                {"wall.file", "wall.name", "ik.wall", "physics.model"}};

ExperimentConfig stances_defaults() {
  ExperimentConfig defaults;
  defaults.wall_seed = 1;
  return defaults;
}

// crux stances' own keys: the walls it surveys and the random kinematic moves per wall
// whose stances it checks.
struct StancesOptions {
  int walls = 30;
  int moves = 300;
};

std::vector<ConfigField> stances_fields(StancesOptions& options) {
  return {wall_count_field(options.walls),
          {"stances.moves", "Random kinematic moves per wall whose stances crux stances checks", &options.moves, "",
           work_size(1, kMaxStanceMoves)}};
}

struct StancesCommand {
  StancesOptions options;
  ParameterBinding binding{"stances", kStancesKeys, stances_defaults()};
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const BodyModel model = load_configured_body(config);
    StanceSurveyParameters parameters;
    parameters.wall_seed = *config.wall_seed;
    parameters.wall_count = options.walls;
    parameters.moves = options.moves;
    parameters.walls = config.settings.walls;
    parameters.climbing = config.settings.learning.climbing;
    ProgressBar progress("stances", parameters.wall_count, config.progress);
    const StanceSurvey survey = survey_stances(model, parameters, [&](int done) { progress.update(done); });
    progress.finish();
    std::cout << (json ? stance_survey_json(survey, parameters).dump(2) + "\n"
                       : stance_survey_text(survey, parameters));
  }
};

}  // namespace

void add_stances_command(CLI::App& app) {
  auto cmd = std::make_shared<StancesCommand>();
  auto* command = app.add_subcommand(
      "stances",
      "Share of the stances random kinematic climbs reach that hold still under the static model, and why the others "
      "fail");
  cmd->binding.add_command_options(cmd->options, stances_fields);
  cmd->binding.bind(command);
  command->add_flag("--json", cmd->json, "Print JSON instead of text");
  command->callback([cmd] { cmd->run(); });
}

}  // namespace crux::cli
