#pragma once
// The climber on its wall as a MuJoCo model (MJCF, for MuJoCo 2.2.2; docs/PHYSICS.md,
// "Performed in MuJoCo"). The body is the one crux reads from its URDF: one MuJoCo body
// per joint of crux's model, with the same masses, inertias, joint axes and limits, the
// URDF's visual primitives as its geoms; but its root is a free joint, which nothing holds
// or drives. One motor per revolute joint, bounded by the joint's torque limit in each
// direction. The wall plane and the holds stand at the wall's incline under gravity along
// -z. Each hand has a grasp constraint (an equality `connect` of its grasp point to the
// world), off until the hand takes a hold; each foot has a footing, a mocap box whose top
// face it stands on through frictional contact, placed where it takes a hold with the
// hold's support direction as its normal (simulation/footing).

#include <string>

#include "body/body_model.hpp"
#include "physics/physics_model.hpp"
#include "physics/strength_profile.hpp"
#include "simulation/joint_servo.hpp"
#include "wall/wall.hpp"

namespace crux {

// The names the model gives what a controller reads and drives: the free root joint and
// its body; each revolute joint's body, hinge and motor share the joint's name.
inline constexpr const char* kMjcfRoot = "root";
// How deep a segment goes into the wall before it touches MuJoCo's wall plane, m: crux's
// skin margin (body/wall_penetration's kWallSkinMargin, 1 cm) and as much again for the
// servos' tracking error.
inline constexpr double kMjcfWallDepth = 0.02;
// The radius of the sphere through which a foot stands on a hold, m.
inline constexpr double kFootContactRadius = 0.01;
// The grasp constraint of a hand: "grasp_right_hand", "grasp_left_hand".
std::string mjcf_grasp_name(Limb hand);
// The body of the hold with this id: "hold_7".
std::string mjcf_hold_name(int hold_id);
// The mocap body of a foot's footing: "footing_right_foot".
std::string mjcf_footing_name(Limb foot);
// Where a footing waits while its foot holds nothing: far below the wall, world coordinates.
inline const Eigen::Vector3d kParkedFooting{0.0, 0.0, -100.0};

// Every revolute joint's motor range, N m each way: the published limit where a source
// gives one (`published`, physics/strength_profile). A joint no source measures takes, in
// both directions, the smaller of the two limits of the measured joint at its site (its
// name without its side and its last word: lumbar_lateral takes lumbar_flexion's); where
// no joint of its site is measured (the neck), the smallest limit measured in the body.
// Infinite nowhere, so that every joint counts in a torque ratio, unless no joint of the
// body is measured at all.
StrengthProfile motor_limits(const BodyModel& model, const StrengthProfile& published);

// The MJCF text: the climber at `start` (a posture in wall coordinates; also the keyframe
// "start"), on `wall`, with the friction and the holds' support directions of `physics`,
// and the motors' `limits`. Self-contained: MuJoCo loads it as written, with no other
// file. A grasp's limit (physics.grip) is no MJCF attribute: the simulation reads the
// constraint's force each step.
std::string mjcf_text(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                      const StrengthProfile& limits, const Posture& start, const ServoParameters& servo = {});

}  // namespace crux
