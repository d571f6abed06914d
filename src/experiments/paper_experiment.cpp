#include "experiments/paper_experiment.hpp"

#include "common/input_error.hpp"

#include <chrono>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "climbing/configuration_reacher.hpp"
#include "common/random.hpp"
#include "configurations/filter_statistics.hpp"

namespace crux {

namespace {

// Candidates per wall before the parameters are refused. Under the static model on a
// 40-degree overhang 1 random wall in 22 has a start that holds, and 100 candidates
// left some of 60 walls without one (docs/PHYSICS.md, "Learning"); a refused candidate
// costs one start solve.
constexpr int kWallAttempts = 1000;

}  // namespace

// Every (3-configuration, possible action) pair is one freed limb of a 4-configuration
// that passes the filter (each rule only compares held holds, so freeing a limb keeps a
// configuration passing).
std::uint64_t filtered_pairs(const Wall& wall, const FilterParameters& filter) {
  const auto counts = filter_statistics({wall}, filter);
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    if (kFeetAboveHandsReadings[r] == filter.feet_above_hands) return 4 * counts[r].pass4;
  }
  return 0;
}

std::uint64_t learning_seed(std::uint64_t seed, Condition condition, int run) {
  // Transfer and control share run i's seed: common random numbers for the paired test.
  const int stream = condition == Condition::Training ? 0 : 1;
  return derive_seed(derive_seed(seed, 1000 + stream), static_cast<std::uint64_t>(run));
}

std::uint64_t preceding_learning_seed(std::uint64_t seed, int run, int j) {
  return derive_seed(derive_seed(derive_seed(seed, 1002), static_cast<std::uint64_t>(run)),
                     static_cast<std::uint64_t>(j));
}

namespace {

// The first wall of `stream`'s candidates whose start is reachable.
ExperimentWall draw_wall_from(const BodyModel& model, const ExperimentParameters& experiment, bool training,
                              std::uint64_t stream, const std::string& label) {
  ExperimentWall out;
  for (int attempt = 0; attempt < kWallAttempts; ++attempt) {
    const std::uint64_t seed = derive_seed(stream, static_cast<std::uint64_t>(attempt));
    Wall wall = generate_random_wall(seed, training ? experiment.training_wall_parameters() : experiment.walls);
    ConfigurationReacher reacher(model, wall, experiment.learning.climbing.reachability,
                                 experiment.learning.climbing.physics);
    if (reacher.reach_start() == nullptr) {
      out.rejected_seeds.push_back(seed);
      continue;
    }
    wall.name = fmt::format("{} (seed {})", label, seed);
    out.wall = std::move(wall);
    out.seed = seed;
    return out;
  }
  // Only the parameters can make every random wall's start unreachable.
  const std::string walls = training && experiment.training_wall ? "--training-wall-*" : "--wall-*";
  throw InputError(experiment.learning.climbing.physics.model == PhysicsModel::Static
                       ? walls + ", --ik-* and --physics-* parameters"
                       : walls + " and --ik-* parameters",
                   fmt::format("no random wall drawn with them has a reachable start ({} tried)", kWallAttempts));
}

}  // namespace

ExperimentWall draw_wall(const BodyModel& model, const ExperimentParameters& parameters, int role, int run) {
  const std::uint64_t stream = derive_seed(derive_seed(parameters.seed, static_cast<std::uint64_t>(role)), run);
  return draw_wall_from(model, parameters, role != kTransferWalls, stream,
                        fmt::format("{} wall {}", role == kTrainingWalls ? "training" : "transfer", run));
}

ExperimentWall draw_preceding_training_wall(const BodyModel& model, const ExperimentParameters& parameters, int pair,
                                            int j) {
  const std::uint64_t stream = derive_seed(
      derive_seed(derive_seed(parameters.seed, static_cast<std::uint64_t>(kPrecedingTrainingWalls)), pair), j);
  return draw_wall_from(model, parameters, true, stream, fmt::format("training wall {}, preceding wall {}", pair, j));
}

QTable preceding_q_grid(const BodyModel& model, std::span<const ExperimentWall> walls,
                        const ExperimentParameters& parameters, int run,
                        const std::function<void(int)>& interruption_point) {
  std::optional<QTable> q_grid;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    RunResult learnt = run_learning(model, walls[j].wall, parameters.learning,
                                    preceding_learning_seed(parameters.seed, run, static_cast<int>(j)),
                                    q_grid ? &*q_grid : nullptr, interruption_point);
    q_grid = std::move(learnt.q_grid);
  }
  return std::move(*q_grid);
}

