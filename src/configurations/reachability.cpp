#include "configurations/reachability.hpp"

namespace crux {

ReachTarget reach_target(const BodyModel& model, const Wall& wall, const HoldConfiguration& complete,
                         const RootTargetParameters& root) {
  ReachTarget target;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const Hold& hold = wall.holds[complete.holds[limb]];
    target.hold_centres[limb] = hold.position;
    target.hold_radii[limb] = hold.radius;
  }
  target.root = root_target(model, target.hold_centres, root);
  return target;
}

HoldConfiguration start_configuration(const Wall& wall) {
  HoldConfiguration start;
  start.holds = wall.start;
  return start;
}

Posture start_guess(const BodyModel& model, const Wall& wall, const RootTargetParameters& root) {
  return standing_posture(reach_target(model, wall, start_configuration(wall), root).root);
}

IkResult solve_start(const BodyModel& model, BodyData& data, const Wall& wall,
                     const ReachabilityParameters& parameters) {
  const ReachTarget target = reach_target(model, wall, start_configuration(wall), parameters.root);
  return solve_ik(model, data, start_guess(model, wall, parameters.root), target, parameters.ik);
}

}  // namespace crux
