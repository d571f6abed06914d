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

IkResult solve_start(const BodyModel& model, BodyData& data, const Wall& wall, const IkSettings& settings,
                     const RootTargetParameters& root) {
  const ReachTarget target = reach_target(model, wall, start_configuration(wall), root);
  return solve_ik(model, data, standing_posture(target.root), target, settings);
}

}  // namespace crux
