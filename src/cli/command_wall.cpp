// crux wall generate | show: random walls, wall files and their front views.

#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "body/urdf_loader.hpp"
#include "agent_space/moving_grid.hpp"
#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "configurations/reachability.hpp"
#include "views/wall_svg.hpp"
#include "wall/random_wall.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

struct StartCheckOptions {
  std::string urdf = default_body_model_path();
  std::string solver = "fast";
  RootTargetParameters root;

  void add(CLI::App* command) {
    command->add_option("--urdf", urdf, "URDF file of the body")->capture_default_str();
    command->add_option("--solver", solver, "IK solver for the start check: paper or fast")->capture_default_str();
  }

  IkResult check(const Wall& wall) const {
    IkSettings settings;
    settings.solver = require_ik_solver(solver, "--solver");
    const BodyModel model = load_body_model(urdf);
    BodyData data(model);
    return solve_start(model, data, wall, settings, root);
  }
};

std::string start_summary(const Wall& wall) {
  return fmt::format("right hand {}, left hand {}, right foot {}, left foot {}", wall.holds[wall.start[0]].id,
                     wall.holds[wall.start[1]].id, wall.holds[wall.start[2]].id, wall.holds[wall.start[3]].id);
}

struct GenerateCommand {
  std::uint64_t seed = 1;
  std::string output;
  std::string name;
  RandomWallParameters parameters;
  StartCheckOptions start;

  // Exit status 3 when the start configuration is not reachable: the file is written
  // so that it can be inspected, but the problem is reported, never silently passed on.
  void run() {
    Wall wall = generate_random_wall(seed, parameters);
    if (!name.empty()) wall.name = name;
    const IkResult reach = start.check(wall);
    save_wall(output, wall);
    std::cout << fmt::format("wrote {}: '{}', {} holds, finish height {} m\n", output, wall.name, wall.hold_count(),
                             wall.finish_height)
              << fmt::format("start configuration ({}): ", start_summary(wall));
    if (reach.reached) {
      std::cout << fmt::format("reachable ({} solver, {} iterations)\n", start.solver, reach.iterations);
      return;
    }
    std::cout << "NOT reachable\n";
    std::cerr << fmt::format("crux: {}: the start configuration is not reachable (residual {:.3f} m)\n", output,
                             reach.residual_m);
    throw CLI::RuntimeError(3);
  }
};

struct ShowCommand {
  std::string file;
  bool json = false;
  std::string svg;
  std::string grid_limb;
  std::string grid_at;
  GridParameters grid;
  StartCheckOptions start;

  void run() {
    const Wall wall = load_wall(file);
    const IkResult reach = start.check(wall);
    std::optional<GridPlacement> placement;
    std::optional<Limb> limb;
    if (!grid_limb.empty()) {
      limb = parse_limb(grid_limb);
      if (!limb) throw InputError("--grid", fmt::format("unknown limb '{}' (right_hand, left_hand, right_foot, left_foot)", grid_limb));
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
    std::cout << fmt::format("'{}' ({}): {} holds, y from {:.2f} to {:.2f} m, z from {:.2f} to {:.2f} m\n", wall.name,
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
    nlohmann::ordered_json start_ids;
    for (int l = 0; l < kLimbCount; ++l) start_ids[limb_name(static_cast<Limb>(l))] = wall.holds[wall.start[l]].id;
    out["start"] = start_ids;
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
  g->add_option("--seed", generate->seed, "Seed of the wall")->capture_default_str();
  g->add_option("-o,--output", generate->output, "Wall file to write (JSON)")->required();
  g->add_option("--name", generate->name, "Name stored in the file");
  g->add_option("--columns", generate->parameters.columns, "Tiles across")->capture_default_str();
  g->add_option("--rows", generate->parameters.rows, "Tiles up")->capture_default_str();
  g->add_option("--tile-width", generate->parameters.tile_width, "Tile width (m)")->capture_default_str();
  g->add_option("--tile-height", generate->parameters.tile_height, "Tile height (m)")->capture_default_str();
  g->add_option("--sigma", generate->parameters.sigma, "Standard deviation of hold displacement (m)")
      ->capture_default_str();
  g->add_option("--hold-radius", generate->parameters.hold_radius, "Hold radius (m)")->capture_default_str();
  g->add_option("--finish-height", generate->parameters.finish_height, "Finishing height of the centre of mass (m)")
      ->capture_default_str();
  generate->start.add(g);
  g->callback([generate] { generate->run(); });

  auto show = std::make_shared<ShowCommand>();
  auto* s = wall->add_subcommand("show", "Summarise a wall file; draw it (--svg), with the moving grid (--grid)");
  s->add_option("file", show->file, "Wall file (JSON)")->required();
  s->add_flag("--json", show->json, "Print JSON instead of text");
  s->add_option("--svg", show->svg, "Write an SVG front view to this file");
  s->add_option("--grid", show->grid_limb, "Place the moving grid on this free limb (right_hand, left_hand, ...)");
  s->add_option("--at", show->grid_at, "Y,Z of the free limb (default: its start hold)");
  show->start.add(s);
  s->callback([show] { show->run(); });
}

}  // namespace crux::cli
