#pragma once
// What a simulated move follows (simulation/performed_move): postures from one stance to
// the next that the IK solves with the free limb lifted off the wall, and at each the
// holding torques on the three holds kept: the static model's least-effort answer where
// its program balances the posture, which holds the body still by construction; where it
// does not (a kinematic plan's stance, a sample the static model refuses), the
// least-squares contact forces' (physics/least_squares_holding).

#include "configurations/reachability.hpp"
#include "physics/static_equilibrium.hpp"
#include "simulation/performed_move.hpp"

namespace crux {

// Holding torques, and whether the static program balanced the posture.
struct HoldingTorques {
  GeneralisedForce torques = GeneralisedForce::Zero();
  bool balanced = false;
};

class MoveReferences {
 public:
  MoveReferences(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                 const ReachabilityParameters& reach, int samples, double force_margin = 0.5, double lift = 0.1);

  // The next holding torques as the first were found, whatever was solved before: a move
  // tried from rest then does not depend on the moves tried before it.
  void forget_warm_start() { equilibrium_.forget_basis(); }

  // `posture` held on the holds of `holds`.
  HoldingTorques holding(const Posture& posture, const HoldConfiguration& holds);

  // The move of the free limb of `before` (a 3-configuration: the kept holds) from
  // `left_hold` (kFree: none) to `hold`, from the planned stance `from` to the planned `to`.
  MoveReference move(const Posture& from, const Posture& to, const HoldConfiguration& before, int left_hold, int hold);

 private:
  const BodyModel& model_;
  const Wall& wall_;
  PhysicsParameters physics_;
  double force_margin_;
  double lift_;  // m  // the share of friction and grip the feed-forward leaves unused, where it can
  int samples_;
  Eigen::Vector3d gravity_;
  BodyData data_;
  StaticEquilibrium equilibrium_;
  std::array<PointContact, kLimbCount> contacts_{};
  IkParameters clearance_ik_;

  // `samples` postures from `from` to `to` (the last), each solved by the IK (the fast
  // solver, ik.wall = avoid) from the one before: the grasp points go straight from where
  // they are in `from` to where they are in `to`, the free limb's drawn lift x
  // sin(pi x fraction) away from the wall, the root straight too. A sample the IK cannot
  // solve is the postures' linear blend.
  void lifted_path(const Posture& from, const Posture& to, Limb limb, std::vector<Posture>& samples);
};

}  // namespace crux
