#include "experiments/run_inputs.hpp"

#include <cmath>

#include <fmt/format.h>

#include "agent_space/agent_descriptor.hpp"
#include "body/urdf_loader.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "learning/q_table_file.hpp"
#include "wall/wall_file.hpp"

namespace crux {

std::string configured_urdf_path(const ExperimentConfig& config) {
  return config.urdf.empty() ? default_body_model_path() : config.urdf;
}

BodyModel load_configured_body(const ExperimentConfig& config) { return load_body_model(configured_urdf_path(config)); }

Wall load_configured_wall(const ExperimentConfig& config) {
  if (!config.wall_file.empty()) return load_wall(config.wall_file);
  if (!config.wall_seed) throw InputError("wall.file", "give a wall: a file or a seed");
  return generate_random_wall(*config.wall_seed, config.settings.walls);
}

void check_q_grid(const QTable& q_grid, const GridParameters& grid, const std::string& source) {
  if (q_grid.action_count() != grid.tile_count()) {
    throw InputError(source, fmt::format("has {}, but the grid has {}", counted(q_grid.action_count(), "action"),
                                         counted(grid.tile_count(), "tile")));
  }
  // Codes beyond this grid's would be read as states of another shape.
  q_grid.for_each_row([&](StateCode state, auto, auto) {
    if (state >= agent_state_count(grid)) {
      throw InputError(source,
                       fmt::format("state code {} does not exist on a {} x {} grid", state, grid.columns, grid.rows));
    }
  });
}

PolicyNetwork load_checked_policy(const std::string& path, const FilterParameters& filter) {
  PolicyNetwork network = load_policy_network(path);
  if (std::abs(network.max_span_m - filter.max_span_m) > 1e-9) {
    throw InputError(path, fmt::format("a policy trained with filter.max_span = {} m, and this run has {} m: its "
                                       "observation would be another",
                                       network.max_span_m, filter.max_span_m));
  }
  return network;
}

QTable load_q_grid(const std::string& path, const GridParameters& grid) {
  QTable q_grid = load_q_table(path, grid.tile_count(), describe_grid(grid));
  check_q_grid(q_grid, grid, path);
  return q_grid;
}

}  // namespace crux
