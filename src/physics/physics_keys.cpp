#include "physics/physics_keys.hpp"

#include "physics/strength_profile.hpp"

namespace crux {

namespace {

// physics.strength: a climbing level's name, or empty (unset).
const ChoiceType kClimbingLevelChoice{[](const void* target) { return *static_cast<const std::string*>(target); },
                                      [](void* target, std::string_view text) {
                                        if (!find_climbing_level(text)) return false;
                                        *static_cast<std::string*>(target) = std::string(text);
                                        return true;
                                      },
                                      [] { return climbing_level_descriptions(); }};
ChoiceTarget<false> level_choice(std::string* target) { return {target, &kClimbingLevelChoice}; }
ChoiceTarget<true> level_choice(const std::string* target) { return {target, &kClimbingLevelChoice}; }

template <typename Parameters, typename Level>
void declare_physics_keys(FieldsFor<Parameters>& keys, Parameters& physics, Level& strength_level) {
  keys.insert(
      keys.end(),
      {
          {"physics.model",
           "kinematic (the paper's: IK alone decides), static (the body kept out of the wall and each stance held "
           "still on its holds, within friction, grip and joint torque limits; docs/PHYSICS.md) or dynamic (crux plan "
           "and crux perform: static stances, and each move of the plan performed in MuJoCo)",
           choice_of(&physics.model)},
          // Rubber on rock measures about 1. CLP's least efforts stay right up to 1e6 and go
          // wrong from 1e7 (larger than at 10, which more friction cannot make them); from
          // 1e10 fewer stances hold than at 10, and from about 1e14 CLP gives up or runs for
          // minutes (docs/RELIABILITY.md).
          {"physics.friction", "Static model: Coulomb friction coefficient of every contact", &physics.friction, "",
           closed_range(0, 10, "ten times rubber on rock; the equilibrium program stays well conditioned")},
          {"physics.strength",
           "Static model: a climbing level whose published grip sets physics.grip (docs/MODEL.md); an explicit "
           "physics.grip overrides it",
           level_choice(&strength_level)},
          {"physics.grip",
           "Static model: largest normal force of a hand on a hold",
           &physics.grip,
           "N",
           {.min = 0, .max = 10000, .min_open = true, .why = "17 times elite climbers' mean finger force"}},
          {"physics.support_angle",
           "Static model: a hold without a support direction pushes a hand up and this far into the wall (a jug's "
           "incut lip)",
           &physics.support_angle_deg, "degrees", closed_range(-90, 90)},
      });
}

}  // namespace

void physics_keys(std::vector<ConfigField>& keys, PhysicsParameters& physics, std::string& strength_level) {
  declare_physics_keys(keys, physics, strength_level);
}
void physics_keys(std::vector<ConstConfigField>& keys, const PhysicsParameters& physics,
                  const std::string& strength_level) {
  declare_physics_keys(keys, physics, strength_level);
}

}  // namespace crux
