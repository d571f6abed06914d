#pragma once
// The experiment of section IV, in three paired conditions, over W wall pairs with K
// learning seeds each (run r = w K + k):
//   training: learning on training wall w from empty tables (with K training walls, on
//             pair w's K - 1 preceding training walls in order and then on training
//             wall w, each run starting from the Q_grid the previous one ended with and
//             an empty Q_wall; the training result is the last run's);
//   transfer: learning on transfer wall w starting from training run r's Q_grid only;
//   control:  learning on transfer wall w from empty tables, with transfer run r's seed
//             (what transfer must beat).
// Walls derive from the experiment seed and w, learning seeds from it and r. Runs on one
// wall are not independent: the wall is the cluster of the statistics. Runs execute in
// parallel (TBB); every result is stored by index, so any thread count gives the same
// bytes as a serial run.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/enum_names.hpp"
#include "experiments/learning_run.hpp"
#include "experiments/shortest_plan.hpp"
#include "simulation/performed_climb.hpp"
#include "wall/random_wall.hpp"

namespace crux {

enum class Condition { Training = 0, Transfer = 1, Control = 2 };
inline constexpr std::array<Condition, 3> kConditions{Condition::Training, Condition::Transfer, Condition::Control};
template <>
struct EnumNames<Condition> {
  static constexpr std::array<EnumName<Condition>, 3> entries{
      {{Condition::Training, "training"}, {Condition::Transfer, "transfer"}, {Condition::Control, "control"}}};
};

// How runs are analysed (docs/OUTPUTS.md): Table I's beginning window, the episode
// length that counts as climbing well, and the cluster bootstrap's size.
struct AnalysisParameters {
  int beginning = 2000;       // iterations; also the early and late windows of the metrics
  int threshold_length = 60;  // time to threshold and take-off
  int bootstrap_resamples = 10000;
};

struct ExperimentParameters {
  LearningParameters learning;
  AnalysisParameters analysis;
  RandomWallParameters walls;
  // The training walls' generator parameters ([training_wall]) when they differ from the
  // transfer walls' (`walls`); none: the training walls are shaped like the transfer walls.
  std::optional<RandomWallParameters> training_wall;
  int wall_pairs = 6;      // training wall w and transfer wall w
  int seeds_per_wall = 1;  // learning seeds per wall pair
  int training_walls = 1;  // K: walls a training run learns Q_grid on, in sequence
  std::uint64_t seed = 1;
  int threads = 0;   // 0: all cores
  bool plan = true;  // compute each wall's exact shortest climb
  PlanParameters plan_search;

  int runs() const { return wall_pairs * seeds_per_wall; }  // per condition
  // What shapes the training walls, preceding ones included.
  const RandomWallParameters& training_wall_parameters() const { return training_wall ? *training_wall : walls; }
  // Every learning run: K per training run, one per transfer and control run.
  long learning_runs() const { return static_cast<long>(training_walls + 2) * runs(); }
};

struct ExperimentWall {
  Wall wall;
  std::uint64_t seed = 0;
  std::vector<std::uint64_t> rejected_seeds;  // walls drawn first whose start was unreachable
  Plan plan;
  std::uint64_t filtered_pairs = 0;  // (3-configuration, possible action) pairs on the wall
};

struct ConditionResult {
  std::vector<RunResult> runs;
  std::vector<std::size_t> wall_of_run;     // index into ExperimentResult::walls
  std::vector<std::size_t> cluster_of_run;  // the wall pair w of run r
  std::vector<std::uint64_t> learning_seeds;
};

struct ExperimentResult {
  std::vector<ExperimentWall> walls;  // training walls 0..W-1, then transfer walls
  // Pair w's preceding training wall j at w (K - 1) + j (no plan, no filtered pairs).
  std::vector<ExperimentWall> preceding_training_walls;
  std::array<ConditionResult, 3> conditions;
  double seconds = 0.0;  // wall clock, informative
};

// InputError naming experiment.transfer for the network mode, whose policy file the
// experiment (and a sweep of it) does not take: it learns each wall with crux train.
void require_experiment_transfer_mode(const ExperimentParameters& parameters);

// Progress: the number of runs finished out of learning_runs() (called under a lock).
// `interruption_point` is called often from the worker threads (before each wall and at
// every learning iteration); an exception it throws stops the experiment and leaves it.
ExperimentResult run_paper_experiment(const BodyModel& model, const ExperimentParameters& parameters,
                                      const std::function<void(int runs_done)>& progress = {},
                                      const std::function<void()>& interruption_point = {});

// The roles of draw_wall: each role is its own random stream of the experiment seed, so
// drawing preceding training walls shifts no other wall.
inline constexpr int kTrainingWalls = 0, kTransferWalls = 1, kPrecedingTrainingWalls = 2;

// Draws the wall of (role, wall pair) from the experiment seed, skipping candidates
// whose start configuration is unreachable (they are recorded, never used).
ExperimentWall draw_wall(const BodyModel& model, const ExperimentParameters& parameters, int role, int pair);
// Preceding training wall j (0..K-2) of a pair: the stream of kPrecedingTrainingWalls and
// the pair, then j.
ExperimentWall draw_preceding_training_wall(const BodyModel& model, const ExperimentParameters& parameters, int pair,
                                            int j);

// The learning seed of run `run` of `condition`: its own stream of the experiment seed.
// Transfer and control share run r's seed (common random numbers for the paired test).
std::uint64_t learning_seed(std::uint64_t seed, Condition condition, int run);
// The learning seed of training run `run` on its preceding training wall j: a stream of
// its own, so that the last training run keeps learning_seed's.
std::uint64_t preceding_learning_seed(std::uint64_t seed, int run, int j);

// Training run `run` over its K - 1 preceding training walls (`walls`, in order), each
// starting from the Q_grid the previous one ended with (the first from an empty one): the
// Q_grid that the run on the pair's training wall starts from. `walls` is not empty.
QTable preceding_q_grid(const BodyModel& model, std::span<const ExperimentWall> walls,
                        const ExperimentParameters& parameters, int run,
                        const std::function<void(int)>& interruption_point = {});

// The (3-configuration, possible action) pairs of `wall` that pass the filter.
std::uint64_t filtered_pairs(const Wall& wall, const FilterParameters& filter);

}  // namespace crux
