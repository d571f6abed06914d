#pragma once
// What holds each stance of a recorded climb under the static model (climbing/stance_check),
// for the report and its replay to show: the forces and joint torque ratios of each stance
// on its four holds, and its effort there and on the three left when the next limb lets go.

#include <optional>
#include <vector>

#include "climbing/stance_check.hpp"
#include "experiments/episode_replay.hpp"

namespace crux {

struct ClimbStances {
  // One per posture of the climb, the start first, each on its climb_configurations
  // holds; the effort is +infinity where no forces balance the stance.
  std::vector<StanceLoads> loads;
  std::vector<double> effort_on_four_holds;
  // Posture k was reached by the k-th move, of the limb (k - 1) mod 4 in the cycle, so the
  // next to let go is k mod 4; the start's is the right hand.
  std::vector<double> effort_on_three_holds;
};

// None under the kinematic model (stance_check_for). The loads come from one program
// solved stance after stance and the efforts from another, each in the climb's order, so
// that a stance's numbers do not depend on which of the two questions came first.
std::optional<ClimbStances> climb_stances(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                          const PhysicsParameters& physics);

}  // namespace crux
