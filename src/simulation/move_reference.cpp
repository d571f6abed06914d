#include "simulation/move_reference.hpp"

#include <cmath>
#include <numbers>

#include "body/kinematics.hpp"
#include "configurations/held_contacts.hpp"
#include "ik/ik_solver.hpp"
#include "physics/least_squares_holding.hpp"
#include "wall/incline.hpp"

namespace crux {

namespace {

// A sample moved out of the wall keeps each grasp point within this of where it was, m,
// and its root within the other.
constexpr double kClearanceGraspTolerance = 0.01;
constexpr double kClearanceRootTolerance = 0.2;

}  // namespace

MoveReferences::MoveReferences(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                               const ReachabilityParameters& reach, int samples, double force_margin, double lift)
    : model_(model),
      wall_(wall),
      physics_(physics),
      force_margin_(force_margin),
      lift_(lift),
      samples_(samples),
      gravity_(wall_to_world(wall.incline_deg).transpose() * kStandardGravity),
      data_(model),
      equilibrium_(model, published_strength_profile(model, model.total_mass, model.stature)) {
  clearance_ik_ = reach.ik;
  clearance_ik_.solver = IkSolverKind::Fast;
  clearance_ik_.wall = WallRule::Avoid;
  clearance_ik_.rule_out_beyond_reach = false;
  clearance_ik_.tolerances = {kClearanceGraspTolerance, kClearanceRootTolerance};
}

HoldingTorques MoveReferences::holding(const Posture& posture, const HoldConfiguration& holds) {
  // The least-effort forces lie on the friction pyramid's faces and at the grip, where the
  // smallest error in the simulated posture takes them out: aim inside, by force_margin,
  // where the stance allows it.
  for (const double margin : {force_margin_, force_margin_ / 2, force_margin_ / 4, 0.0}) {
    PhysicsParameters within = physics_;
    within.friction *= 1.0 - margin;
    within.grip *= 1.0 - margin;
    const StaticEquilibriumResult& result =
        equilibrium_.solve(data_, posture, held_contacts(wall_, holds, within, contacts_), gravity_);
    if (result.balanced) return {result.joint_torques, true};
  }
  return {least_squares_holding(model_, data_, posture, held_contacts(wall_, holds, physics_, contacts_), gravity_)
              .joint_torques,
          false};
}

void MoveReferences::lifted_path(const Posture& from, const Posture& to, Limb limb, std::vector<Posture>& samples) {
  std::array<Eigen::Vector3d, kLimbCount> start, end;
  forward_kinematics(model_, data_, from);
  for (int l = 0; l < kLimbCount; ++l) start[l] = data_.points[operational_point(l)];
  forward_kinematics(model_, data_, to);
  for (int l = 0; l < kLimbCount; ++l) end[l] = data_.points[operational_point(l)];
  samples.clear();
  Posture previous = from;
  for (int s = 1; s < samples_; ++s) {
    const double fraction = static_cast<double>(s) / samples_;
    ReachTarget target;
    for (int l = 0; l < kLimbCount; ++l) target.hold_centres[l] = (1.0 - fraction) * start[l] + fraction * end[l];
    target.hold_centres[static_cast<int>(limb)].x() -= lift_ * std::sin(std::numbers::pi * fraction);
    target.hold_radii.fill(0.0);
    target.root = (1.0 - fraction) * from.head<kRootDof>() + fraction * to.head<kRootDof>();
    const IkResult solved = solve_ik(model_, data_, previous, target, clearance_ik_);
    previous = solved.reached ? solved.posture : (1.0 - fraction) * from + fraction * to;
    samples.push_back(previous);
  }
  samples.push_back(to);
}

MoveReference MoveReferences::move(const Posture& from, const Posture& to, const HoldConfiguration& before,
                                   int left_hold, int hold) {
  MoveReference reference;
  reference.limb = before.free_limb();
  reference.hold = hold;
  reference.kept = before;
  reference.left_hold = left_hold;
  reference.loaded_feed_forward = holding(from, before.with(reference.limb, left_hold)).torques;
  reference.unloaded_feed_forward = holding(from, before).torques;
  const HoldConfiguration complete = before.with(reference.limb, hold);
  lifted_path(from, to, reference.limb, reference.samples);
  for (const Posture& sample : reference.samples) reference.feed_forward.push_back(holding(sample, before).torques);
  reference.arrived_feed_forward = holding(to, complete).torques;
  return reference;
}

}  // namespace crux
