#include "configurations/geometric_filter.hpp"

#include <gtest/gtest.h>

#include "support/test_walls.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

using testing::wall_with_holds;

// Holds: 0 right hand (0.3, 1.5), 1 left hand (0.9, 1.5), 2 right foot (0.3, 0),
// 3 left foot (0.9, 0), 4 far up (0.6, 3.0), 5 low middle (0.6, 0.8).
Wall six_holds() { return wall_with_holds({{0.3, 1.5}, {0.9, 1.5}, {0.3, 0.0}, {0.9, 0.0}, {0.6, 3.0}, {0.6, 0.8}}); }

HoldConfiguration config(int rh, int lh, int rf, int lf) {
  HoldConfiguration c;
  c.holds = {rh, lh, rf, lf};
  return c;
}

TEST(GeometricFilter, NaturalStancePasses) {
  EXPECT_TRUE(passes_filter(six_holds(), config(0, 1, 2, 3), FilterParameters{}));
}

TEST(GeometricFilter, SpanRuleUsesItsThreshold) {
  const Wall wall = six_holds();
  const HoldConfiguration c = config(4, 1, 2, 3);  // right hand 3.01 m from the right foot
  EXPECT_FALSE(span_within_reach(wall, c, 2.8));
  EXPECT_TRUE(span_within_reach(wall, c, 3.1));
  EXPECT_TRUE(span_within_reach(wall, config(kFree, 1, 2, 3), 2.8)) << "the free limb takes no part";
}

TEST(GeometricFilter, CrossedArmsAndLegs) {
  const Wall wall = six_holds();
  EXPECT_FALSE(arms_not_crossed(wall, config(1, 0, 2, 3)));
  EXPECT_TRUE(arms_not_crossed(wall, config(0, 1, 2, 3)));
  EXPECT_FALSE(legs_not_crossed(wall, config(0, 1, 3, 2)));
  EXPECT_TRUE(legs_not_crossed(wall, config(0, 1, kFree, 2)));
}

TEST(GeometricFilter, EachReadingOfFeetAboveHands) {
  const Wall wall = wall_with_holds({{0.3, 1.0}, {0.9, 2.0}, {0.3, 1.2}, {0.9, 1.4}, {0.3, 2.2}, {0.9, 2.4}});
  const HoldConfiguration feet_between = config(0, 1, 2, 3);  // hands 1.0 / 2.0, feet 1.2 / 1.4
  const HoldConfiguration feet_above = config(0, 1, 4, 5);    // feet 2.2 / 2.4 above both hands
  using R = FeetAboveHandsReading;
  EXPECT_FALSE(feet_not_above_hands(wall, feet_above, R::LowestFootAboveHighestHand));
  EXPECT_TRUE(feet_not_above_hands(wall, feet_between, R::LowestFootAboveHighestHand));
  EXPECT_FALSE(feet_not_above_hands(wall, feet_between, R::LowestFootAboveLowestHand));
  EXPECT_FALSE(feet_not_above_hands(wall, feet_between, R::HighestFootAboveLowestHand));
  EXPECT_TRUE(feet_not_above_hands(wall, feet_between, R::MeanFeetAboveMeanHands));         // 1.3 < 1.5
  EXPECT_FALSE(feet_not_above_hands(wall, config(0, 1, 2, 5), R::MeanFeetAboveMeanHands));  // 1.8 > 1.5
}

TEST(GeometricFilter, ReadingsParseByName) {
  for (const auto reading : kFeetAboveHandsReadings)
    EXPECT_EQ(parse_enum<FeetAboveHandsReading>(enum_name(reading)), reading);
  EXPECT_FALSE(parse_enum<FeetAboveHandsReading>("feet-anywhere").has_value());
}

}  // namespace
}  // namespace crux
