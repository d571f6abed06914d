// crux wall generate | show: random walls, wall files and their front views.

#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "agent_space/moving_grid.hpp"
#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"
#include "configurations/reachability.hpp"
#include "experiments/run_inputs.hpp"
#include "outputs/output_folder.hpp"
#include "reports/wall_description.hpp"
#include "views/wall_svg.hpp"
#include "wall/random_wall.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

// The wall keys of each command, and the IK that checks the start as the learning does.
const ParameterSet kGenerateKeys{{"experiment.urdf", "wall", "ik"},
                                 {"wall.file", "wall.count", "ik.cache_unreachable", "ik.guess"}};
const ParameterSet kShowKeys{{"experiment.urdf", "wall.file", "grid", "ik"}, {"ik.cache_unreachable", "ik.guess"}};

ExperimentConfig generate_defaults() {
  ExperimentConfig defaults;
  defaults.wall_seed = 1;
  return defaults;
}

IkResult check_start(const ExperimentConfig& config, const Wall& wall) {
  const BodyModel model = load_configured_body(config);
  BodyData data(model);
  return solve_start(model, data, wall, config.settings.learning.climbing.reachability);
}

// wall generate's own key, wall.name: the name stored in the file.
std::vector<ConfigField> generate_fields(std::string& name) {
  return {{"wall.name", "Name stored in a generated wall file", &name}};
}

struct GenerateCommand {
  std::string name;
  ParameterBinding binding{"wall generate", kGenerateKeys, generate_defaults()};
  std::string output;
  bool json = false;

  // Exit status 3 when the start configuration is not reachable: the file is written
  // so that it can be inspected, but the problem is reported, never silently passed on.
  void run() {
    const ExperimentConfig config = binding.resolve();
    check_output_file(output, {configured_urdf_path(config), binding.config_path()});
    Wall wall = load_configured_wall(config);
    if (!name.empty()) wall.name = name;
    const IkResult reach = check_start(config, wall);
    save_wall(output, wall);
    const std::string solver = enum_name(config.settings.learning.climbing.reachability.ik.solver);
    std::cout << (json ? generated_wall_json(output, wall, *config.wall_seed, reach, solver).dump(2) + "\n"
                       : generated_wall_text(output, wall, reach, solver));
    if (reach.reached) return;
    std::cerr << fmt::format("crux: {}: the start configuration is not reachable (residual {:.3f} m)\n", output,
                             reach.residual_m);
    throw CLI::RuntimeError(3);
  }
};

struct ShowCommand {
  ParameterBinding binding{"wall show", kShowKeys};
  bool json = false;
  std::string svg;
  std::string grid_limb;
  std::string grid_at;

  void run() {
    const ExperimentConfig config = binding.resolve();
    if (config.wall_file.empty()) throw InputError("--wall-file", "give the wall file to show");
    if (!svg.empty()) check_output_file(svg, {config.wall_file, configured_urdf_path(config), binding.config_path()});
    const Wall wall = load_wall(config.wall_file);
    const IkResult reach = check_start(config, wall);
    std::optional<PlacedGrid> grid;
    if (!grid_limb.empty()) {
      const auto limb = parse_enum<Limb>(grid_limb);
      if (!limb)
        throw InputError("--limb", fmt::format("unknown limb '{}' (right_hand, left_hand, right_foot, left_foot)",
                                               printable(grid_limb)));
      Eigen::Vector3d at = wall.holds[wall.start[static_cast<int>(*limb)]].position;
      if (!grid_at.empty()) at = parse_wall_point(grid_at, "--at");
      const GridParameters& parameters = config.settings.learning.climbing.grid;
      grid = PlacedGrid{*limb, place_grid(parameters, *limb, at), parameters};
    }
    if (!svg.empty()) {
      WallSvgOptions options;
      if (grid) {
        options.grid = grid->placement;
        options.grid_limb = grid->limb;
      }
      write_file_atomically(svg, render_wall_svg(wall, options));
    }
    if (json) {
      std::cout << wall_summary_json(config.wall_file, wall, reach, grid).dump(2) << '\n';
      return;
    }
    std::cout << wall_summary_text(config.wall_file, wall, reach, grid);
    if (!svg.empty()) std::cout << "wrote " << svg << '\n';
  }
};

}  // namespace

void add_wall_command(CLI::App& app) {
  auto* wall = app.add_subcommand("wall", "Generate random walls and inspect wall files");
  wall->require_subcommand(1);

  auto generate = std::make_shared<GenerateCommand>();
  auto* g = wall->add_subcommand("generate", "Generate a random wall (paper III-A) and check its start with IK");
  g->add_option("-o,--output", generate->output, "Wall file to write (JSON)")->required();
  g->add_flag("--json", generate->json, "Print JSON instead of text");
  generate->binding.add_command_options(generate->name, generate_fields);
  generate->binding.bind(g);
  g->callback([generate] { generate->run(); });

  auto show = std::make_shared<ShowCommand>();
  auto* s = wall->add_subcommand(
      "show", "Summarise a wall file; draw it (-o FILE.svg), with the moving grid on a limb (--limb)");
  s->add_flag("--json", show->json, "Print JSON instead of text");
  s->add_option("-o,--output", show->svg, "Write an SVG front view to this file");
  s->add_option("--limb", show->grid_limb, "Place the moving grid on this free limb (right_hand, left_hand, ...)");
  s->add_option("--at", show->grid_at, "Y,Z of the free limb (default: its start hold)");
  show->binding.bind(s);
  s->callback([show] { show->run(); });
}

}  // namespace crux::cli
