#include "simulation/joint_servo.hpp"

#include <algorithm>
#include <cmath>

namespace crux {

ServoGain servo_gain(const JointStrength& limit, const ServoParameters& servo) {
  const double weaker = std::min(limit.positive, limit.negative);
  const double torque = std::isfinite(weaker) ? weaker : kUnmeasuredServoTorque;
  const double kp = torque / servo.saturation_angle;
  return {kp, kp * servo.damping_time};
}

}  // namespace crux
