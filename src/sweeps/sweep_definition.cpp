#include "sweeps/sweep_definition.hpp"

#include <algorithm>
#include <map>

#include "jobs/command_keys.hpp"

namespace crux {

const ParameterSet kSweepKeys = kPaperKeys;

SweepDefinition define_sweep(const SweepGrid& grid, const std::function<ExperimentConfig(const ListChoice&)>& resolve,
                             std::size_t max_tasks) {
  std::vector<std::string> keys;
  for (const ListedKey& k : grid.keys) keys.push_back(k.key);
  // Counted, and refused when too many, before any cell is built.
  const std::size_t cell_count = grid.cells();
  std::vector<SweepCell> cells;
  cells.reserve(cell_count);
  // Each listed key's values as TOML, by position in its list.
  std::vector<std::vector<std::string>> listed(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) listed[k].resize(grid.keys[k].values);
  // A lower bound on the tasks of the cells built so far: their runs, and the walls of the
  // largest group (groups are formed by plan_sweep, which counts exactly).
  std::size_t run_tasks = 0, wall_tasks = 0;
  for (std::size_t c = 0; c < cell_count; ++c) {
    const ListChoice choice = grid.choice(c);
    SweepCell cell;
    cell.config = resolve(choice);
    const ExperimentParameters& parameters = cell.config.settings;
    run_tasks += 3 * static_cast<std::size_t>(parameters.runs());
    wall_tasks = std::max(wall_tasks, static_cast<std::size_t>(parameters.training_walls + 1) *
                                          static_cast<std::size_t>(parameters.wall_pairs));
    check_task_count(run_tasks + wall_tasks, max_tasks);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      cell.values.push_back(config_value_text(cell.config, keys[k], false));
      listed[k][choice.at(keys[k])] = config_value_text(cell.config, keys[k], true);
    }
    cells.push_back(std::move(cell));
  }
  SweepDefinition out;
  std::map<std::string, std::string> lists;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    std::string text = "[";
    for (std::size_t i = 0; i < listed[k].size(); ++i) text += (i > 0 ? ", " : "") + listed[k][i];
    lists[keys[k]] = text + "]";
  }
  ExperimentConfig& first = cells.front().config;
  out.provenance = record_provenance(first);
  ParameterSet written = kSweepKeys;
  written.exclude.push_back("experiment.threads");
  out.sweep_toml = config_to_toml(first, written, lists) + provenance_toml(out.provenance);
  out.plan = plan_sweep(std::move(keys), std::move(cells), max_tasks);
  return out;
}

}  // namespace crux
