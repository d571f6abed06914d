#pragma once
// How much torque each actuated joint can exert, one limit per direction (docs/MODEL.md,
// "Strength"): the published maximal isometric torques crux's static equilibrium bounds
// the joints by.

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "body/body_model.hpp"

namespace crux {

// Newton-metres about the joint's axis. `positive` bounds a torque towards the joint's
// positive angle (flexion, abduction, internal rotation, pronation, dorsiflexion, radial
// deviation: docs/MODEL.md, "Sign convention"), `negative` one towards its negative angle.
// +infinity where no source gives the limit: the joint is then not bounded.
struct JointStrength {
  double positive = std::numeric_limits<double>::infinity();
  double negative = std::numeric_limits<double>::infinity();
};

struct StrengthProfile {
  // One per coordinate of G; the root's translations are unactuated and never read.
  std::array<JointStrength, kConfigurationDof> joints;
};

// crux's human of `body_mass_kg` and `stature_m`: Anderson, Madigan and Nussbaum (2007) for
// hip, knee and ankle (young men, their Table 3's c1 times body mass, stature and g), and
// the whole-body "Gymnast" set of RBDL's torque-muscle addon for the shoulder, elbow,
// forearm, wrist and lumbar flexion, scaled from its subject (69.6 kg, 1.732 m) by body
// mass times stature. Joints are matched by name, without their right_/left_ prefix; a
// joint neither source measures (lumbar bending and twisting, the neck, hip abduction and
// rotation, ankle inversion) is left unbounded.
StrengthProfile published_strength_profile(const BodyModel& model, double body_mass_kg, double stature_m);

// The largest normal force of one hand on a hold that a study measured on climbers of one
// level, newtons (physics.strength; docs/MODEL.md, "Grip and push limits"). Only the grip
// varies with the level: no source read gives joint torques by climbing level.
struct ClimbingLevel {
  std::string_view name;
  double grip_n;
};

// Amca et al. (2012)'s advanced climbers: crux's grip unless physics.strength names a level.
inline constexpr double kAdvancedClimberGripN = 575.7;

// Every named level, from the lowest climbing level to the highest.
std::span<const ClimbingLevel> climbing_levels();
std::optional<ClimbingLevel> find_climbing_level(std::string_view name);
// "intermediate (383.0 N), advanced (575.7 N) or elite (563.1 N)", for help and errors.
std::string climbing_level_descriptions();

}  // namespace crux
