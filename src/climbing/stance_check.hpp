#pragma once
// The static model (physics.model = "static"; docs/MODEL.md, choice C26; docs/PHYSICS.md):
// a posture the IK reached (with the body kept out of the wall) counts only if it can be
// held still twice over, as Bretl's planner checks: on its four holds, and on the three
// left when the next limb to move lets go. Each hold is a point contact
// (physics/contact_model) in the wall's gravity (wall/incline); the forces and the joint
// torques come from one linear program (physics/static_equilibrium) per check.

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "configurations/hold_configuration.hpp"
#include "physics/physics_model.hpp"
#include "physics/static_equilibrium.hpp"
#include "wall/wall.hpp"

namespace crux {

// What holds a posture still on its holds, to draw it (crux view; docs/OUTPUTS.md).
struct StanceLoads {
  bool balanced = false;  // an equilibrium exists within the contacts' limits
  double effort = 0.0;    // +infinity when not balanced
  std::array<bool, kLimbCount> held{};
  // The force of each held hold on its limb, newtons, wall coordinates.
  std::array<Eigen::Vector3d, kLimbCount> forces{};
  // Each bounded joint's torque over its limit in the torque's direction, by coordinate
  // of G (empty when not balanced).
  std::vector<std::pair<int, double>> joint_ratios;
};

// Whether postures hold still on their holds, for one wall: one linear program, reused.
class StanceCheck {
 public:
  StanceCheck(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics);

  // The stance's effort: the larger of the efforts on the four holds of `complete` and
  // on the three left once `next_to_move` lets go (+infinity when either cannot
  // balance), which is the three-hold effort. The posture holds still when it is at most 1.
  double effort(const Posture& posture, const HoldConfiguration& complete, Limb next_to_move);
  // Whether that effort is at most 1, from the cheaper program that does not minimise it
  // (StaticEquilibrium::holds_within_strength, whose note on warm starts applies).
  bool holds_still(const Posture& posture, const HoldConfiguration& complete, Limb next_to_move);

  // The program's warm-start basis, for a run's checkpoint (StaticEquilibrium::save_basis).
  void save_state(CheckpointWriter& out) const { equilibrium_.save_basis(out); }
  void load_state(CheckpointReader& in) { equilibrium_.load_basis(in); }

  // The stance on the holds of `configuration` (kFree limbs hold nothing), and its result.
  const StaticEquilibriumResult& solve(const Posture& posture, const HoldConfiguration& configuration);

  // The same stance's forces and torque ratios.
  StanceLoads loads(const Posture& posture, const HoldConfiguration& configuration);

 private:
  const BodyModel& model_;
  const Wall& wall_;
  PhysicsParameters physics_;
  Eigen::Vector3d gravity_;
  BodyData data_;
  StrengthProfile strength_;
  StaticEquilibrium equilibrium_;
  std::array<PointContact, kLimbCount> contacts_;

  // The contacts of the holds of `configuration`, in contacts_.
  std::span<const PointContact> contacts(const HoldConfiguration& configuration);
};

// The stance check of `physics`: the static model's, none under the kinematic model,
// where a reached posture counts as it is. Where crux reads the physics model to check
// stances: the reacher, the replay and the views all ask this.
std::optional<StanceCheck> stance_check_for(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics);

}  // namespace crux
