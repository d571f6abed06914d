#include "experiments/stance_survey.hpp"

#include <gtest/gtest.h>

#include "support/test_models.hpp"

namespace crux {
namespace {

StanceSurveyParameters small_survey() {
  StanceSurveyParameters parameters;
  parameters.wall_seed = 5;
  parameters.wall_count = 4;
  parameters.moves = 80;
  parameters.climbing.physics.model = PhysicsModel::Static;
  parameters.climbing.reachability.ik.wall = WallRule::Avoid;
  return parameters;
}

int sum(const std::map<std::string, int>& failures) {
  int total = 0;
  for (const auto& [name, count] : failures) total += count;
  return total;
}

// Every stance is held, or fails on four holds, or holds on four and fails on three, for
// one named reason; the total is the walls' sum; walls without a reachable start count
// nothing. The same parameters give the same survey.
TEST(StanceSurvey, EveryStanceIsCountedOnceWithOneReason) {
  const BodyModel& model = testing::human_model();
  const StanceSurveyParameters parameters = small_survey();
  int progress_calls = 0;
  const StanceSurvey survey = survey_stances(model, parameters, [&](int done) { EXPECT_EQ(done, ++progress_calls); });
  EXPECT_EQ(progress_calls, parameters.wall_count);
  ASSERT_EQ(survey.walls.size(), 4u);
  StanceTally sums;
  for (const WallStances& wall : survey.walls) {
    const StanceTally& t = wall.tally;
    if (!wall.start_reached) {
      EXPECT_EQ(t.stances, 0);
    }
    EXPECT_EQ(t.four_held + sum(t.four_failures), t.stances) << "wall " << wall.seed;
    EXPECT_EQ(t.three_held + sum(t.three_failures), t.four_held) << "wall " << wall.seed;
    EXPECT_LE(t.stances, parameters.moves);
    sums.stances += t.stances;
    sums.four_held += t.four_held;
    sums.three_held += t.three_held;
  }
  // The replay's 16 samples a move, the last being the new stance (checked as one):
  // 15 checked per move; a move fails when one of them does.
  const StanceTally& total = survey.total;
  EXPECT_EQ(total.path_samples, 15 * total.path_moves);
  EXPECT_GT(total.path_moves, 20);
  EXPECT_LE(total.path_moves_failing, total.path_samples_failing);
  EXPECT_LE(total.path_samples_failing, 15 * total.path_moves_failing);
  EXPECT_EQ(survey.total.stances, sums.stances);
  EXPECT_EQ(survey.total.four_held, sums.four_held);
  EXPECT_EQ(survey.total.three_held, sums.three_held);
  EXPECT_GT(survey.total.stances, 50);
  EXPECT_GT(survey.total.three_held, 0);
  EXPECT_GT(sum(survey.total.three_failures), 0);
  for (const auto& [name, count] : survey.total.three_failures) {
    EXPECT_TRUE(name == "contacts" || name == "grip" || name.find('_') != std::string::npos) << name;
  }
  const StanceSurvey again = survey_stances(model, parameters);
  for (std::size_t i = 0; i < survey.walls.size(); ++i) {
    EXPECT_EQ(again.walls[i].tally.three_failures, survey.walls[i].tally.three_failures);
    EXPECT_EQ(again.walls[i].tally.four_held, survey.walls[i].tally.four_held);
  }
}

// The stances are the same whatever the physics (the walk is kinematic); more friction
// only widens the cones and a weaker grip only narrows them, so on every wall the
// first holds at least as many stances and the second at most as many, and the grip's
// failures appear only under the weaker grip.
TEST(StanceSurvey, FrictionAndGripMoveTheVerdictsTheWayTheConesDo) {
  const BodyModel& model = testing::human_model();
  const StanceSurveyParameters base = small_survey();
  StanceSurveyParameters sticky = base, weak = base;
  sticky.climbing.physics.friction = 5.0;
  weak.climbing.physics.grip = 150.0;
  const StanceSurvey with_base = survey_stances(model, base);
  const StanceSurvey with_sticky = survey_stances(model, sticky);
  const StanceSurvey with_weak = survey_stances(model, weak);
  for (std::size_t i = 0; i < with_base.walls.size(); ++i) {
    const StanceTally& b = with_base.walls[i].tally;
    EXPECT_EQ(with_sticky.walls[i].tally.stances, b.stances);
    EXPECT_GE(with_sticky.walls[i].tally.four_held, b.four_held) << "wall " << i;
    EXPECT_GE(with_sticky.walls[i].tally.three_held, b.three_held) << "wall " << i;
    EXPECT_LE(with_weak.walls[i].tally.four_held, b.four_held) << "wall " << i;
    EXPECT_LE(with_weak.walls[i].tally.three_held, b.three_held) << "wall " << i;
  }
  EXPECT_GT(with_sticky.total.three_held, with_base.total.three_held);
  EXPECT_LT(with_weak.total.three_held, with_base.total.three_held);
  EXPECT_EQ(with_base.total.four_failures.count("grip") + with_base.total.three_failures.count("grip"), 0u);
  EXPECT_GT(with_weak.total.four_failures.count("grip") + with_weak.total.three_failures.count("grip"), 0u);
}

TEST(StanceSurvey, FailureNames) {
  EXPECT_EQ(stance_failure_name(StanceVerdict::Grip, "x"), "grip");
  EXPECT_EQ(stance_failure_name(StanceVerdict::Contacts, "x"), "contacts");
  EXPECT_EQ(stance_failure_name(StanceVerdict::Joint, "left_elbow_flexion"), "left_elbow_flexion");
}

}  // namespace
}  // namespace crux
