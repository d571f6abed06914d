#include "reports/plan_description.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

Wall named_wall() {
  Wall wall;
  wall.name = "w";
  return wall;
}

TEST(PlanDescription, AFoundPlanListsItsMoves) {
  Plan plan;
  plan.found = true;
  plan.length = 2;
  plan.hold_ids = {7, 9};
  plan.limbs = {Limb::RightHand, Limb::LeftFoot};
  plan.expanded_states = 12;
  plan.ik_solves = 40;
  const auto json = plan_json(named_wall(), plan);
  EXPECT_EQ(json["length"], 2);
  EXPECT_EQ(json["holds"], nlohmann::ordered_json({7, 9}));
  EXPECT_EQ(json["limbs"], nlohmann::ordered_json({"right_hand", "left_foot"}));
  EXPECT_EQ(json["physics_model"], "kinematic");
  EXPECT_EQ(plan_text(named_wall(), plan),
            "shortest climb on 'w' under the kinematic model: 2 actions (12 states explored, 40 IK solves)\n"
            "   1. right_hand -> hold 7\n"
            "   2. left_foot  -> hold 9\n");
}

TEST(PlanDescription, NoPlanSaysWhy) {
  Plan none;
  none.expanded_states = 3;
  none.ik_solves = 5;
  EXPECT_EQ(plan_json(named_wall(), none)["length"], -1);
  EXPECT_EQ(plan_text(named_wall(), none),
            "no climb exists on 'w' under the kinematic model (3 states explored, 5 IK solves)\n");
  none.physics_model = PhysicsModel::Static;
  EXPECT_EQ(plan_json(named_wall(), none)["physics_model"], "static");
  EXPECT_EQ(plan_text(named_wall(), none),
            "no climb exists on 'w' under the static model (3 states explored, 5 IK solves)\n");
  none.stopped_at_limit = true;
  EXPECT_NE(plan_text(named_wall(), none).find("--plan-max-solves raises it"), std::string::npos);
  EXPECT_EQ(plan_json(named_wall(), none)["stopped_at_limit"], true);
}

TEST(PlanDescription, CountsOfOneAreSingular) {
  Plan plan;
  plan.found = true;
  plan.length = 1;
  plan.hold_ids = {7};
  plan.limbs = {Limb::RightHand};
  plan.expanded_states = 1;
  plan.ik_solves = 1;
  EXPECT_EQ(plan_text(named_wall(), plan),
            "shortest climb on 'w' under the kinematic model: 1 action (1 state explored, 1 IK solve)\n"
            "   1. right_hand -> hold 7\n");
  plan.found = false;
  EXPECT_EQ(plan_text(named_wall(), plan),
            "no climb exists on 'w' under the kinematic model (1 state explored, 1 IK solve)\n");
  plan.stopped_at_limit = true;
  EXPECT_EQ(plan_text(named_wall(), plan)
                .rfind("no climb found on 'w' under the kinematic model within 1 IK solve (1 state explored);", 0),
            0u);
}

}  // namespace
}  // namespace crux
