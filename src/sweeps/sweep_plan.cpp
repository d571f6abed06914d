#include "sweeps/sweep_plan.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

bool shapes_walls(const std::string& key) {
  // The walls derive from the experiment seed and the wall and reachability keys; the
  // plan adds its budget and the filter (crux plan's keys).
  static const ParameterSet kWallKeys{
      {"experiment.seed", "experiment.urdf", "experiment.plan", "experiment.plan_max_solves",
       "experiment.plan_check_moves", "ik", "physics", "filter", "wall", "training_wall"},
      {}};
  return kWallKeys.accepts(key);
}

std::string preceding_wall_folder(int pair, int j) { return fmt::format("preceding_{}_{}", pair, j); }

std::size_t SweepPlan::run_tasks() const {
  return static_cast<std::size_t>(
      std::count_if(tasks.begin(), tasks.end(), [](const SweepTask& t) { return t.kind == SweepTaskKind::Run; }));
}

void check_task_count(std::size_t tasks, std::size_t max_tasks) {
  if (tasks > max_tasks) {
    throw InputError("experiment.walls",
                     fmt::format("the sweep has {} walls and runs; at most {} are allowed", tasks, max_tasks));
  }
}

SweepPlan plan_sweep(std::vector<std::string> keys, std::vector<SweepCell> cells, std::size_t max_tasks) {
  SweepPlan plan;
  plan.keys = std::move(keys);
  // Wall groups: cells with equal values of every listed key that shapes walls.
  std::map<std::vector<std::string>, std::size_t> groups;
  // A group's preceding training walls: K - 1 per pair for its largest K (pair w's wall j
  // is the same for every K > j).
  std::vector<std::size_t> first_cell, group_walls, group_preceding;
  std::size_t total = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    std::vector<std::string> identity;
    for (std::size_t k = 0; k < plan.keys.size(); ++k) {
      if (shapes_walls(plan.keys[k])) identity.push_back(cells[c].values[k]);
    }
    const auto [group, inserted] = groups.emplace(identity, groups.size());
    cells[c].wall_group = group->second;
    const ExperimentParameters& s = cells[c].config.settings;
    require_experiment_transfer_mode(s);
    if (inserted) {
      first_cell.push_back(c);
      group_walls.push_back(0);
      group_preceding.push_back(0);
    }
    group_walls[group->second] = std::max<std::size_t>(group_walls[group->second], s.wall_pairs);
    group_preceding[group->second] = std::max<std::size_t>(group_preceding[group->second], s.training_walls - 1);
    total += 3 * static_cast<std::size_t>(s.runs());
  }
  for (std::size_t g = 0; g < group_walls.size(); ++g) total += (2 + group_preceding[g]) * group_walls[g];
  check_task_count(total, max_tasks);
  plan.wall_groups = groups.size();
  plan.tasks.reserve(total);
  for (std::size_t g = 0; g < plan.wall_groups; ++g) {
    for (const Condition role : {Condition::Training, Condition::Transfer}) {
      for (std::size_t w = 0; w < group_walls[g]; ++w) {
        plan.tasks.push_back(
            {SweepTaskKind::Wall, first_cell[g], role, static_cast<int>(w), -1,
             std::filesystem::path("walls") / fmt::format("g{}", g) / fmt::format("{}_{}", enum_name(role), w)});
      }
    }
    for (std::size_t w = 0; w < group_walls[g]; ++w) {
      for (std::size_t j = 0; j < group_preceding[g]; ++j) {
        plan.tasks.push_back({SweepTaskKind::Wall, first_cell[g], Condition::Training, static_cast<int>(w), -1,
                              std::filesystem::path("walls") / fmt::format("g{}", g) /
                                  preceding_wall_folder(static_cast<int>(w), static_cast<int>(j)),
                              static_cast<int>(j)});
      }
    }
  }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const int runs = cells[c].config.settings.runs();
    const std::size_t first = plan.tasks.size();
    plan.first_run_task.push_back(first);
    for (const Condition condition : kConditions) {
      for (int r = 0; r < runs; ++r) {
        const int training = condition == Condition::Transfer ? static_cast<int>(first) + r : -1;
        plan.tasks.push_back(
            {SweepTaskKind::Run, c, condition, r, training,
             std::filesystem::path("runs") / fmt::format("c{}", c) / fmt::format("{}_{}", enum_name(condition), r)});
      }
    }
  }
  plan.cells = std::move(cells);
  return plan;
}

std::size_t run_task_index(const SweepPlan& plan, std::size_t cell, Condition condition, int run) {
  return plan.first_run_task[cell] + static_cast<std::size_t>(condition) * plan.cells[cell].config.settings.runs() +
         static_cast<std::size_t>(run);
}

}  // namespace crux
