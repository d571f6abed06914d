#pragma once
// The planners' small cases (experiments/shortest_plan, experiments/climb_graph).

#include "climbing/climbing_mdp.hpp"
#include "wall/random_wall.hpp"

namespace crux::testing {

// Random wall 10 with its finish at 1.4 m, which a few moves reach: cheap enough to plan,
// or to explore whole, under the sanitizers.
inline Wall low_finish_wall() {
  Wall wall = generate_random_wall(10);
  wall.finish_height = 1.4;
  return wall;
}

// The static model's rules, with the body kept out of the wall as that model requires.
inline ClimbingParameters static_rules() {
  ClimbingParameters parameters;
  parameters.physics.model = PhysicsModel::Static;
  parameters.reachability.ik.wall = WallRule::Avoid;
  return parameters;
}

}  // namespace crux::testing
