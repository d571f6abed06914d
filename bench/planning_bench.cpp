// Dyna's planning cost per real step (Algorithm 2, lines 24-29), uniform against
// prioritized sweeping, with the same budget of 50 updates, on a synthetic model the
// size of a run's (about 5000 experienced pairs): 1000 states of 20 actions, of which
// 60 % fail (a -1000 self-loop, as unreachable configurations do), and one state in a
// hundred finishes (+200000, back to the start).

#include <benchmark/benchmark.h>

#include <vector>

#include "common/random.hpp"
#include "learning/dyna_q.hpp"

namespace crux {
namespace {

constexpr int kStates = 1000, kActions = 20, kExperienced = 5000;

std::vector<Experience> synthetic_experiences() {
  Random random(11);
  std::vector<Experience> out;
  for (int i = 0; i < kExperienced; ++i) {
    const StateCode s = random.below(kStates);
    const ActionCode a = static_cast<ActionCode>(random.below(kActions));
    Experience e{s, s, a, a, -1.0, s, s};
    if (random.uniform() < 0.6) {
      e.reward = -1000.0;
    } else if (s % 100 == 99) {
      e.reward = 200000.0;
      e.next_wall_state = e.next_grid_state = 0;
    } else {
      e.next_wall_state = e.next_grid_state = random.below(kStates);
    }
    out.push_back(e);
  }
  return out;
}

void plan(benchmark::State& state, Planner planner) {
  DynaParameters settings;
  settings.planner = planner;
  DynaQAgent agent(kActions, kActions, settings, 1);
  std::vector<ActionCandidate> all;
  for (ActionCode a = 0; a < kActions; ++a) all.push_back({a, a, true});
  for (StateCode s = 0; s < kStates; ++s) agent.observe({s, s}, all);
  const std::vector<Experience> experiences = synthetic_experiences();
  for (const Experience& e : experiences) agent.learn(e);  // the model a run has built
  std::size_t next = 0;
  for (auto _ : state) {
    agent.learn(experiences[next]);
    next = (next + 1) % experiences.size();
  }
  benchmark::DoNotOptimize(agent.q_wall().state_count());
}

void BM_PlanningStepUniform(benchmark::State& state) { plan(state, Planner::Uniform); }
void BM_PlanningStepPrioritized(benchmark::State& state) { plan(state, Planner::Prioritized); }
BENCHMARK(BM_PlanningStepUniform);
BENCHMARK(BM_PlanningStepPrioritized);

}  // namespace
}  // namespace crux
