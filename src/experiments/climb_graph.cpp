#include "experiments/climb_graph.hpp"

#include <cstdint>
#include <deque>
#include <unordered_map>

#include "climbing/configuration_reacher.hpp"

namespace crux {

namespace {

// Distances by breadth-first search backwards from the finishing moves.
void set_distances(ClimbGraph& graph) {
  std::vector<std::vector<int>> predecessors(graph.states.size());
  std::deque<int> frontier;
  for (int s = 0; s < static_cast<int>(graph.states.size()); ++s) {
    GraphState& state = graph.states[s];
    for (const GraphMove& move : state.moves) {
      if (move.target == kFinishState) {
        if (state.distance == kNoRoute) frontier.push_back(s);
        state.distance = 1;
      } else {
        predecessors[move.target].push_back(s);
      }
    }
  }
  while (!frontier.empty()) {
    const int s = frontier.front();
    frontier.pop_front();
    for (const int p : predecessors[s]) {
      if (graph.states[p].distance != kNoRoute) continue;
      graph.states[p].distance = graph.states[s].distance + 1;
      frontier.push_back(p);
    }
  }
}

}  // namespace

ClimbGraph explore_climbs(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                          int max_ik_solves) {
  ConfigurationReacher reacher(model, wall, parameters.reachability, parameters.physics, StanceQuestion::HoldsStill);
  ClimbGraph graph;
  const HoldConfiguration start = start_configuration(wall).with(Limb::RightHand, kFree);
  graph.states.push_back({start, {}});
  std::vector<const Posture*> postures{&reacher.require_start(wall.name)};
  std::unordered_map<std::uint64_t, int> index{{encode(start, wall.hold_count()), 0}};
  std::vector<int> possible(wall.hold_count());
  const auto over_budget = [&] { return reacher.solves() >= static_cast<std::size_t>(max_ik_solves); };
  for (std::size_t current = 0; current < graph.states.size() && !graph.stopped_at_limit; ++current) {
    graph.expanded_states = current + 1;
    const HoldConfiguration configuration = graph.states[current].configuration;
    const Limb free = configuration.free_limb();
    const int count = possible_actions(wall, configuration, parameters.filter, possible);
    for (int i = 0; i < count; ++i) {
      if (over_budget()) {
        graph.stopped_at_limit = true;
        break;
      }
      const HoldConfiguration complete = configuration.with(free, possible[i]);
      const Posture* reached = reacher.reach(*postures[current], complete, next_free_limb(free));
      if (reached == nullptr) continue;
      int target = kFinishState;
      if (reacher.place(*reached).centre_of_mass.z() < wall.finish_height) {
        const HoldConfiguration next = complete.with(next_free_limb(free), kFree);
        const auto [it, added] = index.emplace(encode(next, wall.hold_count()), static_cast<int>(graph.states.size()));
        if (added) {
          graph.states.push_back({next, {}});
          postures.push_back(reached);
        }
        target = it->second;
      }
      graph.states[current].moves.push_back({possible[i], target});
    }
  }
  graph.ik_solves = reacher.solves();
  set_distances(graph);
  return graph;
}

std::vector<int> optimal_holds(const ClimbGraph& graph, const GraphState& state) {
  std::vector<int> holds;
  if (state.distance == kNoRoute) return holds;
  for (const GraphMove& move : state.moves) {
    const int after = move.target == kFinishState ? 0 : graph.states[move.target].distance;
    if (after != kNoRoute && after + 1 == state.distance) holds.push_back(move.hold);
  }
  return holds;
}

}  // namespace crux
