#include "common/config_field.hpp"

#include <gtest/gtest.h>

#include "common/progress_display.hpp"

namespace crux {
namespace {

TEST(ConfigField, BoundsSayWhatTheyAllow) {
  EXPECT_EQ(kPositive.summary(false), "> 0");
  EXPECT_EQ(kPositive.problem(false), "must be positive");
  EXPECT_EQ(kNonNegative.problem(false), "must be 0 or positive");
  EXPECT_EQ(work_size(1, 64).summary(true), "1 to 64");
  EXPECT_EQ(work_size(1, 64).problem(true), "must be from 1 to 64");
  EXPECT_EQ(kZeroToBelowOne.summary(false), "[0, 1)");
  EXPECT_EQ(kZeroToBelowOne.problem(false), "must be in [0, 1)");
  EXPECT_EQ(closed_range(0, 1, "a share").problem(false), "must be in [0, 1] (a share)");
  EXPECT_EQ(kAnyNumber.summary(false), "");
}

TEST(ConfigField, BoundsContainTheirClosedEndsOnly) {
  EXPECT_TRUE(kZeroToBelowOne.contains(0));
  EXPECT_FALSE(kZeroToBelowOne.contains(1));
  EXPECT_FALSE(kAboveZeroToOne.contains(0));
  EXPECT_TRUE(kAboveZeroToOne.contains(1));
  EXPECT_FALSE(kUnitInterval.contains(1.0000001));
}

TEST(ConfigField, TheHelpShownAddsTheUnitTheBoundsAndTheChoices) {
  double length = 1;
  const ConfigField field{"wall.tile_width", "Tile width", &length, "m", kTileSize};
  EXPECT_EQ(field.described_help(), "Tile width (m; [0.01, 10])");
  EXPECT_STREQ(field.type_name(), "number");
  ProgressDisplay progress = ProgressDisplay::Bar;
  const ConfigField choice{"output.progress", "Progress", choice_of(&progress)};
  EXPECT_EQ(choice.described_help(), "Progress (bar, lines or none)");
  EXPECT_STREQ(choice.type_name(), "choice");
  int count = 3;
  const ConfigField integer{"grid.rows", "Rows", &count, "", work_size(1, 1000)};
  EXPECT_TRUE(integer.is_integer());
  EXPECT_EQ(integer.described_help(), "Rows (1 to 1000)");
}

}  // namespace
}  // namespace crux
