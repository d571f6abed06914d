#include "sweeps/sweep_task.hpp"

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "jobs/learning_job.hpp"
#include "learning/q_table_file.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/sweep_files.hpp"
#include "reports/plan_description.hpp"
#include "wall/wall_file.hpp"

namespace crux {

namespace fs = std::filesystem;

namespace {

void write_wall_task(const SweepTask& task, const SweepCell& cell, const BodyModel& model, const fs::path& folder) {
  const ExperimentParameters& parameters = cell.config.settings;
  const int role = task.condition == Condition::Training ? kTrainingWalls : kTransferWalls;
  const ExperimentWall drawn = task.preceding >= 0
                                   ? draw_preceding_training_wall(model, parameters, task.index, task.preceding)
                                   : draw_wall(model, parameters, role, task.index);
  nlohmann::ordered_json facts;
  facts["name"] = drawn.wall.name;
  facts["seed"] = drawn.seed;
  facts["rejected_seeds"] = drawn.rejected_seeds;
  facts["filtered_pairs"] = filtered_pairs(drawn.wall, parameters.learning.climbing.filter);
  facts["plan"] = nullptr;
  if (parameters.plan && task.preceding < 0) {
    facts["plan"] =
        plan_json(drawn.wall, shortest_plan(model, drawn.wall, parameters.learning.climbing, parameters.plan_search));
  }
  save_wall((folder / "wall.json").string(), drawn.wall);
  write_sweep_wall_facts(folder, facts);
}

void write_run_task(const SweepPlan& plan, const SweepTask& task, const BodyModel& model, const fs::path& sweep_folder,
                    const fs::path& folder) {
  const SweepCell& cell = plan.cells[task.cell];
  const ExperimentParameters& settings = cell.config.settings;
  const int pair = task.index / settings.seeds_per_wall;
  const bool training_wall = task.condition == Condition::Training;
  // The run's own config.toml replays it with crux train or crux transfer: the job reads
  // its wall from the seed and its Q_grid from the training run's folder, as they would.
  LearningJob job;
  job.config = cell.config;
  job.config.settings.seed = learning_seed(settings.seed, task.condition, task.index);
  job.config.wall_seed = draw_wall(model, settings, training_wall ? kTrainingWalls : kTransferWalls, pair).seed;
  // crux train draws the wall of that seed with [wall]'s keys: a training wall's are
  // [training_wall]'s, which the run's config.toml then records under [wall].
  if (training_wall) job.config.settings.walls = settings.training_wall_parameters();
  if (task.condition == Condition::Transfer) {
    const SweepTask& training = plan.tasks[static_cast<std::size_t>(task.depends_on)];
    job.config.q_grid = fs::absolute(sweep_folder / training.folder / "q_grid.bin").lexically_normal().string();
  }
  if (training_wall && settings.training_walls > 1) {
    // crux paper's K - 1 runs before the last, on the same walls with the same seeds. The
    // Q_grid they leave is an input of the last run, so it lies beside the run's folder
    // (an input may not lie in its output folder), where the run's config.toml names it.
    std::vector<ExperimentWall> preceding;
    for (int j = 0; j < settings.training_walls - 1; ++j) {
      preceding.push_back(draw_preceding_training_wall(model, settings, pair, j));
    }
    const fs::path q_grid = fs::absolute(sweep_folder / preceding_q_grid_file(task)).lexically_normal();
    make_output_directory(q_grid.parent_path());
    save_q_table(q_grid.string(), preceding_q_grid(model, preceding, settings, task.index),
                 describe_grid(settings.learning.climbing.grid));
    job.config.q_grid = q_grid.string();
    job.continues_training = true;
  }
  job.condition = task.condition;
  job.output = folder;
  job.model = &model;
  run_learning_job(std::move(job), {"crux sweep", {}, {}, {}});
}

}  // namespace

fs::path preceding_q_grid_file(const SweepTask& task) {
  return task.folder.parent_path() / (task.folder.filename().string() + ".preceding_q_grid.bin");
}

void run_sweep_task(const SweepPlan& plan, std::size_t index, const BodyModel& model, const fs::path& sweep_folder) {
  const SweepTask& task = plan.tasks.at(index);
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const fs::path partial = sweep_folder / kPartialFolder / fmt::format("{}.{}.{}", index, host, ::getpid());
  std::error_code error;
  fs::remove_all(partial, error);
  make_output_directory(partial);
  if (task.kind == SweepTaskKind::Wall) {
    write_wall_task(task, plan.cells[task.cell], model, partial);
  } else {
    write_run_task(plan, task, model, sweep_folder, partial);
  }
  const fs::path destination = sweep_folder / task.folder;
  make_output_directory(destination.parent_path());
  fs::rename(partial, destination, error);
  if (error) throw InputError(destination.string(), "cannot move the finished task here: " + error.message());
}

}  // namespace crux
