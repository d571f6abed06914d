#pragma once
// The start state of random wall 1 under the default parameters, as the tests of the
// numeric observation and of the policy network read it: the candidate holds in
// ascending order, the centre of mass and the free limb's grasp point at the start.

#include <algorithm>
#include <vector>

#include "body/kinematics.hpp"
#include "climbing/climbing_mdp.hpp"
#include "climbing/numeric_observation.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux::testing {

struct ClimbStart {
  const BodyModel& model = human_model();
  Wall wall = generate_random_wall(1);
  ClimbingParameters parameters;
  ClimbingMdp mdp{model, wall, parameters};
  std::vector<int> candidates;
  Eigen::Vector3d centre_of_mass, grasp;

  ClimbStart() {
    for (const ActionCandidate& c : mdp.candidates()) candidates.push_back(c.wall);
    std::sort(candidates.begin(), candidates.end());
    BodyData data(model);
    forward_kinematics(model, data, mdp.posture());
    centre_of_mass = crux::centre_of_mass(model, data);
    grasp = data.points[operational_point(mdp.configuration().free_limb())];
  }

  // The observation's input on wall `w` (this wall, or one changed from it).
  NumericObservationInput input(const Wall& w, double max_span_m) const {
    return {w, mdp.configuration(), mdp.posture(), centre_of_mass, candidates, max_span_m};
  }
};

}  // namespace crux::testing
