#include "reports/model_description.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

// Docs/MODEL.md's segments: the thigh (hip to knee) and shank (knee to ankle) of 1.70 m
// body, 0.245 H and 0.246 H (Winter), each side.
TEST(ModelDescription, SegmentLengthsAreTheKinematicsOwn) {
  const auto segments = segment_lengths(testing::human_model());
  int thighs = 0, grasp_segments = 0;
  for (const SegmentLength& s : segments) {
    EXPECT_GT(s.length_m, 1e-9) << s.name;
    if (s.name.find("hip_rotation -> ") != std::string::npos && s.name.find("knee") != std::string::npos) {
      EXPECT_NEAR(s.length_m, 0.245 * 1.70, 0.01) << s.name;
      ++thighs;
    }
    if (s.name.find("palm") != std::string::npos || s.name.find("foot_ball") != std::string::npos) ++grasp_segments;
  }
  EXPECT_EQ(thighs, 2);
  EXPECT_EQ(grasp_segments, kLimbCount);
}

TEST(ModelDescription, JsonAndTextNameTheBodyAndEveryJoint) {
  const BodyModel& model = testing::human_model();
  const auto json = model_json(model);
  EXPECT_EQ(json["dof_root"], kRootDof);
  EXPECT_EQ(json["joints"].size(), static_cast<std::size_t>(kRevoluteDof));
  EXPECT_EQ(json["segments"].size(), segment_lengths(model).size());
  EXPECT_DOUBLE_EQ(json["mass_kg"].get<double>(), model.total_mass);
  const std::string text = model_text(model);
  EXPECT_EQ(text.rfind("body '" + model.name + "' from " + model.source + "\n", 0), 0u) << text;
  for (int i = kRootDof; i < kConfigurationDof; ++i) EXPECT_NE(text.find(model.joints[i].name), std::string::npos);
  EXPECT_NE(text.find("degrees of freedom: 3 root translations + 32 revolute = 35\n"), std::string::npos);
}

}  // namespace
}  // namespace crux
