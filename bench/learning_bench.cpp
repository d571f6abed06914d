// End to end: one 8000-iteration training run (Algorithm 2 with Dyna-Q, IK and the
// cache) on a random wall, with each IK solver. The paper reports 30 hours for this
// on a 2.6 GHz Opteron in Matlab.

#include <benchmark/benchmark.h>

#include "body/urdf_loader.hpp"
#include "experiments/learning_run.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

void run_training(benchmark::State& state, IkSolverKind solver, Planner planner = Planner::Uniform) {
  const BodyModel model = load_body_model(default_body_model_path());
  const Wall wall = generate_random_wall(1);
  LearningParameters parameters;
  parameters.climbing.reachability.ik.solver = solver;
  parameters.dyna.planner = planner;
  long episodes = 0;
  for (auto _ : state) {
    const RunResult result = run_learning(model, wall, parameters, 42);
    episodes += static_cast<long>(result.episode_lengths.size());
    benchmark::DoNotOptimize(result.q_grid.state_count());
  }
  state.counters["episodes"] = static_cast<double>(episodes) / static_cast<double>(state.iterations());
}

void BM_TrainingRunFast(benchmark::State& state) { run_training(state, IkSolverKind::Fast); }
void BM_TrainingRunPaper(benchmark::State& state) { run_training(state, IkSolverKind::Paper); }
void BM_TrainingRunFastPrioritized(benchmark::State& state) {
  run_training(state, IkSolverKind::Fast, Planner::Prioritized);
}
// Algorithm 3 alone on 40 candidates with random-stream draws: the cost that the named
// streams add to each iteration (the random action hashes every candidate).
void BM_SelectAction(benchmark::State& state) {
  QTable wall(45), grid(35);
  std::vector<ActionCandidate> candidates;
  for (ActionCode a = 0; a < 40; ++a) candidates.push_back({a, a % 35, a < 35});
  for (ActionCode a = 0; a < 40; a += 3) wall.set_value(7, a, -100.0), wall.add_visit(7, a);
  const SelectionStreams streams(1);
  std::uint64_t iteration = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(select_action(wall, grid, {7, 9}, candidates, 0.1, streams, iteration++));
  }
}
BENCHMARK(BM_SelectAction);

BENCHMARK(BM_TrainingRunFast)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_TrainingRunFastPrioritized)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_TrainingRunPaper)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace crux
