#pragma once
// The inputs a configured command reads, checked the same way for every caller: the
// body model, the wall (a file or a seed) and a transferred Q_grid.

#include "climbing/policy_network.hpp"
#include "experiments/experiment_config.hpp"
#include "learning/q_table.hpp"

namespace crux {

// The configured URDF's path, or the default body model's.
std::string configured_urdf_path(const ExperimentConfig& config);

// The body model of configured_urdf_path.
BodyModel load_configured_body(const ExperimentConfig& config);

// The wall of config.wall_file, or the random wall of config.wall_seed drawn with the
// configured wall parameters. InputError("wall.file", ...) when neither is given.
Wall load_configured_wall(const ExperimentConfig& config);

// A Q_grid for `grid`: InputError(source, ...) when its action count is not the grid's
// tile count or one of its state codes does not belong to the grid.
void check_q_grid(const QTable& q_grid, const GridParameters& grid, const std::string& source);

// A Q_grid file for `grid`: InputError(path, ...) when its tile count or one of its
// state codes does not belong to that grid.
QTable load_q_grid(const std::string& path, const GridParameters& grid);

// The policy network of a file (climbing/policy_network), refused with an InputError
// naming the file when it was trained under another filter.max_span: its observation's
// lengths and bounds would be another's.
PolicyNetwork load_checked_policy(const std::string& path, const FilterParameters& filter);

}  // namespace crux
