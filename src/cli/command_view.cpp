// crux view: the virtual human on the wall at one posture (the paper's Fig. 1), as SVG.

#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "climbing/configuration_reacher.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/episode_replay.hpp"
#include "experiments/run_inputs.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/perform_folder.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/run_folder.hpp"
#include "reports/view_description.hpp"
#include "views/body_svg.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

// The IK settings solve a wall file's start; a run is drawn with its own config's.
const ParameterSet kViewKeys{{"experiment.urdf", "wall.file", "ik", "physics"},
                             {"ik.cache_unreachable", "ik.guess", "physics.fall_when_stuck"}};

struct ViewCommand {
  ParameterBinding binding{"view", kViewKeys};
  std::string run;
  int step = 0;
  std::string climb_choice = "greedy";
  std::string output;
  bool json = false;
  CLI::App* command = nullptr;

  void run_command() {
    ExperimentConfig config = binding.resolve();
    if (run.empty() && config.wall_file.empty()) {
      throw InputError("--run", "give a run folder (--run DIR) or a wall file (--wall-file FILE)");
    }
    if (!run.empty() && !config.wall_file.empty()) {
      throw InputError("--run", "give a run folder (--run DIR) or a wall file (--wall-file FILE), not both");
    }
    if (output.empty()) throw InputError("--output", "give the SVG file to write");
    if (!run.empty()) {
      for (const ConfigField& field : config_fields(config)) {
        if ((field.key.rfind("ik.", 0) == 0 || field.key.rfind("physics.", 0) == 0) && binding.is_set(field.key)) {
          throw InputError(binding.where(field.key), "not used with --run: a run is drawn with its own config.toml");
        }
      }
      if (is_perform_folder(run)) {
        draw_performed(config);
      } else {
        draw_run(config);
      }
      return;
    }
    check_output(config);
    const BodyModel model = load_configured_body(config);
    const Wall wall = load_wall(config.wall_file);
    const ReachabilityParameters& reach = config.settings.learning.climbing.reachability;
    ConfigurationReacher reacher(model, wall, reach, config.settings.learning.climbing.physics);
    const Posture start = reacher.require_start(config.wall_file);
    write(model, start, wall, wall_view_caption(wall, output), reach, config.settings.learning.climbing.physics,
          start_configuration(wall));
  }

  void draw_run(ExperimentConfig& config) {
    RunFolder folder = locate_run_folder(run);
    const ExperimentConfig recorded = read_run_config(folder.config_file);
    if (config.urdf.empty()) config.urdf = folder.urdf;
    check_output(config);
    const BodyModel model = load_configured_body(config);
    read_run_climb(folder, model);
    const ClimbingParameters& climbing = recorded.settings.learning.climbing;
    const RecordedClimb climb = climb_to_show(folder, model, climbing, climb_choice, "--climb");
    if (climb.postures.empty()) throw InputError(run, "the run completed no climb, so it has no posture to show");
    if (step < 0 || step >= static_cast<int>(climb.postures.size())) {
      throw InputError("--step", fmt::format("must be from 0 to {}, the postures of the climb, got {}",
                                             climb.postures.size() - 1, step));
    }
    write(model, climb.postures[step], folder.wall, run_view_caption(folder, climb, step, output),
          climbing.reachability, climbing.physics, climb_configurations(folder.wall, climb)[step]);
  }

  // A crux perform folder: step K is the simulated posture at the end of move K, the body
  // turned by its free root, the forces from its holds drawn as MuJoCo gave them.
  void draw_performed(ExperimentConfig& config) {
    if (command->count("--climb") > 0) {
      throw InputError("--climb", fmt::format("{} is a crux perform folder, which holds one climb: drop --climb", run));
    }
    const ExperimentConfig recorded = read_perform_config(std::filesystem::path(run) / "config.toml");
    if (config.urdf.empty()) config.urdf = recorded.urdf;
    check_output(config);
    const BodyModel model = load_configured_body(config);
    const PerformFolder folder = read_perform_folder(run, model);
    if (folder.trajectory.empty()) throw InputError(run, "nothing was performed, so there is no posture to show");
    const int steps = static_cast<int>(folder.moves.size());
    if (step < 0 || step > steps) {
      throw InputError(
          "--step", fmt::format("must be from 0 (the start) to {}, the moves performed or tried, got {}", steps, step));
    }
    const TrajectorySample& sample = folder.step_sample(step);
    const ViewCaption caption = performed_view_caption(folder, step, output);
    BodySvgOptions options;
    options.grasp_radius = recorded.settings.learning.climbing.reachability.ik.tolerances.grasp_radius;
    options.title = caption.title;
    options.subtitle = caption.subtitle;
    options.root_rotation = sample.root_orientation;
    options.hold_forces = &sample.hold_forces;
    write_file_atomically(output, render_body_svg(model, sample.posture, folder.wall, options));
    std::cout << (json ? performed_view_json(model, sample, caption).dump(2) + "\n" : view_text(caption));
  }

  void check_output(const ExperimentConfig& config) const {
    check_output_file(output, {run, config.wall_file, configured_urdf_path(config), binding.config_path()});
  }

  // Under the static model the drawing and the JSON add what holds the posture on the
  // holds of `configuration`.
  void write(const BodyModel& model, const Posture& posture, const Wall& wall, const ViewCaption& plain,
             const ReachabilityParameters& reach, const PhysicsParameters& physics,
             const HoldConfiguration& configuration) const {
    ViewCaption caption = with_wall_note(plain, model, posture);
    BodySvgOptions options;
    options.grasp_radius = reach.ik.tolerances.grasp_radius;
    std::optional<StanceLoads> loads;
    if (std::optional<StanceCheck> check = stance_check_for(model, wall, physics)) {
      loads = check->loads(posture, configuration);
      options.loads = &*loads;
      caption = with_stance_note(caption, model, *loads);
    }
    options.title = caption.title;
    options.subtitle = caption.subtitle;
    write_file_atomically(output, render_body_svg(model, posture, wall, options));
    std::cout << (json ? view_json(model, posture, caption, options.loads).dump(2) + "\n" : view_text(caption));
  }
};

}  // namespace

void add_view_command(CLI::App& app) {
  auto view = std::make_shared<ViewCommand>();
  auto* v = app.add_subcommand(
      "view",
      "Draw the climber on the wall at one posture, front and side (paper Fig. 1), as SVG: step K of a run's\n"
      "climb (--run DIR --step K), or the start posture of a wall file (--wall-file FILE)");
  v->add_option("--run", view->run,
                "A run folder: that of crux train or transfer, or runs/<condition>_<i> of a crux paper folder; or a "
                "crux perform folder, whose step K is the posture MuJoCo simulated at the end of move K; it is drawn "
                "with its own body and config.toml");
  v->add_option("--step", view->step, "The posture of the climb to draw: 0 is the start")->capture_default_str();
  add_climb_option(v, view->climb_choice);
  v->add_option("-o,--output", view->output, "The SVG file to write");
  v->add_flag("--json", view->json, "Print JSON instead of text");
  view->binding.bind(v);
  view->command = v;
  v->callback([view] { view->run_command(); });
}

}  // namespace crux::cli
