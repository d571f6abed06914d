#pragma once
// A hand-made wall for the simulation's tests: feet on two holds at knee height, hands on
// two jugs above the shoulders, and a jug 20 cm above the right hand (hold index 4), with
// the start stance and the stance of the right hand's move up to it as the IK solves them
// under the static model's rules (ik.wall = avoid). No finish unless a test sets one
// (finish_after_one_move).

#include <gtest/gtest.h>

#include "climbing/configuration_reacher.hpp"
#include "configurations/reachability.hpp"
#include "ik/ik_solver.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"

namespace crux::testing {

struct JugLadder {
  Wall wall = wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});
  ReachabilityParameters reach;
  PhysicsParameters physics;
  Posture start, reached;
  HoldConfiguration before;  // the start's holds, the right hand free

  JugLadder() {
    const BodyModel& model = human_model();
    wall.finish_height = 3.0;
    reach.ik.wall = WallRule::Avoid;
    physics.model = PhysicsModel::Static;
    BodyData data(model);
    const IkResult started = solve_start(model, data, wall, reach);
    EXPECT_TRUE(started.reached) << "the ladder's start";
    start = started.posture;
    before = start_configuration(wall).with(Limb::RightHand, kFree);
    const IkResult up =
        solve_ik(model, data, start, reach_target(model, wall, before.with(Limb::RightHand, 4), reach.root), reach.ik);
    EXPECT_TRUE(up.reached) << "the right hand on the jug";
    reached = up.posture;
  }

  // A finish that the right hand's move up to the jug passes and its move back to the hold
  // it left does not, as the planner reaches their stances (the jug's centre of mass is a
  // centimetre above): the exact plan is that one move.
  void finish_after_one_move() {
    const BodyModel& model = human_model();
    ConfigurationReacher reacher(model, wall, reach, physics, StanceQuestion::HoldsStill);
    const Posture& from = reacher.require_start(wall.name);
    const auto centre_height = [&](int hold) {
      const Posture* stance = reacher.reach(from, before.with(Limb::RightHand, hold), Limb::LeftHand);
      EXPECT_NE(stance, nullptr) << "hold " << hold;
      return stance == nullptr ? 0.0 : reacher.place(*stance).centre_of_mass.z();
    };
    const double jug = centre_height(4), back = centre_height(0);
    EXPECT_GT(jug, back + 0.002);
    wall.finish_height = 0.5 * (jug + back);
  }
};

}  // namespace crux::testing
