#include "simulation/grasp.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include <cmath>

#include "simulation/mujoco_model.hpp"

namespace crux {
namespace {

// A 10 kg body whose hand is its origin, its centre of mass 0.3 m below: it hangs still
// from a grasp at the hand.
constexpr const char* kHangingBody = R"(<mujoco model="hanging">
  <option timestep="0.002" gravity="0 0 -9.81"/>
  <worldbody>
    <body name="climber" pos="0 0 1">
      <freejoint/>
      <geom type="sphere" size="0.1" pos="0 0 -0.3" mass="10"/>
    </body>
  </worldbody>
  <equality><connect name="grasp_right_hand" body1="climber" anchor="0 0 0" active="false"/></equality>
</mujoco>
)";
constexpr double kWeightN = 10 * 9.81;

PointContact hold_pushing(const Eigen::Vector3d& support, double friction, double grip) {
  PointContact contact;
  contact.support_direction = support.normalized();
  contact.friction = friction;
  contact.normal_force_limit = grip;
  return contact;
}

Eigen::Vector3d body_position(const mjData* data) { return {data->qpos[0], data->qpos[1], data->qpos[2]}; }

// Steps `seconds`, letting go as soon as the grasp's force leaves `contact`'s limits;
// returns the first verdict other than held (held if none).
GraspVerdict hang(mjModel* model, mjData* data, const Grasp& grasp, const PointContact& contact, double seconds) {
  GraspVerdict first = GraspVerdict::Held;
  for (int step = 0; step < std::lround(seconds / model->opt.timestep); ++step) {
    mj_step(model, data);
    if (!grasp.taken(model)) continue;
    const GraspVerdict verdict = grasp_verdict(contact, grasp.force(model, data), 1e-9);
    if (verdict != GraspVerdict::Held) {
      grasp.release(model);
      first = verdict;
    }
  }
  return first;
}

TEST(Grasp, HoldsAHangingBodyWithItsWeightUpAndLetsGoBeyondTheGrip) {
  MujocoModel model(kHangingBody, "hanging");
  mjData* data = mj_makeData(model.get());
  const Grasp grasp(model.get(), "grasp_right_hand");
  EXPECT_FALSE(grasp.taken(model.get()));
  grasp.take(model.get(), {0.0, 0.0, 1.0});
  const PointContact jug_top = hold_pushing(Eigen::Vector3d::UnitZ(), 1.0, 575.7);
  EXPECT_EQ(hang(model.get(), data, grasp, jug_top, 2.0), GraspVerdict::Held);
  EXPECT_LT((body_position(data) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-3) << "held where it took the hold";
  const Eigen::Vector3d force = grasp.force(model.get(), data);
  EXPECT_NEAR(force.z(), kWeightN, 0.01 * kWeightN) << "the hold carries the body's weight, upwards";
  EXPECT_LT(force.head<2>().norm(), 0.01 * kWeightN);

  // A grip below the body's weight: the hand lets go at the first step, and the body falls.
  const PointContact weak = hold_pushing(Eigen::Vector3d::UnitZ(), 1.0, 0.5 * kWeightN);
  EXPECT_EQ(hang(model.get(), data, grasp, weak, 0.5), GraspVerdict::GripExceeded);
  EXPECT_FALSE(grasp.taken(model.get()));
  EXPECT_EQ(grasp.force(model.get(), data), Eigen::Vector3d::Zero());
  EXPECT_LT(body_position(data).z(), 1.0 - 0.5 * 0.5 * 9.81 * 0.45 * 0.45) << "in free fall";
  mj_deleteData(data);
}

// A hold that pushes sideways (a vertical face) cannot carry weight with friction 0.5.
TEST(Grasp, LetsGoWhenTheForceLeavesTheFrictionPyramid) {
  MujocoModel model(kHangingBody, "hanging");
  mjData* data = mj_makeData(model.get());
  const Grasp grasp(model.get(), "grasp_right_hand");
  grasp.take(model.get(), {0.0, 0.0, 1.0});
  EXPECT_EQ(hang(model.get(), data, grasp, hold_pushing(Eigen::Vector3d::UnitX(), 0.5, 575.7), 0.1),
            GraspVerdict::OutsideFriction);
  mj_deleteData(data);
}

TEST(Grasp, AModelWithoutTheConstraintIsRefused) {
  const MujocoModel model(kHangingBody, "hanging");
  EXPECT_THROW(Grasp(model.get(), "grasp_left_hand"), std::invalid_argument);
}

TEST(Grasp, VerdictsAreTheGripFirstThenThePyramid) {
  const PointContact top = hold_pushing(Eigen::Vector3d::UnitZ(), 0.5, 100.0);
  EXPECT_EQ(grasp_verdict(top, {0.0, 0.0, 100.0}, 1e-9), GraspVerdict::Held);
  EXPECT_EQ(grasp_verdict(top, {0.0, 0.0, 100.1}, 1e-9), GraspVerdict::GripExceeded);
  EXPECT_EQ(grasp_verdict(top, {80.0, 0.0, 120.0}, 1e-9), GraspVerdict::GripExceeded) << "both: the grip is named";
  EXPECT_EQ(grasp_verdict(top, {30.0, 30.0, 100.0}, 1e-9), GraspVerdict::OutsideFriction);
  EXPECT_EQ(grasp_verdict(top, {0.0, 0.0, -1.0}, 1e-9), GraspVerdict::OutsideFriction) << "a hold cannot pull";
}

}  // namespace
}  // namespace crux
