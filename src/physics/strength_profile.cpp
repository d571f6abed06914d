#include "physics/strength_profile.hpp"

#include <algorithm>
#include <string_view>

#include <fmt/format.h>

namespace crux {
namespace {

// Anderson, D. E., Madigan, M. L., Nussbaum, M. A. (2007). Maximum voluntary joint torque as
// a function of joint angle and angular velocity: model development and application to the
// lower limb. J. Biomech. 40(14), 3105-3113, Table 3, young (18-25) men: c1, the peak
// isometric torque divided by body mass x stature x g.
constexpr double kAndersonGravity = 9.81;
// Millard, M. et al., RBDL's torque-muscle addon (addons/muscle/Millard2016TorqueMuscle.cc,
// the GymnastWholeBody table): maximal isometric torques of one elite male gymnast from
// Jackson's thesis (shoulder flexion and extension, wrist flexion and extension), Kentel et
// al. scaled to him (shoulder horizontal adduction and abduction, rotations, elbow,
// pronation, supination, wrist deviation), Raschke et al. and Beimborn et al. (lumbar).
constexpr double kGymnastMassKg = 69.6, kGymnastStatureM = 1.732;

enum class StrengthSource { Anderson2007, Gymnast };

struct PublishedStrength {
  std::string_view joint;  // crux's joint name without right_ / left_
  StrengthSource source;
  // Towards the joint's positive angle, then its negative angle: Anderson's c1 or the
  // gymnast's newton-metres, with the source's direction named.
  double positive, negative;
};

constexpr PublishedStrength kPublishedStrengths[] = {
    // hip flexion 0.113, extension 0.161
    {"hip_flexion", StrengthSource::Anderson2007, 0.113, 0.161},
    // knee flexion 0.087, extension 0.163
    {"knee_flexion", StrengthSource::Anderson2007, 0.087, 0.163},
    // ankle: crux's positive is dorsiflexion (Anderson's "flexion", 0.033), its negative
    // plantar flexion (Anderson's "extension", 0.095)
    {"ankle_flexion", StrengthSource::Anderson2007, 0.033, 0.095},
    // lumbar flexion 211.65, extension 687.864
    {"lumbar_flexion", StrengthSource::Gymnast, 211.65, 687.864},
    // shoulder flexion 91.1388, extension 127.401
    {"shoulder_flexion", StrengthSource::Gymnast, 91.1388, 127.401},
    // The set has no shoulder abduction or adduction: horizontal abduction (94.6839) and
    // horizontal adduction (128.496), the same muscles' moments in the transverse plane,
    // stand in for them (docs/MODEL.md, "Strength", says so).
    {"shoulder_abduction", StrengthSource::Gymnast, 94.6839, 128.496},
    // internal rotation 50.522, external rotation 43.5837
    {"shoulder_rotation", StrengthSource::Gymnast, 50.522, 43.5837},
    // elbow flexion 101.384, extension 69.8728
    {"elbow_flexion", StrengthSource::Gymnast, 101.384, 69.8728},
    // pronation 12.976, supination 13.5361
    {"forearm_pronation", StrengthSource::Gymnast, 12.976, 13.5361},
    // wrist flexion 39.2252, extension 15.5653
    {"wrist_flexion", StrengthSource::Gymnast, 39.2252, 15.5653},
    // radial deviation 23.8345, ulnar deviation 31.4217
    {"wrist_deviation", StrengthSource::Gymnast, 23.8345, 31.4217},
};

// Each level's grip is one study's mean maximal finger force for a group of that level
// (docs/MODEL.md, "Grip and push limits": the grades, the protocols, and why the three do
// not rise with the level). The studies' protocols differ: the levels are not one scale.
constexpr double kKilogramForceN = 9.81;
constexpr ClimbingLevel kClimbingLevels[] = {
    // Grant et al. (2003), J. Sports Sci. 21(8): nine intermediate male rock climbers'
    // maximal voluntary contraction on a climbing-specific finger apparatus, 383 N.
    {"intermediate", 383.0},
    // Amca, Vigouroux, Aritan & Berton (2012), J. Sports Sci. 30(7): ten advanced climbers'
    // largest mean maximal vertical finger force over hold depths and grip techniques.
    {"advanced", kAdvancedClimberGripN},
    // Binney & Cochrane (2003): ten elite British competition climbers (men), maximal
    // isometric crimp grip 57.4 kg.
    {"elite", 57.4 * kKilogramForceN},
};

std::string_view without_side(std::string_view name) {
  for (const std::string_view side : {"right_", "left_"}) {
    if (name.substr(0, side.size()) == side) return name.substr(side.size());
  }
  return name;
}

}  // namespace

StrengthProfile published_strength_profile(const BodyModel& model, double body_mass_kg, double stature_m) {
  const double anderson_scale = body_mass_kg * stature_m * kAndersonGravity;
  const double gymnast_scale = body_mass_kg * stature_m / (kGymnastMassKg * kGymnastStatureM);
  StrengthProfile profile;
  for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i) {
    const std::string_view joint = without_side(model.joints[i].name);
    for (const PublishedStrength& published : kPublishedStrengths) {
      if (published.joint != joint) continue;
      const double scale = published.source == StrengthSource::Anderson2007 ? anderson_scale : gymnast_scale;
      profile.joints[i] = {published.positive * scale, published.negative * scale};
    }
  }
  return profile;
}

std::span<const ClimbingLevel> climbing_levels() { return kClimbingLevels; }

std::optional<ClimbingLevel> find_climbing_level(std::string_view name) {
  const auto* level = std::find_if(std::begin(kClimbingLevels), std::end(kClimbingLevels),
                                   [&](const ClimbingLevel& l) { return l.name == name; });
  if (level == std::end(kClimbingLevels)) return std::nullopt;
  return *level;
}

std::string climbing_level_descriptions() {
  std::string text;
  const std::span<const ClimbingLevel> levels = climbing_levels();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const char* separator = i == 0 ? "" : i + 1 == levels.size() ? " or " : ", ";
    text += fmt::format("{}{} ({:.1f} N)", separator, levels[i].name, levels[i].grip_n);
  }
  return text;
}

}  // namespace crux
