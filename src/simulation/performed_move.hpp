#pragma once
// One move performed in MuJoCo (docs/PHYSICS.md, "Performed in MuJoCo"): the free limb
// leaves its hold and follows the IK's path to the next while the other three stay on
// theirs, every joint driven by its servo (simulation/joint_servo) towards the path's
// angles with the static model's holding torques as feed-forward. Nothing else acts on
// the body but gravity, the contacts, the grasps and the joints' range limits. The move
// starts from wherever the last one left the body.

#include <vector>

#include "body/gravity_forces.hpp"
#include "common/enum_names.hpp"
#include "simulation/climb_trajectory.hpp"
#include "simulation/simulated_climber.hpp"

namespace crux {

// Why a move failed; None when it was performed.
// Unstable: MuJoCo found a non-finite acceleration (and reset its state), no outcome of
// the move's physics.
enum class MoveFailure { None, GripExceeded, HandSlipped, FootSlipped, TorqueSaturated, HitWall, TimedOut, Unstable };
template <>
struct EnumNames<MoveFailure> {
  static constexpr std::array<EnumName<MoveFailure>, 8> entries{{{MoveFailure::None, "none"},
                                                                 {MoveFailure::GripExceeded, "grip_exceeded"},
                                                                 {MoveFailure::HandSlipped, "hand_slipped"},
                                                                 {MoveFailure::FootSlipped, "foot_slipped"},
                                                                 {MoveFailure::TorqueSaturated, "torque_saturated"},
                                                                 {MoveFailure::HitWall, "hit_wall"},
                                                                 {MoveFailure::TimedOut, "timed_out"},
                                                                 {MoveFailure::Unstable, "unstable"}}};
};

struct MoveParameters {
  // A hand lets go when its force has stayed outside its limits (the grip, the friction
  // pyramid) for this long, s: shorter excursions are slips of a few millimetres that the
  // fingers take up.
  double slip_time_s = 0.05;
  // A hand's force within this of its limits, N, is held: the fingers' own hold on a jug,
  // and the last newtons of a hand being unweighted, whose direction is anyone's.
  double grasp_tolerance_n = 10.0;
  // Before a limb lets go, the time over which its hold is unweighted, s.
  double unweight_time_s = 0.3;
  // The reference's pace: its duration is the largest joint excursion summed along the
  // path over this speed, rad/s, and at least min_duration_s; a smoothstep in time, so it
  // starts and ends at rest.
  double joint_speed = 0.5;
  double min_duration_s = 0.5;
  // A limb is on a hold, as the IK's termination test has it, when its grasp sphere of this
  // radius, m, meets the hold's sphere (ik.grasp_radius): the free limb has arrived when it
  // is, a held foot has slipped when it is no longer.
  double grasp_radius = 0.04;
  // Held still: every velocity of the body (rad/s, and m/s for the root) below
  // still_speed for still_time_s.
  double still_speed = 0.05;
  double still_time_s = 0.25;
  // After the reference ends, the time allowed to arrive and hold still.
  double settle_time_s = 2.0;
  // The body has hit the wall when the wall pushes its segments with more than this share
  // of its weight (a knee that brushes the wall is no support).
  double wall_push_share = 0.05;
  // A move that times out failed for its torques when some servo was at its limit in at
  // least this share of its steps.
  double saturated_share = 0.1;
};

// What the servos follow: the IK path's postures, the first the planned stance the move
// leaves, the last the one it arrives at, with each one's holding torques on the three
// kept holds, and the arrived stance's on all four.
struct MoveReference {
  Limb limb = Limb::RightHand;
  int hold = -1;                               // the hold it moves to (index)
  HoldConfiguration kept;                      // the three held during the move
  int left_hold = kFree;                       // the hold it lets go of (index), kFree when it held none
  std::vector<Posture> samples;                // the IK path (at least one: the arrived stance)
  std::vector<GeneralisedForce> feed_forward;  // per sample
  GeneralisedForce arrived_feed_forward = GeneralisedForce::Zero();
  // The stance the move leaves, on its four holds and on the three kept.
  GeneralisedForce loaded_feed_forward = GeneralisedForce::Zero();
  GeneralisedForce unloaded_feed_forward = GeneralisedForce::Zero();
};

struct MoveOutcome {
  MoveFailure failure = MoveFailure::None;
  bool performed() const { return failure == MoveFailure::None; }
  double seconds = 0.0;  // simulated, until performed or failed
  int steps = 0;
  double max_torque_ratio = 0.0;   // largest |servo torque| / its limit in that direction
  double peak_range_torque = 0.0;  // largest joint range-limit torque, N m
  double grasp_error_m = 0.0;      // the free limb's grasp point to its hold, at the end
  double joint_error_rad = 0.0;    // largest |angle - reference| at the end
  double max_root_turn_rad = 0.0;  // the root's largest rotation from its orientation on the wall
  double peak_wall_push_n = 0.0;   // the wall's largest push on the segments
};

// Performs `reference` from the climber's present state: the limb's hold unweighted, the
// path followed, the new hold taken where the limb comes to rest on it. `recorder`, when
// given, samples each step.
MoveOutcome perform_move(SimulatedClimber& climber, const MoveReference& reference, const MoveParameters& parameters,
                         TrajectoryRecorder* recorder = nullptr);

// Holds the climber still on `holds` with `feed_forward` towards `posture`, for at most
// `seconds`: the outcome of a move that goes nowhere (the start settling, a stance's test).
MoveOutcome hold_still(SimulatedClimber& climber, const Posture& posture, const HoldConfiguration& holds,
                       const GeneralisedForce& feed_forward, double seconds, const MoveParameters& parameters,
                       TrajectoryRecorder* recorder = nullptr);

}  // namespace crux
