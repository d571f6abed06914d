#pragma once
// Which physics decides whether a reached stance counts (physics.model; docs/MODEL.md,
// choice C26; docs/PHYSICS.md), and the static model's contact and strength parameters.

#include "common/enum_names.hpp"
#include "physics/strength_profile.hpp"

namespace crux {

// kinematic: the paper's, IK alone decides; static: each stance must also hold still;
// dynamic: the static model's stances, and each move of a plan performed in MuJoCo
// (crux plan and crux perform only: experiments/performed_plan).
enum class PhysicsModel { Kinematic, Static, Dynamic };
template <>
struct EnumNames<PhysicsModel> {
  static constexpr std::array<EnumName<PhysicsModel>, 3> entries{
      {{PhysicsModel::Kinematic, "kinematic"}, {PhysicsModel::Static, "static"}, {PhysicsModel::Dynamic, "dynamic"}}};
};

// Whether each stance must hold still (the static and dynamic models).
inline bool checks_stances(PhysicsModel model) { return model != PhysicsModel::Kinematic; }

struct PhysicsParameters {
  PhysicsModel model = PhysicsModel::Kinematic;  // the paper's, and the default
  // Coulomb's coefficient of every contact (a choice: the paper and the sources are silent).
  double friction = 1.0;
  // The largest normal force of a hand on a hold, newtons: by default the advanced
  // climbers' (physics/strength_profile), else physics.strength's level or physics.grip.
  // Feet are bounded by the legs' joint torques and friction only.
  double grip = kAdvancedClimberGripN;
  // A hold without a support direction in its wall file: a hand hooks its incut lip,
  // which pushes up and this many degrees into the wall (a jug); a foot stands on its
  // top, which pushes straight up the wall.
  double support_angle_deg = 45.0;
};

}  // namespace crux
