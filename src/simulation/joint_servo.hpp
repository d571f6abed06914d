#pragma once
// Each revolute joint's motor in MuJoCo is a servo (docs/PHYSICS.md, "Performed in
// MuJoCo"): its torque is
//   tau = clamp(tau_ff + kp (q_ref - q) + kv (qd_ref - qd), -negative limit, positive limit),
// a feed-forward torque plus joint-space feedback, clamped by the motor at the joint's
// torque limit. MuJoCo's general actuator writes it with gain kp on the control and the
// bias -kp q - kv qd, so that its implicit integrator takes the damping implicitly (a
// wrist's kv over its inertia is far beyond what explicit steps of 2 ms keep stable); the
// control then carries q_ref and the feed-forward together.

#include "physics/strength_profile.hpp"

namespace crux {

struct ServoParameters {
  // The angle error, radians, at which the proportional term alone reaches the joint's
  // torque limit: kp = limit / saturation_angle.
  double saturation_angle = 0.2;
  // kv = kp * damping_time, seconds.
  double damping_time = 0.05;
};

struct ServoGain {
  double kp = 0.0;  // N m / rad
  double kv = 0.0;  // N m s / rad
};

// A joint without a finite limit (a body no source measures) is stiffened as if its limit
// were kUnmeasuredServoTorque.
inline constexpr double kUnmeasuredServoTorque = 1000.0;  // N m
ServoGain servo_gain(const JointStrength& limit, const ServoParameters& servo);

// The control that gives tau above for the target angle and rate and the feed-forward.
inline double servo_control(const ServoGain& gain, double target_angle, double target_rate, double feed_forward) {
  return target_angle + (feed_forward + gain.kv * target_rate) / gain.kp;
}

}  // namespace crux
