#include "configurations/reachability.hpp"

#include <gtest/gtest.h>

#include "body/kinematics.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

using testing::wall_with_holds;

// Five holds; hold 4 is larger than the others. Start: right hand on 4, left hand on 1,
// right foot on 2, left foot on 3.
Wall five_holds() {
  Wall wall = wall_with_holds({{0.2, 2.0}, {0.8, 2.1}, {0.1, 0.7}, {0.5, 0.4}, {0.3, 1.9}}, {4, 1, 2, 3});
  wall.holds[4].radius = 0.06;
  return wall;
}

TEST(Reachability, IkGuessesAreNamedAndParsedBack) {
  for (const IkGuess guess : {IkGuess::Previous, IkGuess::Standing}) {
    EXPECT_EQ(parse_enum<IkGuess>(enum_name(guess)), guess);
  }
  EXPECT_STREQ(enum_name(IkGuess::Previous), "previous");
  EXPECT_STREQ(enum_name(IkGuess::Standing), "standing");
  EXPECT_FALSE(parse_enum<IkGuess>("last"));
}

TEST(Reachability, TargetTakesTheConfigurationsHoldsInLimbOrder) {
  const BodyModel& model = testing::human_model();
  const Wall wall = five_holds();
  HoldConfiguration c;
  c.holds = {4, 1, 2, 3};
  const ReachTarget target = reach_target(model, wall, c, RootTargetParameters{0.25});
  EXPECT_EQ(target.hold_centres[0], Eigen::Vector3d(0, 0.3, 1.9));
  EXPECT_EQ(target.hold_centres[1], Eigen::Vector3d(0, 0.8, 2.1));
  EXPECT_EQ(target.hold_centres[2], Eigen::Vector3d(0, 0.1, 0.7));
  EXPECT_EQ(target.hold_centres[3], Eigen::Vector3d(0, 0.5, 0.4));
  EXPECT_EQ(target.hold_radii, (std::array<double, kLimbCount>{0.06, 0.04, 0.04, 0.04}));
  // H(C4): 0.25 m off the wall on the climber's side (x < 0), y midway between the
  // feet (0.1, 0.5), z the lowest foot (0.4) plus the root's standing height above the soles.
  EXPECT_DOUBLE_EQ(target.root.x(), -0.25);
  EXPECT_DOUBLE_EQ(target.root.y(), 0.3);
  EXPECT_DOUBLE_EQ(target.root.z(), 0.4 + model.root_height_above_soles);
  EXPECT_GT(model.root_height_above_soles, 0.5) << "a human's hips stand well above its soles";
}

TEST(Reachability, TargetFollowsTheFeetOfTheConfigurationGiven) {
  const BodyModel& model = testing::human_model();
  const Wall wall = five_holds();
  HoldConfiguration swapped;
  swapped.holds = {0, 4, 3, 2};  // feet on 3 (0.5, 0.4) and 2 (0.1, 0.7), hands on 0 and 4
  const ReachTarget target = reach_target(model, wall, swapped, {});
  EXPECT_EQ(target.hold_centres[2], wall.holds[3].position);
  EXPECT_EQ(target.hold_radii[1], 0.06);
  EXPECT_DOUBLE_EQ(target.root.x(), -RootTargetParameters{}.distance_from_wall);
  EXPECT_DOUBLE_EQ(target.root.y(), 0.3);
  EXPECT_DOUBLE_EQ(target.root.z(), 0.4 + model.root_height_above_soles);
}

TEST(Reachability, StartConfigurationIsTheWallsStart) {
  const Wall wall = five_holds();
  const HoldConfiguration start = start_configuration(wall);
  EXPECT_EQ(start.holds, (std::array<int, kLimbCount>{4, 1, 2, 3}));
  EXPECT_EQ(start.free_count(), 0);
  EXPECT_EQ(start_configuration(generate_random_wall(3)).holds, generate_random_wall(3).start);
}

TEST(Reachability, StartGuessStandsWithTheRootAtTheStartsTarget) {
  const BodyModel& model = testing::human_model();
  const Wall wall = five_holds();
  const Posture guess = start_guess(model, wall, RootTargetParameters{0.4});
  // 0.4 m off the wall on the climber's side; feet of the start on holds 2 and 3: y = 0.3,
  // z = 0.4 + the standing height.
  EXPECT_DOUBLE_EQ(guess[0], -0.4);
  EXPECT_DOUBLE_EQ(guess[1], 0.3);
  EXPECT_DOUBLE_EQ(guess[2], 0.4 + model.root_height_above_soles);
  EXPECT_TRUE(guess.tail<kRevoluteDof>().isZero()) << "every joint at its natural standing angle";
}

TEST(Reachability, AReachedStartGraspsItsHoldsWithinTheLimits) {
  const BodyModel& model = testing::human_model();
  const ReachabilityParameters parameters;
  const Wall wall = generate_random_wall(1);
  BodyData data(model);
  const IkResult result = solve_start(model, data, wall, parameters);
  ASSERT_TRUE(result.reached) << "the default random wall's start is climbable";
  // Check the verdict independently: place the posture and apply the termination test.
  forward_kinematics(model, data, result.posture);
  const ReachTarget target = reach_target(model, wall, start_configuration(wall), parameters.root);
  EXPECT_TRUE(target_reached(data.points, target, parameters.ik.tolerances));
  EXPECT_NEAR(grasp_residual(data.points, target), result.residual_m, 1e-12)
      << "the residual reported is the posture's";
  EXPECT_TRUE(within_limits(model, result.posture));
}

TEST(Reachability, AnUnreachableStartReturnsTheStartGuess) {
  // Feet 4 m apart: no human does the splits that far.
  const BodyModel& model = testing::human_model();
  const Wall wall = wall_with_holds({{0.0, 1.8}, {0.6, 1.8}, {-2.0, 0.0}, {2.0, 0.0}});
  const ReachabilityParameters parameters;
  BodyData data(model);
  const IkResult result = solve_start(model, data, wall, parameters);
  EXPECT_FALSE(result.reached);
  EXPECT_EQ(result.posture, start_guess(model, wall, parameters.root)) << "Algorithm 1 returns G_init";
}

}  // namespace
}  // namespace crux
