#pragma once
// The experiment of section IV, in three paired conditions:
//   training: learning on training wall i from empty tables;
//   transfer: learning on transfer wall i starting from training run i's Q_grid only;
//   control:  learning on transfer wall i from empty tables (what transfer must beat).
// Run i's walls and seeds derive from the experiment seed and i. Runs execute in
// parallel (TBB); every result is stored by index, so any thread count gives the same
// bytes as a serial run.

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "experiments/learning_run.hpp"
#include "experiments/shortest_plan.hpp"
#include "wall/random_wall.hpp"

namespace crux {

enum class Condition { Training = 0, Transfer = 1, Control = 2 };
inline constexpr std::array<Condition, 3> kConditions{Condition::Training, Condition::Transfer, Condition::Control};
const char* condition_name(Condition condition);

struct ExperimentSettings {
  LearningParameters learning;
  RandomWallParameters walls;
  int runs = 6;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  bool plan = true;  // compute each wall's exact shortest climb
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
  std::vector<std::size_t> wall_of_run;   // index into ExperimentResult::walls
  std::vector<std::uint64_t> learning_seeds;
};

struct ExperimentResult {
  std::vector<ExperimentWall> walls;  // training walls 0..runs-1, then transfer walls
  std::array<ConditionResult, 3> conditions;
  double seconds = 0.0;  // wall clock, informative
};

// Progress: the number of runs finished out of 3 x runs (called under a lock).
ExperimentResult run_paper_experiment(const BodyModel& model, const ExperimentSettings& settings,
                                      const std::function<void(int runs_done)>& progress = {});

// Draws the wall of (role, run) from the experiment seed, skipping candidates whose
// start configuration is unreachable (they are recorded, never used).
ExperimentWall draw_wall(const BodyModel& model, const ExperimentSettings& settings, int role, int run);

}  // namespace crux
