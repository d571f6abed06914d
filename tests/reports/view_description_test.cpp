#include "reports/view_description.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(ViewDescription, ThePostureIsPlacedAndCaptioned) {
  const BodyModel& model = testing::human_model();
  const Posture posture = standing_posture({0.3, 0.6, 1.0});
  const ViewCaption caption{"v.svg", "title", "subtitle"};
  const auto json = view_json(model, posture, caption);
  BodyData data(model);
  forward_kinematics(model, data, posture);
  const Eigen::Vector3d com = centre_of_mass(model, data);
  EXPECT_EQ(json["svg"], "v.svg");
  EXPECT_EQ(json["root"], nlohmann::json({0.3, 0.6, 1.0}));
  EXPECT_DOUBLE_EQ(json["centre_of_mass"][2].get<double>(), com.z());
  EXPECT_DOUBLE_EQ(json["grasp_points"]["left_foot"][2].get<double>(),
                   data.points[operational_point(Limb::LeftFoot)].z());
  EXPECT_EQ(view_text(caption), "wrote v.svg: title, subtitle\n");
}

}  // namespace
}  // namespace crux
