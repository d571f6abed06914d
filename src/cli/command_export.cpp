// crux export --mjcf: the climber at a wall's start, on that wall, as a MuJoCo model
// (docs/PHYSICS.md, "Performed in MuJoCo").

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "climbing/configuration_reacher.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/run_inputs.hpp"
#include "outputs/output_folder.hpp"
#include "reports/export_description.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/mujoco_model.hpp"

namespace crux::cli {

namespace {

// The wall (a file or a seed), the body, the IK and the static model that place the
// climber at the start, and the contacts' parameters.
const ParameterSet kExportKeys{{"experiment.urdf", "wall", "ik", "physics"},
                               {"wall.count", "ik.cache_unreachable", "ik.guess", "physics.fall_when_stuck"}};

ExperimentConfig export_defaults() {
  ExperimentConfig defaults;
  defaults.wall_seed = 1;
  return defaults;
}

struct ExportCommand {
  ParameterBinding binding{"export", kExportKeys, export_defaults()};
  bool mjcf = false;
  std::string output;
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    if (!mjcf) throw InputError("--mjcf", "give the format to write: --mjcf (MuJoCo's MJCF), the only one");
    if (output.empty()) throw InputError("--output", "give the file to write");
    check_output_file(output, {config.wall_file, configured_urdf_path(config), binding.config_path()});
    const BodyModel model = load_configured_body(config);
    const Wall wall = load_configured_wall(config);
    const ClimbingParameters& climbing = config.settings.learning.climbing;
    ConfigurationReacher reacher(model, wall, climbing.reachability, climbing.physics);
    const Posture& start = reacher.require_start(config.wall_file.empty() ? wall.name : config.wall_file);
    const PhysicsParameters& physics = climbing.physics;
    const StrengthProfile limits =
        motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
    const std::string text = mjcf_text(model, wall, physics, limits, start);
    // What MuJoCo would refuse is refused here, before anything is written.
    MujocoModel(text, configured_urdf_path(config));
    write_file_atomically(output, text);
    const MjcfExport written = describe_mjcf_export(output, model, wall);
    std::cout << (json ? mjcf_export_json(written).dump(2) + "\n" : mjcf_export_text(written));
  }
};

}  // namespace

void add_export_command(CLI::App& app) {
  auto cmd = std::make_shared<ExportCommand>();
  auto* command = app.add_subcommand(
      "export",
      "Write the climber at a wall's start, on that wall, for another program: --mjcf, a MuJoCo model (free root, "
      "one motor per joint at its torque limit, the grasps as constraints)");
  command->add_flag("--mjcf", cmd->mjcf, "Write MuJoCo's MJCF (MuJoCo 2.2.2 loads it as written)");
  command->add_option("-o,--output", cmd->output, "The file to write");
  command->add_flag("--json", cmd->json, "Print JSON instead of text");
  cmd->binding.bind(command);
  command->callback([cmd] { cmd->run(); });
}

}  // namespace crux::cli
