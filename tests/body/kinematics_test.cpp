#include "body/kinematics.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/allocation_counter.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::human_model;
using testing::random_posture;

constexpr std::uint64_t kSeed = 20261122;

TEST(Kinematics, JacobiansMatchCentralFiniteDifferences) {
  const BodyModel& model = human_model();
  BodyData data(model), probe(model);
  Random random(kSeed);
  constexpr double h = 1e-6;
  for (int sample = 0; sample < 1000; ++sample) {
    const Posture g = random_posture(model, random);
    forward_kinematics(model, data, g);
    operational_jacobians(model, data);
    for (int i = 0; i < kConfigurationDof; ++i) {
      Posture plus = g, minus = g;
      plus[i] += h;
      minus[i] -= h;
      forward_kinematics(model, probe, plus);
      const auto points_plus = probe.points;
      forward_kinematics(model, probe, minus);
      for (int k = 0; k < kOperationalPointCount; ++k) {
        const Eigen::Vector3d numeric = (points_plus[k] - probe.points[k]) / (2 * h);
        ASSERT_LT((numeric - data.jacobians[k].col(i)).norm(), 1e-7)
            << "seed " << kSeed << " sample " << sample << " point " << k << " coordinate " << i;
      }
    }
  }
}

TEST(Kinematics, StandingPostureIsUprightWithFeetBelowRoot) {
  const BodyModel& model = human_model();
  BodyData data(model);
  const Eigen::Vector3d root(0.3, 0.6, 1.0);
  forward_kinematics(model, data, standing_posture(root));
  EXPECT_EQ(data.points[0], root);
  const auto& rh = data.points[operational_point(Limb::RightHand)];
  const auto& lh = data.points[operational_point(Limb::LeftHand)];
  const auto& rf = data.points[operational_point(Limb::RightFoot)];
  const auto& lf = data.points[operational_point(Limb::LeftFoot)];
  EXPECT_LT(rh.y(), lh.y()) << "y grows to the climber's left";
  EXPECT_LT(rf.y(), lf.y());
  EXPECT_NEAR(rf.z(), root.z() - model.root_height_above_soles, 1e-12);
  EXPECT_LT(rf.x(), root.x()) << "the climber faces -x, the feet point to the wall";
  const Eigen::Vector3d com = centre_of_mass(model, data);
  EXPECT_NEAR(com.y(), root.y(), 1e-9) << "the body is symmetric";
}

TEST(Kinematics, HotPathDoesNotAllocate) {
  const BodyModel& model = human_model();
  BodyData data(model);
  Random random(kSeed);
  const Posture g = random_posture(model, random);
  const long before = testing::allocation_count();
  for (int n = 0; n < 10; ++n) {
    forward_kinematics(model, data, g);
    operational_forward_kinematics(model, data, g);
    operational_jacobians(model, data);
    centre_of_mass(model, data);
  }
  EXPECT_EQ(testing::allocation_count(), before);
}

// IK's forward kinematics places the operational points and their chains exactly as the
// whole-body one, and leaves the other joints (the neck) where they were.
TEST(Kinematics, OperationalForwardKinematicsIsTheWholeOnesOnTheChains) {
  const BodyModel& model = human_model();
  ASSERT_LT(model.operational_joints.size(), model.joints.size());
  for (const int i : model.operational_joints) EXPECT_EQ(model.joints[i].name.rfind("neck", 0), std::string::npos);
  BodyData whole(model), operational(model);
  Random random(kSeed);
  const Posture first = random_posture(model, random);
  forward_kinematics(model, operational, first);
  const BodyData before = operational;
  for (int sample = 0; sample < 100; ++sample) {
    const Posture g = random_posture(model, random);
    forward_kinematics(model, whole, g);
    operational_forward_kinematics(model, operational, g);
    for (int k = 0; k < kOperationalPointCount; ++k) EXPECT_EQ(operational.points[k], whole.points[k]) << k;
    operational_jacobians(model, whole);
    operational_jacobians(model, operational);
    for (int k = 0; k < kOperationalPointCount; ++k) EXPECT_EQ(operational.jacobians[k], whole.jacobians[k]) << k;
  }
  for (int i = 0; i < static_cast<int>(model.joints.size()); ++i) {
    if (std::find(model.operational_joints.begin(), model.operational_joints.end(), i) !=
        model.operational_joints.end()) {
      continue;
    }
    EXPECT_EQ(operational.placements[i].origin, before.placements[i].origin) << model.joints[i].name;
  }
}

}  // namespace
}  // namespace crux
