#include "reports/view_description.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"

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
  EXPECT_EQ(json["root"], nlohmann::ordered_json({0.3, 0.6, 1.0}));
  EXPECT_DOUBLE_EQ(json["centre_of_mass"][2].get<double>(), com.z());
  EXPECT_DOUBLE_EQ(json["grasp_points"]["left_foot"][2].get<double>(),
                   data.points[operational_point(Limb::LeftFoot)].z());
  EXPECT_EQ(view_text(caption), "wrote v.svg: title, subtitle\n");
}

// The static model's loads: the forces of the held limbs, each bounded joint's ratio, and
// a note of the verdict and the most loaded joint.
TEST(ViewDescription, TheStaticModelsLoadsAreListedAndNoted) {
  const BodyModel& model = testing::human_model();
  const Posture posture = standing_posture({-0.3, 0.6, 1.0});
  StanceLoads loads;
  loads.balanced = true;
  loads.effort = 1.25;
  loads.held = {true, false, true, true};
  loads.forces = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(9, 9, 9), Eigen::Vector3d(4, 5, 6),
                  Eigen::Vector3d(7, 8, 9)};
  loads.joint_ratios = {{6, 0.5}, {9, 1.25}};
  const ViewCaption caption{"v.svg", "title", "subtitle"};
  const auto json = view_json(model, posture, caption, &loads);
  EXPECT_EQ(json["stance"]["balanced"], true);
  EXPECT_EQ(json["stance"]["feasible"], false);
  EXPECT_EQ(json["stance"]["effort"], 1.25);
  EXPECT_EQ(json["stance"]["contact_forces_n"]["right_hand"], nlohmann::ordered_json({1.0, 2.0, 3.0}));
  EXPECT_FALSE(json["stance"]["contact_forces_n"].contains("left_hand"));
  EXPECT_EQ(json["stance"]["torque_to_limit"][model.joints[9].name], 1.25);
  EXPECT_FALSE(view_json(model, posture, caption).contains("stance"));
  EXPECT_EQ(with_stance_note(caption, model, loads).subtitle,
            "subtitle; static model: not held at effort 1.25 (" + model.joints[9].name + ")");
  loads.effort = 0.5;
  loads.joint_ratios = {{6, 0.5}};
  EXPECT_EQ(with_stance_note(caption, model, loads).subtitle,
            "subtitle; static model: held at effort 0.50 (" + model.joints[6].name + ")");
  loads.balanced = false;
  EXPECT_EQ(with_stance_note(caption, model, loads).subtitle,
            "subtitle; static model: no forces on these holds balance it");
  EXPECT_TRUE(view_json(model, posture, caption, &loads)["stance"]["effort"].is_null());
}

TEST(ViewDescription, CaptionsNameTheRunItsClimbAndStep) {
  RunFolder folder;
  folder.name = "training_2";
  folder.wall.name = "w";
  // Episode index 3 (iterations.csv's) is episode 4: crux shows episodes from 1, as Fig. 4 does.
  RecordedClimb climb{"episode", 3, false, {}, {Posture::Zero(), Posture::Zero()}};
  const ViewCaption run = run_view_caption(folder, climb, 1, "a.svg");
  EXPECT_EQ(run.title, "training_2 on 'w'");
  EXPECT_EQ(run.subtitle, "step 1 of the climb of episode 4 (unfinished) (2 postures, the start is step 0)");
  climb.postures.pop_back();
  EXPECT_EQ(run_view_caption(folder, climb, 0, "a.svg").subtitle,
            "step 0 of the climb of episode 4 (unfinished) (1 posture, the start is step 0)");
  const ViewCaption wall = wall_view_caption(folder.wall, "b.svg");
  EXPECT_EQ(wall.title, "'w'");
  EXPECT_EQ(wall.svg, "b.svg");
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

// A performed climb's step: its caption names the move and its outcome, and the JSON
// places the body turned by the root's rotation, with the forces from the holds.
TEST(ViewDescription, APerformedStepIsCaptionedAndPlacedTurned) {
  const BodyModel& model = testing::human_model();
  PerformFolder folder;
  folder.climb = "the wall's exact plan";
  folder.wall = testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});
  folder.wall.name = "w";
  folder.moves = {{Limb::RightHand, 4, false, MoveFailure::HandSlipped, 0.8}};
  folder.trajectory.resize(3);
  for (int i = 0; i < 3; ++i) {
    folder.trajectory[i].time = 0.5 * i;
    folder.trajectory[i].move = i == 0 ? -1 : 0;
    folder.trajectory[i].posture = standing_posture({-0.3, 0.0, 1.0});
  }
  folder.trajectory[2].root_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
  folder.trajectory[2].hold_forces[1] = Eigen::Vector3d(0, 0, 250);
  EXPECT_EQ(performed_view_caption(folder, 0, "a.svg").subtitle, "step 0 of 1: the start at rest, t = 0.00 s");
  const ViewCaption caption = performed_view_caption(folder, 1, "a.svg");
  EXPECT_EQ(caption.title, "the wall's exact plan on 'w', performed in MuJoCo");
  EXPECT_EQ(caption.subtitle,
            "step 1 of 1: move 1, right_hand to hold 5, failed: a hand slipped off its hold, t = 1.00 s");
  const nlohmann::ordered_json json = performed_view_json(model, folder.step_sample(1), caption);
  EXPECT_EQ(json["time_s"], 1.0);
  EXPECT_EQ(json["hold_forces_n"].size(), 1u);
  EXPECT_EQ(json["hold_forces_n"]["left_hand"][2], 250.0);
  BodyData data(model);
  forward_kinematics(model, data, folder.trajectory[2].posture);
  turn_about_root(data, folder.trajectory[2].root_orientation);
  const Eigen::Vector3d hand = data.points[operational_point(Limb::RightHand)];
  EXPECT_EQ(json["grasp_points"]["right_hand"], nlohmann::ordered_json({hand.x(), hand.y(), hand.z()}));
}

}  // namespace
}  // namespace crux
