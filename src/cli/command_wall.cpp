// crux wall generate | show: random walls, wall files and their front views.

#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "agent_space/moving_grid.hpp"
#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "experiments/run_inputs.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"
#include "configurations/reachability.hpp"
#include "views/wall_svg.hpp"
#include "wall/random_wall.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

// The wall keys of each command, and the IK that checks the start as the learning does.
const ParameterSet kGenerateParameters{{"experiment.urdf", "wall", "ik"},
                                       {"wall.file", "wall.count", "ik.cache_unreachable"}};
const ParameterSet kShowParameters{{"experiment.urdf", "wall.file", "grid", "ik"}, {"ik.cache_unreachable"}};

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

nlohmann::ordered_json start_json(const Wall& wall) {
  nlohmann::ordered_json ids;
  for (int l = 0; l < kLimbCount; ++l) ids[limb_name(static_cast<Limb>(l))] = wall.holds[wall.start[l]].id;
  return ids;
}

std::string start_summary(const Wall& wall) {
  return fmt::format("right hand {}, left hand {}, right foot {}, left foot {}", wall.holds[wall.start[0]].id,
                     wall.holds[wall.start[1]].id, wall.holds[wall.start[2]].id, wall.holds[wall.start[3]].id);
}

struct GenerateCommand {
  ParameterBinding binding{"wall generate", kGenerateParameters, generate_defaults()};
  std::string output;
  bool json = false;

  // Exit status 3 when the start configuration is not reachable: the file is written
  // so that it can be inspected, but the problem is reported, never silently passed on.
  void run() {
    const ExperimentConfig config = binding.resolve();
    Wall wall = load_configured_wall(config);
    if (!config.wall_name.empty()) wall.name = config.wall_name;
    const IkResult reach = check_start(config, wall);
    save_wall(output, wall);
    const std::string solver = ik_solver_name(config.settings.learning.climbing.reachability.ik.solver);
    if (json) {
      nlohmann::ordered_json out;
      out["file"] = output;
      out["name"] = wall.name;
      out["seed"] = *config.wall_seed;
      out["holds"] = wall.hold_count();
      out["finish_height"] = wall.finish_height;
      out["start"] = start_json(wall);
      out["start_reachable"] = reach.reached;
      out["start_iterations"] = reach.iterations;
      out["start_solver"] = solver;
      std::cout << out.dump(2) << '\n';
    } else {
      std::cout << fmt::format("wrote {}: '{}', {} holds, finish height {} m\n", output, printable(wall.name), wall.hold_count(),
                             wall.finish_height)
              << fmt::format("start configuration ({}): ", start_summary(wall));
      std::cout << (reach.reached ? fmt::format("reachable ({} solver, {} iterations)\n", solver, reach.iterations)
                                  : std::string("NOT reachable\n"));
    }
    if (reach.reached) return;
    std::cerr << fmt::format("crux: {}: the start configuration is not reachable (residual {:.3f} m)\n", output,
                             reach.residual_m);
    throw CLI::RuntimeError(3);
  }
};

struct ShowCommand {
  ParameterBinding binding{"wall show", kShowParameters};
  bool json = false;
  std::string svg;
  std::string grid_limb;
  std::string grid_at;
  GridParameters grid;
  std::string file;

  void run() {
    const ExperimentConfig config = binding.resolve();
    if (config.wall_file.empty()) throw InputError("--wall-file", "give the wall file to show");
    file = config.wall_file;
    grid = config.settings.learning.climbing.grid;
    const Wall wall = load_wall(file);
    const IkResult reach = check_start(config, wall);
    std::optional<GridPlacement> placement;
    std::optional<Limb> limb;
    if (!grid_limb.empty()) {
      limb = parse_limb(grid_limb);
      if (!limb) throw InputError("--limb", fmt::format("unknown limb '{}' (right_hand, left_hand, right_foot, left_foot)", grid_limb));
      Eigen::Vector3d at = wall.holds[wall.start[static_cast<int>(*limb)]].position;
      if (!grid_at.empty()) at = parse_wall_point(grid_at, "--at");
      placement = place_grid(grid, *limb, at);
    }
    if (!svg.empty()) {
      WallSvgOptions options;
      options.grid = placement;
      options.grid_limb = limb;
      write_file_atomically(svg, render_wall_svg(wall, options));
    }
    json ? print_json(wall, reach, placement, limb) : print_text(wall, reach, placement);
  }

  void print_text(const Wall& wall, const IkResult& reach, const std::optional<GridPlacement>& placement) const {
    Eigen::Vector3d low = wall.holds[0].position, high = low;
    for (const Hold& h : wall.holds) {
      low = low.cwiseMin(h.position);
      high = high.cwiseMax(h.position);
    }
    std::cout << fmt::format("'{}' ({}): {} holds, y from {:.2f} to {:.2f} m, z from {:.2f} to {:.2f} m\n", printable(wall.name),
                             file, wall.hold_count(), low.y(), high.y(), low.z(), high.z())
              << fmt::format("finish height {} m; start configuration: {} ({})\n", wall.finish_height,
                             start_summary(wall), reach.reached ? "reachable" : "NOT reachable");
    if (placement) {
      std::cout << "grid tiles -> holds (tile: hold id):";
      for (int tile = 0; tile < grid.tile_count(); ++tile) {
        const int hold = hold_in_tile(wall, *placement, tile);
        if (hold >= 0) std::cout << fmt::format(" {}:{}", tile, wall.holds[hold].id);
      }
      std::cout << '\n';
    }
    if (!svg.empty()) std::cout << "wrote " << svg << '\n';
  }

  void print_json(const Wall& wall, const IkResult& reach, const std::optional<GridPlacement>& placement,
                  const std::optional<Limb>& limb) const {
    nlohmann::ordered_json out;
    out["file"] = file;
    out["name"] = wall.name;
    out["holds"] = wall.hold_count();
    out["finish_height"] = wall.finish_height;
    out["start"] = start_json(wall);
    out["start_reachable"] = reach.reached;
    out["start_iterations"] = reach.iterations;
    if (placement) {
      nlohmann::ordered_json g;
      g["limb"] = limb_name(*limb);
      g["origin"] = {placement->origin.x(), placement->origin.y()};
      g["hold_tiles"] = nlohmann::json::array();
      for (const Hold& h : wall.holds) g["hold_tiles"].push_back({{"id", h.id}, {"tile", placement->tile_of(h.position)}});
      g["tile_holds"] = nlohmann::json::array();
      for (int tile = 0; tile < grid.tile_count(); ++tile) {
        const int hold = hold_in_tile(wall, *placement, tile);
        g["tile_holds"].push_back({{"tile", tile}, {"id", hold >= 0 ? wall.holds[hold].id : 0}});
      }
      out["grid"] = g;
    }
    std::cout << out.dump(2) << '\n';
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
  generate->binding.bind(g);
  g->callback([generate] { generate->run(); });

  auto show = std::make_shared<ShowCommand>();
  auto* s = wall->add_subcommand("show", "Summarise a wall file; draw it (--svg), with the moving grid on a limb (--limb)");
  s->add_flag("--json", show->json, "Print JSON instead of text");
  s->add_option("--svg", show->svg, "Write an SVG front view to this file");
  s->add_option("--limb", show->grid_limb, "Place the moving grid on this free limb (right_hand, left_hand, ...)");
  s->add_option("--at", show->grid_at, "Y,Z of the free limb (default: its start hold)");
  show->binding.bind(s);
  s->callback([show] { show->run(); });
}

}  // namespace crux::cli
