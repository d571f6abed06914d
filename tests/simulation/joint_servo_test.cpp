#include "simulation/joint_servo.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include <limits>

#include "simulation/mujoco_model.hpp"

namespace crux {
namespace {

TEST(JointServo, GainsScaleWithTheWeakerLimit) {
  const ServoParameters servo{0.2, 0.05};
  const ServoGain gain = servo_gain({80.0, 60.0}, servo);
  EXPECT_DOUBLE_EQ(gain.kp, 300.0) << "60 N m at 0.2 rad";
  EXPECT_DOUBLE_EQ(gain.kv, 15.0);
  const double unbounded = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(servo_gain({unbounded, unbounded}, servo).kp, kUnmeasuredServoTorque / 0.2);
}

// MuJoCo's general actuator with gain kp and bias (0, -kp, -kv), fed servo_control, exerts
// tau_ff + kp (q_ref - q) + kv (qd_ref - qd), clamped at its force range.
TEST(JointServo, MujocosActuatorExertsTheServoLawClampedAtTheLimit) {
  constexpr const char* kHinge = R"(<mujoco>
  <worldbody><body><joint name="j" type="hinge" axis="0 1 0"/><geom type="sphere" size="0.1" mass="1"/></body></worldbody>
  <actuator><general joint="j" gaintype="fixed" gainprm="300" biastype="affine" biasprm="0 -300 -15"
    forcelimited="true" forcerange="-60 80"/></actuator>
</mujoco>)";
  MujocoModel model(kHinge, "hinge");
  mjData* data = mj_makeData(model.get());
  const ServoGain gain{300.0, 15.0};
  data->qpos[0] = 0.1;
  data->qvel[0] = -0.4;
  const auto force_for = [&](double angle, double rate, double feed_forward) {
    data->ctrl[0] = servo_control(gain, angle, rate, feed_forward);
    mj_forward(model.get(), data);
    return data->actuator_force[0];
  };
  EXPECT_NEAR(force_for(0.15, 0.2, 5.0), 5.0 + 300.0 * 0.05 + 15.0 * 0.6, 1e-9);
  EXPECT_NEAR(force_for(0.1, -0.4, -12.0), -12.0, 1e-9) << "on its reference: the feed-forward alone";
  EXPECT_NEAR(force_for(1.0, 0.0, 0.0), 80.0, 1e-9) << "clamped at the positive limit";
  EXPECT_NEAR(force_for(-1.0, 0.0, 0.0), -60.0, 1e-9) << "and at the negative one";
  mj_deleteData(data);
}

}  // namespace
}  // namespace crux
