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

TEST(KinematicsAgainstKdl, SyntheticTreeWithArbitraryAxesAndOrigins) {
  const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(kKdlSeed));
  const BodyModel model = load_body_model(path.string());
  expect_agreement(path.string(), model, kKdlSeed + 1);
}

}  // namespace
}  // namespace crux
