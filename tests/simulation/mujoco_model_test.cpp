#include "simulation/mujoco_model.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include "common/input_error.hpp"

namespace crux {
namespace {

constexpr const char* kPendulum = R"(<mujoco model="pendulum">
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.5" size="0.02" mass="1"/>
    </body>
  </worldbody>
  <equality><connect name="hold" body1="arm" anchor="0 0 -0.5" active="false"/></equality>
</mujoco>
)";

TEST(MujocoModel, CompilesTextAsMujocoReadsAFile) {
  const MujocoModel model(kPendulum, "pendulum.xml");
  EXPECT_EQ(model.get()->nq, 1);
  EXPECT_EQ(model.get()->nbody, 2);
  EXPECT_NEAR(mj_getTotalmass(model.get()), 1.0, 1e-12);
}

TEST(MujocoModel, ARefusedModelIsOneLineNamingItsSource) {
  try {
    const MujocoModel model("<mujoco><worldbody><body><joint type=\"twisting\"/></body></worldbody></mujoco>",
                            "bad.xml");
    FAIL() << "MuJoCo took an unknown joint type";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "bad.xml");
    EXPECT_EQ(std::string(e.problem()).find('\n'), std::string::npos) << e.problem();
    EXPECT_NE(std::string(e.problem()).find("MuJoCo refused the model: "), std::string::npos) << e.problem();
  }
  EXPECT_THROW(MujocoModel("not xml", "text"), InputError);
}

// A grasp writes its constraint's anchor into the model: a copy is the thread's own.
TEST(MujocoModel, ACopyIsItsOwn) {
  const MujocoModel original(kPendulum, "pendulum.xml");
  MujocoModel copy(original);
  copy.get()->eq_active[0] = 1;
  copy.get()->eq_data[3] = 0.25;
  EXPECT_EQ(original.get()->eq_active[0], 0);
  EXPECT_NE(original.get()->eq_data[3], 0.25);
  EXPECT_EQ(copy.get()->nq, original.get()->nq);
}

}  // namespace
}  // namespace crux
