#include "climbing/stance_check.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "configurations/held_contacts.hpp"
#include "physics/strength_profile.hpp"
#include "wall/incline.hpp"

namespace crux {

namespace {

// The static model scales the body's strength by its mass and stature (the loader
// refuses a body without mass): a body without the head-top frame cannot be checked.
const BodyModel& weighed_body(const BodyModel& model) {
  if (!(model.stature > 0.0)) {
    throw InputError(model.source, fmt::format("the static model (physics.model) needs the body's stature, from its "
                                               "'{}' frame, and the body has none",
                                               model.head_top_frame));
  }
  return model;
}

}  // namespace

StanceCheck::StanceCheck(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics)
    : model_(weighed_body(model)),
      wall_(wall),
      physics_(physics),
      gravity_(wall_to_world(wall.incline_deg).transpose() * kStandardGravity),
      data_(model),
      strength_(published_strength_profile(model, model.total_mass, model.stature)),
      equilibrium_(model, strength_) {}

std::span<const PointContact> StanceCheck::contacts(const HoldConfiguration& configuration) {
  return held_contacts(wall_, configuration, physics_, contacts_);
}

const StaticEquilibriumResult& StanceCheck::solve(const Posture& posture, const HoldConfiguration& configuration) {
  return equilibrium_.solve(data_, posture, contacts(configuration), gravity_);
}

double StanceCheck::effort(const Posture& posture, const HoldConfiguration& complete, Limb next_to_move) {
  // One program, not two: the four-hold program is the three-hold one with the fourth
  // limb's forces freed from zero, so any equilibrium on three holds is one on four at the
  // same effort, and the four-hold effort is never larger (docs/PHYSICS.md, "One program
  // per stance").
  return solve(posture, complete.with(next_to_move, kFree)).effort;
}

bool StanceCheck::holds_still(const Posture& posture, const HoldConfiguration& complete, Limb next_to_move) {
  // The three-hold program decides, as for effort.
  return equilibrium_.holds_within_strength(data_, posture, contacts(complete.with(next_to_move, kFree)), gravity_);
}

StanceLoads StanceCheck::loads(const Posture& posture, const HoldConfiguration& configuration) {
  const StaticEquilibriumResult& result = solve(posture, configuration);
  StanceLoads loads;
  loads.balanced = result.balanced;
  loads.effort = result.effort;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    loads.held[limb] = configuration.holds[limb] != kFree;
    loads.forces[limb] = result.contact_forces[limb];
  }
  if (!result.balanced) return loads;
  for (int j = kRootDof; j < kConfigurationDof; ++j) {
    const double torque = result.joint_torques[j];
    const double limit = torque >= 0.0 ? strength_.joints[j].positive : strength_.joints[j].negative;
    if (std::isfinite(limit)) loads.joint_ratios.emplace_back(j, std::abs(torque) / limit);
  }
  return loads;
}

std::optional<StanceCheck> stance_check_for(const BodyModel& model, const Wall& wall,
                                            const PhysicsParameters& physics) {
  if (physics.model == PhysicsModel::Kinematic) return std::nullopt;
  return std::optional<StanceCheck>(std::in_place, model, wall, physics);
}

}  // namespace crux
