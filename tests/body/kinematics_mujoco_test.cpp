// crux's kinematics against MuJoCo reading the same URDF: every joint frame, the grasp
// frames and the centre of mass.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "support/mujoco_reference.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kMujocoKinematicsSeed = 2611;

// Returns the largest centre-of-mass distance seen, for the caller to state.
double expect_mujoco_kinematics(const std::string& urdf_path, const BodyModel& model, std::uint64_t seed) {
  testing::MujocoReference mujoco(urdf_path, model);
  BodyData data(model);
  Random random(seed);
  double largest_com_distance = 0.0;
  for (int sample = 0; sample < 1000; ++sample) {
    const Posture g = testing::random_posture(model, random);
    forward_kinematics(model, data, g);
    mujoco.set_posture(g);
    for (int i = 0; i < kConfigurationDof; ++i) {
      EXPECT_LT((data.placements[i].origin - mujoco.joint_origin(i)).norm(), 1e-9)
          << "seed " << seed << " sample " << sample << " joint " << model.joints[i].name;
      EXPECT_LT((data.placements[i].rotation - mujoco.joint_rotation(i)).cwiseAbs().maxCoeff(), 1e-12)
          << "seed " << seed << " sample " << sample << " joint " << model.joints[i].name;
    }
    for (int limb = 0; limb < kLimbCount; ++limb) {
      EXPECT_LT((data.points[operational_point(limb)] - mujoco.link_origin(model.grasp_frame_names[limb])).norm(), 1e-9)
          << "seed " << seed << " sample " << sample << " grasp frame " << model.grasp_frame_names[limb];
    }
    const double com_distance = (centre_of_mass(model, data) - mujoco.centre_of_mass()).norm();
    EXPECT_LT(com_distance, 1e-9) << "seed " << seed << " sample " << sample;
    largest_com_distance = std::max(largest_com_distance, com_distance);
    if (::testing::Test::HasFailure()) break;
  }
  return largest_com_distance;
}

// Issue 26: MuJoCo reads the body as shipped, facing +x (its toes, from the ankles, point
// to the wall) with its left palm and left foot on its left (+y = up x forward), at the
// zero posture.
TEST(KinematicsAgainstMujoco, TheZeroPostureFacesPlusXWithItsLeftLimbsOnItsLeft) {
  testing::MujocoReference mujoco(default_body_model_path(), testing::human_model());
  mujoco.set_posture(Posture::Zero());
  const Eigen::Vector3d toes = mujoco.link_origin("right_foot_ball") + mujoco.link_origin("left_foot_ball") -
                               mujoco.link_origin("right_ankle_link") - mujoco.link_origin("left_ankle_link");
  EXPECT_GT(toes.x(), 0.2) << toes.transpose();
  const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(Eigen::Vector3d(toes.x(), toes.y(), 0).normalized());
  EXPECT_GT(left.y(), 0.99);
  EXPECT_NEAR((mujoco.link_origin("left_palm") - mujoco.link_origin("right_palm")).dot(left), 2 * 0.1853, 1e-9);
  EXPECT_NEAR((mujoco.link_origin("left_foot_ball") - mujoco.link_origin("right_foot_ball")).dot(left), 2 * 0.085,
              1e-9);
}

TEST(KinematicsAgainstMujoco, HumanOver1000RandomPostures) {
  const double com_distance =
      expect_mujoco_kinematics(default_body_model_path(), testing::human_model(), kMujocoKinematicsSeed);
  ::testing::Test::RecordProperty("largest_centre_of_mass_distance_m", std::to_string(com_distance));
}

TEST(KinematicsAgainstMujoco, SyntheticTreeWithArbitraryAxesAndOrigins) {
  const auto path =
      testing::write_temporary("synthetic_mujoco.urdf", testing::synthetic_tree_urdf_for_mujoco(kMujocoKinematicsSeed));
  expect_mujoco_kinematics(path.string(), load_body_model(path.string()), kMujocoKinematicsSeed + 1);
}

// The mass bounds that let MuJoCo compile the body add 25 nanograms to its 68 kg.
TEST(KinematicsAgainstMujoco, TheMassBoundsAddAtMostANanogramPerBody) {
  const BodyModel& model = testing::human_model();
  const testing::MujocoReference mujoco(default_body_model_path(), model);
  const double added = mujoco.total_mass() - model.total_mass;
  EXPECT_GE(added, 0.0);
  EXPECT_LE(added, 1e-12 * mujoco.model().nbody);
}

}  // namespace
}  // namespace crux
