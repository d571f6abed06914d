// crux's kinematics against Orocos KDL reading the same URDF through kdl_parser.

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "support/kdl_reference.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kKdlSeed = 1122;

void expect_agreement(const std::string& urdf_path, const BodyModel& model, std::uint64_t seed) {
  testing::KdlReference kdl(urdf_path, model);
  BodyData data(model);
  Random random(seed);
  for (int sample = 0; sample < 1000; ++sample) {
    const Posture g = testing::random_posture(model, random);
    forward_kinematics(model, data, g);
    operational_jacobians(model, data);
    for (int k = 0; k < kOperationalPointCount; ++k) {
      ASSERT_LT((data.points[k] - kdl.point(g, k)).norm(), 1e-9)
          << "seed " << seed << " sample " << sample << " point " << k;
      ASSERT_LT((data.jacobians[k] - kdl.jacobian(g, k)).cwiseAbs().maxCoeff(), 1e-9)
          << "seed " << seed << " sample " << sample << " point " << k;
    }
    ASSERT_LT((centre_of_mass(model, data) - kdl.centre_of_mass(g)).norm(), 1e-9)
        << "seed " << seed << " sample " << sample;
  }
}

TEST(KinematicsAgainstKdl, HumanOver1000RandomPostures) {
  expect_agreement(default_body_model_path(), testing::human_model(), kKdlSeed);
}

// Issue 26: the body was mirrored (left limbs on the climber's right in every
// right-handed tool). Read by KDL, the zero posture stands facing +x, the wall's
// direction, with its left hand and foot on its left, +y.
TEST(KinematicsAgainstKdl, TheZeroPostureFacesPlusXWithItsLeftLimbsOnItsLeft) {
  testing::KdlReference kdl(default_body_model_path(), testing::human_model());
  const testing::BodySides sides = kdl.body_sides(Posture::Zero());
  EXPECT_GT(sides.forward.x(), 0.99) << sides.forward.transpose();
  EXPECT_GT(sides.left.y(), 0.99) << sides.left.transpose();
  EXPECT_NEAR(sides.hands, 2 * 0.1853, 1e-9) << "the shoulders' breadth: the palms hang below them";
  EXPECT_NEAR(sides.feet, 2 * 0.085, 1e-9) << "the hips' breadth";
}

TEST(KinematicsAgainstKdl, SyntheticTreeWithArbitraryAxesAndOrigins) {
  const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(kKdlSeed));
  const BodyModel model = load_body_model(path.string());
  expect_agreement(path.string(), model, kKdlSeed + 1);
}

}  // namespace
}  // namespace crux
