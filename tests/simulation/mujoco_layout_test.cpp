#include "simulation/mujoco_layout.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "body/kinematics.hpp"
#include "common/random.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/mujoco_model.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

// A posture placed in MuJoCo reads back as itself, and its grasp points are crux's, on a
// wall inclined so that wall and world coordinates differ.
TEST(MujocoLayout, APosturePlacedReadsBackWithCruxsGraspPoints) {
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(2);
  wall.incline_deg = 25.0;
  const Posture standing = standing_posture({-0.5, 0.1, 1.0});
  const MujocoModel mujoco(mjcf_text(model, wall, PhysicsParameters{}, StrengthProfile{}, standing), "test");
  const MujocoLayout layout = mujoco_layout(model, mujoco.get(), wall.incline_deg);
  mjData* data = mj_makeData(mujoco.get());
  Random random(20261129);
  BodyData body(model);
  for (int sample = 0; sample < 10; ++sample) {
    const Posture g = testing::random_posture(model, random);
    place_at_rest(layout, mujoco.get(), data, g);
    ASSERT_LT((simulated_posture(layout, data) - g).cwiseAbs().maxCoeff(), 1e-12) << "sample " << sample;
    ASSERT_LT(root_turn(layout, data), 1e-9);
    forward_kinematics(model, body, g);
    for (int limb = 0; limb < kLimbCount; ++limb) {
      ASSERT_LT(
          (simulated_grasp_point(layout, data, static_cast<Limb>(limb)) - body.points[operational_point(limb)]).norm(),
          1e-9);
    }
  }
  mj_deleteData(data);
}

TEST(MujocoLayout, AModelWithoutCruxsNamesIsRefused) {
  const MujocoModel other(R"(<mujoco><worldbody><body name="root"><freejoint name="root"/>
    <geom type="sphere" size="0.1" mass="1"/></body></worldbody></mujoco>)",
                          "other");
  EXPECT_THROW(mujoco_layout(testing::human_model(), other.get(), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace crux
