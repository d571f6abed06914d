#pragma once
// Every climb the learning's rules allow on a wall, as a graph: the 3-configurations
// reachable from the start (right hand free), each with its moves (a possible hold whose
// 4-configuration is C-reachable, under the same IK test and cache as the MDP and
// experiments/shortest_plan), and each state's distance to the finish in actions. Where
// shortest_plan gives one optimal climb from the start, the graph gives every optimal
// move from every state a climb can reach: the labels a learner copying the plans needs
// on the states its own mistakes lead to (DAgger, Ross et al. 2011).

#include <cstddef>
#include <vector>

#include "climbing/climbing_mdp.hpp"
#include "configurations/hold_configuration.hpp"

namespace crux {

inline constexpr int kFinishState = -1;  // a move's target when its stance finishes the climb
inline constexpr int kNoRoute = -1;      // a state's distance when no climb finishes from it

struct GraphMove {
  int hold;    // hold index taken by the free limb
  int target;  // the state reached (its 3-configuration), or kFinishState
};

struct GraphState {
  HoldConfiguration configuration;  // a 3-configuration
  std::vector<GraphMove> moves;     // the reachable ones, in possible_actions' order
  int distance = kNoRoute;          // actions to the finish
};

struct ClimbGraph {
  std::vector<GraphState> states;  // breadth-first from the start, states[0]
  // The budget ran out: the states from expanded_states on (and the last expanded one's
  // later moves) were never explored, so their distances say nothing.
  bool stopped_at_limit = false;
  std::size_t expanded_states = 0;
  std::size_t ik_solves = 0;
};

// The graph within `max_ik_solves` solves (the plans' budget is too small for whole walls:
// random wall 3's plan alone takes about 34000). A state's distance counts only moves the
// graph holds, so it is exact when the search did not stop at its limit.
ClimbGraph explore_climbs(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                          int max_ik_solves);

// The moves of `state` along which the finish is nearest (empty when no route finishes).
std::vector<int> optimal_holds(const ClimbGraph& graph, const GraphState& state);

}  // namespace crux
