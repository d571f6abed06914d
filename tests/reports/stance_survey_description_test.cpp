#include "reports/stance_survey_description.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace crux {
namespace {

// Two walls surveyed, one whose start was out of reach. Per wall: 10 stances, 8 held on
// four, 4 of them on three; 20 stances, 20 on four, 15 on three. Shares over the two
// walls: on four (0.8 + 1.0) / 2 = 0.9, sd 0.1414, half-width t(0.975, 1) x sd / sqrt 2
// = 12.706 x 0.1; on three of four (0.5 + 0.75) / 2 = 0.625, half-width 12.706 x 0.125;
// held (0.4 + 0.75) / 2 = 0.575, half-width 12.706 x 0.175.
StanceSurvey hand_built() {
  StanceSurvey survey;
  WallStances first{11, true, {10, 8, 4, {{"contacts", 1}, {"left_elbow_flexion", 1}}, {{"contacts", 3}, {"grip", 1}}}};
  WallStances second{12, true, {20, 20, 15, {}, {{"left_elbow_flexion", 5}}}};
  WallStances out_of_reach{13, false, {}};
  survey.walls = {first, second, out_of_reach};
  survey.total = {30,
                  28,
                  19,
                  {{"contacts", 1}, {"left_elbow_flexion", 1}},
                  {{"contacts", 3}, {"grip", 1}, {"left_elbow_flexion", 5}},
                  40,
                  3,
                  600,
                  7};
  return survey;
}

TEST(StanceSurveyDescription, JsonSharesAreMeansOverWallsWithTheirTIntervals) {
  StanceSurveyParameters parameters;
  parameters.wall_count = 3;
  parameters.walls.incline_deg = 40.0;
  const auto json = stance_survey_json(hand_built(), parameters);
  EXPECT_EQ(json["format"], "crux-stances");
  EXPECT_EQ(json["incline_deg"], 40.0);
  EXPECT_EQ(json["stances"], 30);
  constexpr double t = 12.7062047361747;
  EXPECT_NEAR(json["share_four_held"]["mean"].get<double>(), 0.9, 1e-12);
  EXPECT_NEAR(json["share_four_held"]["ci95_half_width"].get<double>(), t * 0.1, 1e-9);
  EXPECT_EQ(json["share_four_held"]["walls"], 2);
  EXPECT_NEAR(json["share_three_held_of_four_held"]["mean"].get<double>(), 0.625, 1e-12);
  EXPECT_NEAR(json["share_three_held_of_four_held"]["ci95_half_width"].get<double>(), t * 0.125, 1e-9);
  EXPECT_NEAR(json["share_held"]["mean"].get<double>(), 0.575, 1e-12);
  EXPECT_NEAR(json["share_held"]["ci95_half_width"].get<double>(), t * 0.175, 1e-9);
  // Most frequent first.
  auto three = json["three_failures"].begin();
  EXPECT_EQ(three.key(), "left_elbow_flexion");
  EXPECT_EQ(three.value(), 5);
  EXPECT_EQ((++three).key(), "contacts");
  EXPECT_EQ(json["path_samples_per_move"], 16);
  EXPECT_EQ(json["path_moves"], 40);
  EXPECT_EQ(json["path_moves_failing"], 3);
  EXPECT_EQ(json["path_samples_failing"], 7);
  EXPECT_EQ(json["walls"].size(), 3u);
  EXPECT_EQ(json["walls"][2]["start_reached"], false);
}

TEST(StanceSurveyDescription, TextGivesTheSharesAndTheReasons) {
  StanceSurveyParameters parameters;
  parameters.wall_count = 3;
  const std::string text = stance_survey_text(hand_built(), parameters);
  EXPECT_NE(text.find("30 distinct stances"), std::string::npos) << text;
  EXPECT_NE(text.find("1 with an unreachable start left out"), std::string::npos) << text;
  EXPECT_NE(text.find("held on four holds:              90.0 % +- 127.1 (mean over 2 walls"), std::string::npos)
      << text;
  EXPECT_NE(text.find("why 9 stances held on four fail on three"), std::string::npos) << text;
  EXPECT_NE(text.find("left_elbow_flexion                5  (55.6 %)"), std::string::npos) << text;
  EXPECT_NE(text.find("of 40 reached moves that start held on the three holds they keep, 3 (7.5 %) pass through a "
                      "posture that does not hold on them (7 of 600 samples, 1.2 %)"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace crux
