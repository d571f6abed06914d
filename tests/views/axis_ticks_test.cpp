#include "views/axis_ticks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace crux {
namespace {

TEST(AxisTicksTest, NiceTicksCoverTheRangeWithOneTwoFiveSteps) {
  const Ticks iterations = nice_ticks(0, 8000, 5);
  EXPECT_DOUBLE_EQ(iterations.step, 2000);
  EXPECT_EQ(iterations.values, (std::vector<double>{0, 2000, 4000, 6000, 8000}));

  // Step 1 needs 12 intervals and 2 needs 6, more than 5: step 5, from -5 to 10.
  const Ticks mixed = nice_ticks(-3.2, 7.9, 5);
  EXPECT_DOUBLE_EQ(mixed.step, 5);
  EXPECT_EQ(mixed.values, (std::vector<double>{-5, 0, 5, 10}));
  EXPECT_DOUBLE_EQ(mixed.low, -5);
  EXPECT_DOUBLE_EQ(mixed.high, 10);

  const Ticks small = nice_ticks(0.013, 0.049, 4);
  EXPECT_DOUBLE_EQ(small.step, 0.01);
  ASSERT_EQ(small.values.size(), 5u);
  EXPECT_NEAR(small.values.front(), 0.01, 1e-15);
  EXPECT_NEAR(small.values.back(), 0.05, 1e-15);
}

TEST(AxisTicksTest, NiceTicksWidenAnEmptyRangeAndRefuseNonFiniteOnes) {
  const Ticks single = nice_ticks(3, 3, 5);
  EXPECT_LT(single.low, 3);
  EXPECT_GT(single.high, 3);
  const Ticks zero = nice_ticks(0, 0, 4);
  EXPECT_LT(zero.low, 0);
  EXPECT_GT(zero.high, 0);
  EXPECT_THROW(nice_ticks(0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(nice_ticks(std::nan(""), 1), std::invalid_argument);
}

TEST(AxisTicksTest, TickLabelsUseTheStepsDecimalsAndSuffixesForLargeValues) {
  EXPECT_EQ(tick_label(2000, 2000, 8000), "2000");
  EXPECT_EQ(tick_label(0.5, 0.1, 1), "0.5");
  EXPECT_EQ(tick_label(-0.2, 0.1, 1), "-0.2");
  EXPECT_EQ(tick_label(0.05, 0.05, 0.2), "0.05");
  EXPECT_EQ(tick_label(3 * 0.1, 0.1, 1), "0.3");  // not 0.30000000000000004
  EXPECT_EQ(tick_label(200000, 200000, 1e6), "0.2M");
  EXPECT_EQ(tick_label(1e6, 200000, 1e6), "1.0M");
  EXPECT_EQ(tick_label(-5000, 5000, 2e5), "-5k");
  EXPECT_EQ(tick_label(1e-17, 0.1, 1), "0");
  EXPECT_EQ(tick_label(-0.0, 1, 1), "0");
}

// Half a metre between metre lines while they stay 30 pixels apart, doubled otherwise.
TEST(AxisTicksTest, MetreLinesStayThirtyPixelsApart) {
  EXPECT_DOUBLE_EQ(metre_tick_spacing(60), 0.5);  // 30 px apart: the finest spacing
  EXPECT_DOUBLE_EQ(metre_tick_spacing(59), 1.0);  // 29.5 px: doubled once
  EXPECT_DOUBLE_EQ(metre_tick_spacing(30), 1.0);
  EXPECT_DOUBLE_EQ(metre_tick_spacing(29), 2.0);
  EXPECT_DOUBLE_EQ(metre_tick_spacing(1), 32.0);  // 16 px at 16 m, 32 px at 32 m
}

TEST(AxisTicksTest, MetreTicksAreTheMultiplesOfTheSpacingInTheRange) {
  EXPECT_EQ(metre_ticks(-0.3, 1.2, 0.5), (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(metre_ticks(-1, 1, 1), (std::vector<double>{-1, 0, 1}));  // the bounds are in
  EXPECT_EQ(metre_ticks(3, 3.5, 2), std::vector<double>{});           // none between
  // Each is k * spacing, not a running sum that drifts.
  const std::vector<double> fine = metre_ticks(0, 30, 0.1);
  ASSERT_EQ(fine.size(), 301u);
  EXPECT_EQ(fine[3], 3 * 0.1);
}

TEST(AxisTicksTest, MetreLabelsHaveOneDecimalAndNoNegativeZero) {
  EXPECT_EQ(metre_tick_label(1.5), "1.5");
  EXPECT_EQ(metre_tick_label(-2), "-2.0");
  EXPECT_EQ(metre_tick_label(-0.0), "0.0");
  EXPECT_EQ(metre_tick_label(-1 * 0.0), "0.0");
}

}  // namespace
}  // namespace crux
