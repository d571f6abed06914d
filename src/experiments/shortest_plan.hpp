#pragma once
// An exact shortest climb under the learning's rules: breadth-first search over
// 3-configurations from the start (right hand free), where an action is a possible hold
// whose 4-configuration is C-reachable (the same IK test and cache as the MDP), the
// free limb follows the round robin, and the climb ends when the centre of mass
// reaches the finishing height. The paper says an optimal climb takes about 10 actions.

#include <cstddef>
#include <vector>

#include "climbing/climbing_mdp.hpp"

namespace crux {

struct PlanSettings {
  int max_length = 60;
  std::size_t max_states = 500000;  // gives up beyond this many expanded states
};

struct Plan {
  bool found = false;
  int length = 0;                  // actions
  std::vector<int> hold_ids;       // the hold taken by each action, in order
  std::vector<Limb> limbs;         // the limb that moved at each action
  std::size_t expanded_states = 0;
  std::size_t ik_solves = 0;
};

Plan shortest_plan(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                   const PlanSettings& settings = {});

}  // namespace crux
