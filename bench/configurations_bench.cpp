// The possible actions of a 3-configuration, computed at every learning step.

#include <benchmark/benchmark.h>

#include <vector>

#include "common/random.hpp"
#include "configurations/possible_actions.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

void BM_PossibleActions(benchmark::State& state) {
  const Wall wall = generate_random_wall(1);
  const FilterParameters parameters;
  // States: the start configuration with each limb free, and random filtered ones.
  std::vector<HoldConfiguration> states;
  Random random(3);
  while (states.size() < 256) {
    HoldConfiguration c;
    for (int& h : c.holds) h = static_cast<int>(random.below(wall.hold_count()));
    if (c.holds[0] == c.holds[1] || c.holds[0] == c.holds[2] || c.holds[0] == c.holds[3] || c.holds[1] == c.holds[2] ||
        c.holds[1] == c.holds[3] || c.holds[2] == c.holds[3] || !passes_filter(wall, c, parameters)) {
      continue;
    }
    c.holds[random.below(kLimbCount)] = kFree;
    states.push_back(c);
  }
  std::vector<int> buffer(wall.hold_count());
  std::size_t n = 0;
  long actions = 0;
  for (auto _ : state) {
    actions += possible_actions(wall, states[n++ & 255], parameters, buffer);
    benchmark::DoNotOptimize(buffer.data());
  }
  state.counters["actions_per_state"] = static_cast<double>(actions) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_PossibleActions);

}  // namespace
}  // namespace crux
