#pragma once
// An exact shortest climb under the learning's rules: breadth-first search over
// 3-configurations from the start (right hand free), where an action is a possible hold
// whose 4-configuration is C-reachable (the same IK test and cache as the MDP), the
// free limb follows the round robin, and the climb ends when the centre of mass
// reaches the finishing height. The paper says an optimal climb takes about 10 actions.

#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "climbing/climbing_mdp.hpp"

namespace crux {

// IK solves dominate the search's time and every stored state costs one, so a budget of
// solves bounds both time and memory on a wall of any size (12-20 us per solve on average
// on this machine, since a query the reach envelope rules out does not iterate).
struct PlanParameters {
  int max_ik_solves = 50000;
  // Static model only: a move counts when, besides its new stance, every posture along its
  // IK path (the replay's samples) holds still on the three holds kept during it.
  bool check_moves = false;
  int move_samples = 16;  // per move, as the replay draws them (the last is the new stance)
  // Dynamic model only: plans searched after the first, each refusing the moves that
  // failed in MuJoCo (experiments/performed_plan).
  int max_replans = 20;
};

struct Plan {
  PhysicsModel physics_model = PhysicsModel::Kinematic;  // the model it planned under
  bool found = false;
  bool stopped_at_limit = false;  // the budget ran out before a climb was found or ruled out
  int length = 0;                 // actions
  std::vector<int> hold_ids;      // the hold taken by each action, in order
  std::vector<Limb> limbs;        // the limb that moved at each action
  std::vector<Posture> postures;  // the start, then the stance each action reached
  std::size_t expanded_states = 0;
  std::size_t ik_solves = 0;
  bool checked_moves = false;                // PlanParameters::check_moves
  std::size_t moves_refused_on_the_way = 0;  // reached stances whose path did not hold
};

// Moves the search must not take: (a 3-configuration's code, encode(configuration,
// hold_count), the hold taken from it, an index). The plans the dynamic model repairs
// refuse the moves that failed in MuJoCo (experiments/performed_plan).
using RefusedMoves = std::set<std::pair<std::uint64_t, int>>;

Plan shortest_plan(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
                   const PlanParameters& search = {}, const RefusedMoves& refused = {});

}  // namespace crux
