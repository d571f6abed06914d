#include "body/reach_envelope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "support/sample_count.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kEnvelopeSeed = 20261124;

// The envelope read back from forward kinematics at a posture: where the chain's first
// joint sits relative to the root, and the sum of the distances between successive
// joint origins down to the grasp point, which no rotation changes.
void expect_envelope_from_placements(const BodyModel& model, const ReachEnvelope& envelope, const Posture& g,
                                     const std::string& label) {
  BodyData data(model);
  forward_kinematics(model, data, g);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    int joint = model.grasp_points[limb].joint;
    double length = (data.points[operational_point(limb)] - data.placements[joint].origin).norm();
    for (; model.joints[joint].parent >= kRootDof; joint = model.joints[joint].parent) {
      length += (data.placements[joint].origin - data.placements[model.joints[joint].parent].origin).norm();
    }
    EXPECT_NEAR((envelope.chain_base[limb] - (data.placements[joint].origin - data.points[0])).norm(), 0.0, 1e-12)
        << label << " limb " << limb;
    EXPECT_NEAR(envelope.radius[limb], length, 1e-12) << label << " limb " << limb;
  }
}

// Every grasp point of every sampled posture lies inside its limb's ball; returns the
// farthest each limb went.
std::array<double, kLimbCount> expect_sound(const BodyModel& model, const ReachEnvelope& envelope, std::uint64_t seed,
                                            const std::string& label) {
  BodyData data(model);
  Random random(seed);
  std::array<double, kLimbCount> farthest{};
  for (int sample = 0; sample < testing::sample_count(20000); ++sample) {
    const Posture g = testing::random_posture(model, random);
    forward_kinematics(model, data, g);
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const double distance =
          (data.points[operational_point(limb)] - data.points[0] - envelope.chain_base[limb]).norm();
      EXPECT_LE(distance, envelope.radius[limb] + 1e-12) << label << " seed " << seed << " sample " << sample;
      farthest[limb] = std::max(farthest[limb], distance);
    }
  }
  return farthest;
}

TEST(ReachEnvelope, HumanChainsMatchTheirPlacementsAtAnyPosture) {
  const BodyModel& model = testing::human_model();
  const ReachEnvelope& envelope = model.reach_envelope;
  Random random(kEnvelopeSeed);
  for (int sample = 0; sample < 20; ++sample) {
    expect_envelope_from_placements(model, envelope, testing::random_posture(model, random),
                                    "seed " + std::to_string(kEnvelopeSeed) + " sample " + std::to_string(sample));
  }
  // The human is symmetric: the hands' chains start at the shoulders' mirror images.
  EXPECT_NEAR(envelope.chain_base[0].y(), -envelope.chain_base[1].y(), 1e-12);
  EXPECT_DOUBLE_EQ(envelope.radius[0], envelope.radius[1]);
  EXPECT_DOUBLE_EQ(envelope.radius[2], envelope.radius[3]);
}

TEST(ReachEnvelope, GraspPointsNeverLeaveIt) {
  const ReachEnvelope& human = testing::human_model().reach_envelope;
  const auto farthest = expect_sound(testing::human_model(), human, kEnvelopeSeed, "human");
  for (int limb = 0; limb < kLimbCount; ++limb) {
    // The human's limbs nearly straighten within their limits, so the radius is not
    // loose (the synthetic trees' random axes cannot straighten).
    EXPECT_GT(farthest[limb], 0.8 * human.radius[limb]) << "seed " << kEnvelopeSeed << " limb " << limb;
  }
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(seed));
    const BodyModel model = load_body_model(path.string());
    const ReachEnvelope& envelope = model.reach_envelope;
    expect_envelope_from_placements(model, envelope, Posture::Zero(), "synthetic tree " + std::to_string(seed));
    expect_sound(model, envelope, kEnvelopeSeed + seed, "synthetic tree " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace crux
