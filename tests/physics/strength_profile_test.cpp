#include "physics/strength_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_models.hpp"

namespace crux {
namespace {

int coordinate_of(const BodyModel& model, const std::string& name) {
  for (int i = 0; i < static_cast<int>(model.joints.size()); ++i) {
    if (model.joints[i].name == name) return i;
  }
  throw std::runtime_error("no joint " + name);
}

// The human of docs/MODEL.md (68 kg, 1.70 m): Anderson's c1 x m x h x g, the gymnast's
// newton-metres x (68 x 1.70) / (69.6 x 1.732), both sides alike, and no bound where
// neither source measures the joint.
TEST(StrengthProfile, HumanLimitsAreTheScaledPublishedValues) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile profile = published_strength_profile(model, 68.0, 1.70);
  const double anderson = 68.0 * 1.70 * 9.81, gymnast = 68.0 * 1.70 / (69.6 * 1.732);
  for (const std::string side : {"right_", "left_"}) {
    const JointStrength& knee = profile.joints[coordinate_of(model, side + "knee_flexion")];
    EXPECT_DOUBLE_EQ(knee.positive, 0.087 * anderson);  // flexion
    EXPECT_DOUBLE_EQ(knee.negative, 0.163 * anderson);  // extension
    const JointStrength& ankle = profile.joints[coordinate_of(model, side + "ankle_flexion")];
    EXPECT_DOUBLE_EQ(ankle.positive, 0.033 * anderson);  // dorsiflexion
    EXPECT_DOUBLE_EQ(ankle.negative, 0.095 * anderson);  // plantar flexion
    const JointStrength& elbow = profile.joints[coordinate_of(model, side + "elbow_flexion")];
    EXPECT_DOUBLE_EQ(elbow.positive, 101.384 * gymnast);
    EXPECT_DOUBLE_EQ(elbow.negative, 69.8728 * gymnast);
    EXPECT_TRUE(std::isinf(profile.joints[coordinate_of(model, side + "hip_abduction")].positive));
    EXPECT_TRUE(std::isinf(profile.joints[coordinate_of(model, side + "ankle_inversion")].negative));
  }
  EXPECT_DOUBLE_EQ(profile.joints[coordinate_of(model, "lumbar_flexion")].negative, 687.864 * gymnast);
  EXPECT_TRUE(std::isinf(profile.joints[coordinate_of(model, "neck_flexion")].positive));
  int bounded = 0;
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    bounded += std::isfinite(profile.joints[i].positive) && std::isfinite(profile.joints[i].negative);
  }
  EXPECT_EQ(bounded, 1 + 2 * 7 + 2 * 3);  // lumbar flexion, 7 arm joints and 3 leg joints a side
}

// Each level's grip is its study's number (docs/MODEL.md, "Grip and push limits"):
// Grant et al. 2003's 383 N, Amca et al. 2012's 575.7 N, and Binney & Cochrane 2003's
// 57.4 kg x 9.81 m/s^2 = 563.094 N; the default grip is the advanced level's.
TEST(ClimbingLevels, GripsAreTheCitedMeasurementsInNewtons) {
  ASSERT_EQ(climbing_levels().size(), 3u);
  EXPECT_DOUBLE_EQ(find_climbing_level("intermediate")->grip_n, 383.0);
  EXPECT_DOUBLE_EQ(find_climbing_level("advanced")->grip_n, 575.7);
  EXPECT_NEAR(find_climbing_level("elite")->grip_n, 563.094, 1e-9);
  EXPECT_DOUBLE_EQ(kAdvancedClimberGripN, 575.7);
  EXPECT_FALSE(find_climbing_level("Advanced").has_value()) << "names are exact";
  EXPECT_FALSE(find_climbing_level("").has_value());
  EXPECT_EQ(climbing_level_descriptions(), "intermediate (383.0 N), advanced (575.7 N) or elite (563.1 N)");
}

}  // namespace
}  // namespace crux
