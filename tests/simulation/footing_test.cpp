#include "simulation/footing.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include <cmath>

#include "simulation/mjcf_model.hpp"
#include "simulation/mujoco_model.hpp"

namespace crux {
namespace {

// A 70 kg ball whose centre is a foot's grasp point, on the footing of the right foot; it
// translates only, as a foot's sphere that cannot roll.
constexpr const char* kBallOnAFooting = R"(<mujoco>
  <option timestep="0.002" cone="pyramidal" noslip_iterations="10"/>
  <default><geom solref="0.005 1"/></default>
  <worldbody>
    <body name="footing_right_foot" mocap="true" pos="0 0 -100">
      <geom type="box" pos="0 0 -0.01" size="0.04 0.04 0.01" contype="0" conaffinity="4"/>
    </body>
    <body name="ball" pos="0 0 1">
      <joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/><joint type="slide" axis="0 0 1"/>
      <geom type="sphere" size="0.01" mass="70" contype="4" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>)";

TEST(Footing, AFootStandsWhereItTookItsHoldOnAPlaneNormalToTheSupport) {
  MujocoModel model(kBallOnAFooting, "footing");
  mjData* data = mj_makeData(model.get());
  const Footing footing(model.get(), Limb::RightFoot);
  EXPECT_FALSE(footing.taken(data));
  // A slope of 30 degrees: with friction 1 the ball stays where it stood.
  const Eigen::Vector3d support(0.5, 0.0, std::sqrt(3.0) / 2);
  const Eigen::Vector3d grasp_point(0.0, 0.0, 1.0);
  footing.take(data, grasp_point, support);
  EXPECT_TRUE(footing.taken(data));
  for (int step = 0; step < 1000; ++step) mj_step(model.get(), data);
  const Eigen::Vector3d ball = Eigen::Vector3d(data->qpos[0], data->qpos[1], data->qpos[2]) + grasp_point;
  const Eigen::Vector3d moved = ball - grasp_point;
  // MuJoCo's soft friction lets it creep (3 mm/s here), far from leaving its hold.
  EXPECT_LT((moved - moved.dot(support) * support).norm(), 0.01) << "it does not slide off down the slope";
  EXPECT_LT(std::abs(moved.dot(support)), 0.01) << "it sinks less than a centimetre into the soft contact";
  footing.release(data);
  EXPECT_FALSE(footing.taken(data));
  for (int step = 0; step < 100; ++step) mj_step(model.get(), data);
  EXPECT_LT(data->qpos[2], -0.1) << "without its footing it falls";
  mj_deleteData(data);
}

TEST(Footing, AModelWithoutTheFootingIsRefused) {
  const MujocoModel model(kBallOnAFooting, "footing");
  EXPECT_THROW(Footing(model.get(), Limb::LeftFoot), std::invalid_argument);
}

}  // namespace
}  // namespace crux
