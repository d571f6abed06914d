#include "body/kinematics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "body/urdf_loader.hpp"
#include "support/allocation_counter.hpp"
#include "support/sample_count.hpp"
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
  for (int sample = 0; sample < testing::sample_count(1000); ++sample) {
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

// A quarter turn about z takes each point's offset from the root's frame (dx, dy, dz) to
// (-dy, dx, dz), and turns the frames with it; the root's frame stays where it is.
TEST(Kinematics, TurningAboutTheRootTurnsEveryPointAboutTheRootsFrame) {
  const BodyModel& model = human_model();
  BodyData data(model), turned(model);
  const Posture g = standing_posture({-0.3, 0.2, 1.0});
  forward_kinematics(model, data, g);
  forward_kinematics(model, turned, g);
  turn_about_root(turned, Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ())));
  const Eigen::Vector3d pivot = g.head<kRootDof>();
  EXPECT_LT((turned.placements[kRootDof - 1].origin - pivot).norm(), 1e-15);
  for (int point = 0; point < kOperationalPointCount; ++point) {
    const Eigen::Vector3d d = data.points[point] - pivot;
    EXPECT_LT((turned.points[point] - pivot - Eigen::Vector3d(-d.y(), d.x(), d.z())).norm(), 1e-12) << point;
  }
  const Eigen::Vector3d axis = data.placements.back().axis;
  EXPECT_LT((turned.placements.back().axis - Eigen::Vector3d(-axis.y(), axis.x(), axis.z())).norm(), 1e-12);
}

TEST(Kinematics, StandingPostureIsUprightWithFeetBelowRoot) {
  const BodyModel& model = human_model();
  BodyData data(model);
  const Eigen::Vector3d root(-0.3, 0.6, 1.0);
  forward_kinematics(model, data, standing_posture(root));
  EXPECT_EQ(data.points[0], root);
  const auto& rh = data.points[operational_point(Limb::RightHand)];
  const auto& lh = data.points[operational_point(Limb::LeftHand)];
  const auto& rf = data.points[operational_point(Limb::RightFoot)];
  const auto& lf = data.points[operational_point(Limb::LeftFoot)];
  EXPECT_LT(rh.y(), lh.y()) << "y grows to the climber's left";
  EXPECT_LT(rf.y(), lf.y());
  EXPECT_NEAR(rf.z(), root.z() - model.root_height_above_soles, 1e-12);
  EXPECT_GT(rf.x(), root.x()) << "the climber faces +x, the feet point to the wall";
  const Eigen::Vector3d com = centre_of_mass(model, data);
  EXPECT_NEAR(com.y(), root.y(), 1e-9) << "the body is symmetric";
}

// A workspace is sized from its model; one sized for another is refused, not overrun.
TEST(Kinematics, AWorkspaceOfAnotherModelIsRefused) {
  const BodyModel& model = testing::human_model();
  BodyModel fewer_joints = model;
  fewer_joints.joints.pop_back();
  BodyData data(fewer_joints);
  EXPECT_THROW(forward_kinematics(model, data, Posture::Zero()), std::invalid_argument);
  EXPECT_THROW(operational_forward_kinematics(model, data, Posture::Zero()), std::invalid_argument);
  BodyData own(model);
  EXPECT_NO_THROW(forward_kinematics(model, own, Posture::Zero()));
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

// Bit for bit, on the joints `joints` and the operational points.
bool same_bits(const BodyData& a, const BodyData& b, const std::vector<int>& joints) {
  const auto same = [](const auto& x, const auto& y) {
    return std::memcmp(x.data(), y.data(), sizeof(double) * x.size()) == 0;
  };
  for (const int i : joints) {
    if (!same(a.placements[i].rotation, b.placements[i].rotation) ||
        !same(a.placements[i].origin, b.placements[i].origin) || !same(a.placements[i].axis, b.placements[i].axis)) {
      return false;
    }
  }
  for (int k = 0; k < kOperationalPointCount; ++k) {
    if (!same(a.points[k], b.points[k])) return false;
  }
  return true;
}

TEST(Kinematics, OperationalThenRemainingForwardKinematicsIsTheWholeToTheBit) {
  const BodyModel& model = human_model();
  std::vector<int> every_joint(model.joints.size());
  for (std::size_t i = 0; i < every_joint.size(); ++i) every_joint[i] = static_cast<int>(i);
  BodyData whole(model), in_two(model);
  Random random(kSeed + 7);
  for (int sample = 0; sample < 100; ++sample) {
    const Posture g = random_posture(model, random);
    forward_kinematics(model, whole, g);
    operational_forward_kinematics(model, in_two, g);
    remaining_forward_kinematics(model, in_two, g);
    EXPECT_TRUE(same_bits(whole, in_two, every_joint)) << "seed " << kSeed + 7 << ", sample " << sample;
  }
}

// A workspace that has placed other postures reuses the sines and cosines of the joints
// whose coordinates kept their bits; it must place each posture exactly as a fresh one.
void expect_reuse_changes_no_bit(const BodyModel& model, std::uint64_t seed, const std::string& body) {
  Random random(seed);
  BodyData reused(model);
  std::vector<int> every_joint(model.joints.size());
  for (std::size_t i = 0; i < every_joint.size(); ++i) every_joint[i] = static_cast<int>(i);
  Posture g = random_posture(model, random);
  for (int step = 0; step < 300; ++step) {
    const Posture other = random_posture(model, random);
    for (int i = 0; i < kConfigurationDof; ++i) {
      const double u = random.uniform();
      if (u < 0.4)
        g[i] = other[i];  // moved
      else if (u < 0.45)
        g[i] = -g[i];  // mirrored, so +0.0 and -0.0 both occur
      else if (u < 0.5)
        g[i] = 0.0;  // at zero
    }
    BodyData fresh(model);
    forward_kinematics(model, fresh, g);
    // Odd steps place only the chains, as the solvers' trials do.
    const bool whole = step % 2 == 0;
    if (whole) {
      forward_kinematics(model, reused, g);
    } else {
      operational_forward_kinematics(model, reused, g);
    }
    ASSERT_TRUE(same_bits(reused, fresh, whole ? every_joint : model.operational_joints))
        << body << ", seed " << seed << ", step " << step;
  }
}

TEST(Kinematics, ReusedSinesAndCosinesChangeNoBit) {
  expect_reuse_changes_no_bit(human_model(), kSeed, "human");
  // Random axes: the general rotation, not the coordinate-axis one.
  const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(1));
  expect_reuse_changes_no_bit(load_body_model(path.string()), kSeed + 1, "synthetic tree 1");
}

TEST(Kinematics, AMinusZeroAngleIsNotTakenForPlusZero) {
  const BodyModel& model = human_model();
  BodyData data(model);
  Posture g = standing_posture({0.3, 0.6, 1.0});
  forward_kinematics(model, data, g);
  const int joint = model.operational_joints.back();
  EXPECT_EQ(std::bit_cast<std::uint64_t>(data.trigonometry[joint].sine), std::bit_cast<std::uint64_t>(0.0));
  g[joint] = -0.0;
  forward_kinematics(model, data, g);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(data.trigonometry[joint].sine), std::bit_cast<std::uint64_t>(-0.0));
}

}  // namespace
}  // namespace crux
