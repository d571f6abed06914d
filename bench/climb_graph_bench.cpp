// A whole wall's climb graph (experiments/climb_graph) against its shortest plan
// (experiments/shortest_plan) on random wall 3: the graph explores every state a climb
// can reach, where the plan stops at the first climb that finishes.

#include <benchmark/benchmark.h>

#include "body/urdf_loader.hpp"
#include "experiments/climb_graph.hpp"
#include "experiments/shortest_plan.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr int kWholeWall = 5000000;

void BM_ShortestPlanWall3(benchmark::State& state) {
  const BodyModel model = load_body_model(default_body_model_path());
  const Wall wall = generate_random_wall(3);
  for (auto _ : state) {
    const Plan plan = shortest_plan(model, wall, ClimbingParameters{});
    state.counters["ik_solves"] = static_cast<double>(plan.ik_solves);
  }
}

void BM_ClimbGraphWall3(benchmark::State& state) {
  const BodyModel model = load_body_model(default_body_model_path());
  const Wall wall = generate_random_wall(3);
  for (auto _ : state) {
    const ClimbGraph graph = explore_climbs(model, wall, ClimbingParameters{}, kWholeWall);
    state.counters["ik_solves"] = static_cast<double>(graph.ik_solves);
    state.counters["states"] = static_cast<double>(graph.states.size());
  }
}

BENCHMARK(BM_ShortestPlanWall3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClimbGraphWall3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace crux
