#pragma once
// What a sweep computes (docs/OUTPUTS.md), as independent tasks in a fixed order:
//   a wall task per wall of each wall group: draws it, counts its filtered pairs and,
//     with experiment.plan, finds its exact shortest climb (walls/g<G>/<role>_<w>/);
//     with experiment.training_walls K > 1, also each pair's K - 1 preceding training
//     walls, without a plan as in crux paper (walls/g<G>/preceding_<w>_<j>/);
//   a run task per cell, condition and run, as in crux paper (runs/c<C>/<condition>_<r>/);
//     a training run with K > 1 learns on its K walls in sequence within its one task.
// Cells that agree on every listed key that shapes walls or plans form one wall group
// and share its walls. A transfer run starts from its training run's Q_grid, so it
// depends on that task; every other task can start at once. Runs draw their walls
// themselves (draw_wall is deterministic), so no run waits for a wall task.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/experiment_config.hpp"
#include "experiments/paper_experiment.hpp"

namespace crux {

// Whether a key changes the walls a cell draws or their plans.
bool shapes_walls(const std::string& key);

// The folder, under walls/g<G>/, of pair w's preceding training wall j (K > 1).
std::string preceding_wall_folder(int pair, int j);

struct SweepCell {
  ExperimentConfig config;          // finalized
  std::vector<std::string> values;  // each listed key's value in this cell, as plain text
  std::size_t wall_group = 0;
};

enum class SweepTaskKind { Wall, Run };

struct SweepTask {
  SweepTaskKind kind = SweepTaskKind::Run;
  std::size_t cell = 0;                       // a run's cell; for a wall, the first cell of its group
  Condition condition = Condition::Training;  // a wall: Training for a training wall, else Transfer
  int index = 0;                              // a run's r, a wall's pair w
  int depends_on = -1;                        // the task that must finish first (a transfer run's training run)
  std::filesystem::path folder;               // relative to the sweep folder
  int preceding = -1;                         // a preceding training wall's j (0..K-2); -1 for any other task
};

struct SweepPlan {
  std::vector<std::string> keys;  // the listed keys
  std::vector<SweepCell> cells;
  std::size_t wall_groups = 0;
  std::vector<SweepTask> tasks;
  std::vector<std::size_t> first_run_task;  // per cell: its runs, by condition then r

  std::size_t run_tasks() const;
};

// The most tasks a sweep may have: its plan keeps one entry per task (~100 bytes).
inline constexpr std::size_t kMaxSweepTasks = 10000000;

// InputError("experiment.walls") when `tasks`, a count of the sweep's tasks or a lower
// bound on it, exceeds `max_tasks`.
void check_task_count(std::size_t tasks, std::size_t max_tasks);

// The tasks of `cells` (their wall_group set here); InputError("experiment.walls") when
// the sweep exceeds `max_tasks`.
SweepPlan plan_sweep(std::vector<std::string> keys, std::vector<SweepCell> cells,
                     std::size_t max_tasks = kMaxSweepTasks);

// The task of run r of `condition` in `cell`.
std::size_t run_task_index(const SweepPlan& plan, std::size_t cell, Condition condition, int run);

}  // namespace crux