namespace {

// Every wall of the experiment, in parallel (each is drawn from its own stream, so the
// order changes none): the training walls' preceding walls, then the training and
// transfer walls with their filtered pairs.
void draw_experiment_walls(const BodyModel& model, const ExperimentParameters& parameters,
                           const std::function<void(int)>& interruptible, ExperimentResult& result) {
  const int walls = parameters.wall_pairs, preceding = parameters.training_walls - 1;
  result.walls.resize(2 * walls);
  result.preceding_training_walls.resize(static_cast<std::size_t>(walls) * preceding);
  tbb::parallel_for(0, walls * preceding, [&](int w) {
    interruptible(w);
    result.preceding_training_walls[w] = draw_preceding_training_wall(model, parameters, w / preceding, w % preceding);
  });
  tbb::parallel_for(0, 2 * walls, [&](int w) {
    interruptible(w);
    ExperimentWall& wall = result.walls[w];
    wall = draw_wall(model, parameters, w < walls ? kTrainingWalls : kTransferWalls, w % walls);
    wall.filtered_pairs = filtered_pairs(wall.wall, parameters.learning.climbing.filter);
  });
}

// Each condition's slots for its runs, made before the runs so that each task writes its own.
void size_condition_results(int runs, ExperimentResult& result) {
  for (ConditionResult& c : result.conditions) {
    c.runs.resize(runs);
    c.wall_of_run.resize(runs);
    c.cluster_of_run.resize(runs);
    c.learning_seeds.resize(runs);
  }
}

}  // namespace

void require_experiment_transfer_mode(const ExperimentParameters& parameters) {
  if (parameters.learning.dyna.transfer == TransferMode::Network) {
    throw InputError("experiment.transfer",
                     "network orders exploration by a policy file, which crux paper and crux sweep do not take: run "
                     "crux train --transfer network --policy FILE on each wall");
  }
}

ExperimentResult run_paper_experiment(const BodyModel& model, const ExperimentParameters& parameters,
                                      const std::function<void(int)>& progress,
                                      const std::function<void()>& interruption_point) {
  require_experiment_transfer_mode(parameters);
  const auto started = std::chrono::steady_clock::now();
  const int walls = parameters.wall_pairs, runs = parameters.runs();
  std::optional<tbb::global_control> limit;
  if (parameters.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, parameters.threads);

  ExperimentResult result;
  const int preceding = parameters.training_walls - 1;
  const auto interruptible = [&](int) {
    if (interruption_point) interruption_point();
  };
  draw_experiment_walls(model, parameters, interruptible, result);
  size_condition_results(runs, result);
  std::mutex progress_mutex;
  int done = 0;
  const auto count_done = [&] {
    if (!progress) return;
    const std::lock_guard lock(progress_mutex);
    progress(++done);
  };
  const auto run_one = [&](Condition condition, int i, const QTable* initial) {
    ConditionResult& c = result.conditions[static_cast<int>(condition)];
    const int pair = i / parameters.seeds_per_wall;
    c.cluster_of_run[i] = pair;
    c.wall_of_run[i] = condition == Condition::Training ? pair : walls + pair;
    c.learning_seeds[i] = learning_seed(parameters.seed, condition, i);
    c.runs[i] = run_learning(model, result.walls[c.wall_of_run[i]].wall, parameters.learning, c.learning_seeds[i],
                             initial, interruptible);
    count_done();
  };
  // One pool for every task, so that no thread waits at the end of a phase while the other
  // finishes a long task (the exact plans take seconds under the static model): the plans,
  // the control runs, and each training run followed by its transfer run. Every task
  // writes its own slots and draws from its own streams, so the order changes no result.
  tbb::task_group tasks;
  if (parameters.plan) {
    for (int w = 0; w < 2 * walls; ++w) {
      tasks.run([&, w] {
        interruptible(w);
        result.walls[w].plan =
            shortest_plan(model, result.walls[w].wall, parameters.learning.climbing, parameters.plan_search);
      });
    }
  }
  for (int i = 0; i < runs; ++i) {
    tasks.run([&, i] {
      if (preceding == 0) {
        run_one(Condition::Training, i, nullptr);
      } else {
        const std::span<const ExperimentWall> pair_walls(
            result.preceding_training_walls.data() +
                static_cast<std::size_t>(i / parameters.seeds_per_wall) * preceding,
            preceding);
        const QTable q_grid = preceding_q_grid(model, pair_walls, parameters, i, interruptible);
        for (int j = 0; j < preceding; ++j) count_done();
        run_one(Condition::Training, i, &q_grid);
      }
      tasks.run([&, i] {
        run_one(Condition::Transfer, i, &result.conditions[static_cast<int>(Condition::Training)].runs[i].q_grid);
      });
    });
    tasks.run([&, i] { run_one(Condition::Control, i, nullptr); });
  }
  tasks.wait();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace crux
