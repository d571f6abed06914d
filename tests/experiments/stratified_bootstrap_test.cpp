#include "experiments/stratified_bootstrap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace crux {
namespace {

TEST(StratifiedBootstrap, InterquartileMeanIsScipysTrimMean) {
  // The expected values are scipy.stats.trim_mean(x, 0.25) (scipy 1.10, Debian's
  // /usr/bin/python3): int(0.25 n) values cut at each end, no fractional trimming.
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{1, 2, 3}), 2.0);                 // n = 3: nothing cut
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{4, 1, 3, 2}), 2.5);              // n = 4: one each end
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{5, 1, 4, 2, 3}), 3.0);           // n = 5: one each end
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{1, 2, 3, 4, 5, 100}), 3.5);      // n = 6: (2+3+4+5)/4
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{7, 1, 2, 9, 3, 8, 4}), 4.8);     // n = 7: (2+3+4+7+8)/5
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}), 4.5);  // n = 8: two each end
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{10, 2, 2, 3, 1}), 7.0 / 3.0);    // ties: (2+2+3)/3
  EXPECT_DOUBLE_EQ(interquartile_mean(std::vector<double>{42}), 42.0);
  EXPECT_TRUE(std::isnan(interquartile_mean(std::vector<double>{})));
}

TEST(StratifiedBootstrap, TrimmedMeanCutsWholeValuesOnly) {
  // scipy.stats.trim_mean(x, 0.1): 10 values lose one at each end, 9 values none.
  EXPECT_DOUBLE_EQ(trimmed_mean(std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 100}, 0.1), 5.5);
  EXPECT_DOUBLE_EQ(trimmed_mean(std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 100}, 0.1), 136.0 / 9.0);
  EXPECT_DOUBLE_EQ(trimmed_mean(std::vector<double>{3, 1, 2}, 0.0), 2.0);
}

TEST(StratifiedBootstrap, StrataInOrderOfFirstAppearance) {
  const Strata strata = strata_of({7, 3, 7, 3, 9});
  EXPECT_EQ(strata.order, (std::vector<std::size_t>{0, 2, 1, 3, 4}));
  EXPECT_EQ(strata.starts, (std::vector<std::size_t>{0, 2, 4, 5}));
}

TEST(StratifiedBootstrap, ProbabilityOfImprovementOnTwoWallsWithTies) {
  // Wall 0: x {1, 3} against y {2, 3}; wall 1: x {4, 6, 5} against y {5, 5, 5}.
  // Lower is better. Wall 0: 1 < 2 and 1 < 3 win, 3 > 2 loses, 3 = 3 ties: 2.5 / 4.
  // Wall 1: 4 wins thrice, 6 loses thrice, 5 ties thrice: 4.5 / 9. Mean 0.5625, as
  // rliable's (scipy's mannwhitneyu U / (m n) per task, then the mean over tasks).
  const std::vector<double> x{1, 3, 4, 6, 5}, y{2, 3, 5, 5, 5};
  const std::vector<std::size_t> starts{0, 2, 5};
  EXPECT_DOUBLE_EQ(probability_of_improvement(x, y, starts, false), 0.5625);
  // Higher is better: wall 0 gives 1.5 / 4, wall 1 still 4.5 / 9.
  EXPECT_DOUBLE_EQ(probability_of_improvement(x, y, starts, true), 0.4375);
  // A wall where both are the same counts 1/2 whatever the direction.
  EXPECT_DOUBLE_EQ(probability_of_improvement(std::vector<double>{2, 8}, std::vector<double>{2, 8},
                                              std::vector<std::size_t>{0, 2}, false),
                   0.5);
}

TEST(StratifiedBootstrap, SameStreamSameIntervalOtherStreamOtherDraws) {
  const std::vector<std::size_t> starts{0, 4, 8};
  const std::vector<double> values{1, 5, 2, 8, 3, 9, 4, 7};
  const auto mean = [&](std::span<const std::size_t> positions) {
    double sum = 0.0;
    for (const std::size_t p : positions) sum += values[p];
    return sum / static_cast<double>(positions.size());
  };
  const BootstrapEstimate first = StratifiedBootstrap(starts, RandomStream(11, "test"), 500).estimate(mean);
  const BootstrapEstimate again = StratifiedBootstrap(starts, RandomStream(11, "test"), 500).estimate(mean);
  const BootstrapEstimate other = StratifiedBootstrap(starts, RandomStream(12, "test"), 500).estimate(mean);
  EXPECT_EQ(first.low, again.low);
  EXPECT_EQ(first.high, again.high);
  EXPECT_EQ(first.value, other.value);
  EXPECT_TRUE(first.low != other.low || first.high != other.high);
}

TEST(StratifiedBootstrap, IntervalContainsTheEstimateAndDrawsStayInTheirStratum) {
  const std::vector<std::size_t> starts{0, 3, 6, 9};
  const std::vector<double> values{1, 4, 9, 2, 2, 7, 10, 3, 5};
  const StratifiedBootstrap bootstrap(starts, RandomStream(3, "test"), 2000);
  const BootstrapEstimate iqm = bootstrap.estimate([&](std::span<const std::size_t> positions) {
    std::vector<double> drawn;
    for (const std::size_t p : positions) drawn.push_back(values[p]);
    return interquartile_mean(drawn);
  });
  EXPECT_DOUBLE_EQ(iqm.value, interquartile_mean(values));
  EXPECT_LT(iqm.low, iqm.value);
  EXPECT_GT(iqm.high, iqm.value);
  // Every slot of stratum k is drawn from stratum k: no replicate counts a stray draw.
  const BootstrapEstimate strays = bootstrap.estimate([&](std::span<const std::size_t> positions) {
    int stray = 0;
    for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
      for (std::size_t i = starts[k]; i < starts[k + 1]; ++i)
        stray += positions[i] < starts[k] || positions[i] >= starts[k + 1];
    }
    return static_cast<double>(stray);
  });
  EXPECT_EQ(strays.high, 0.0);
}

TEST(StratifiedBootstrap, ASingleValuedStratumContributesNoWidth) {
  // Stratum 0 holds one value: every replicate keeps it, so a statistic of it alone has
  // a zero-width interval, while stratum 1's resampling still moves the total.
  const std::vector<std::size_t> starts{0, 1, 4};
  const std::vector<double> values{5, 1, 2, 30};
  const StratifiedBootstrap bootstrap(starts, RandomStream(5, "test"), 2000);
  const BootstrapEstimate alone = bootstrap.estimate([&](std::span<const std::size_t> p) { return values[p[0]]; });
  EXPECT_EQ(alone.low, 5.0);
  EXPECT_EQ(alone.high, 5.0);
  const BootstrapEstimate sum = bootstrap.estimate(
      [&](std::span<const std::size_t> p) { return values[p[0]] + values[p[1]] + values[p[2]] + values[p[3]]; });
  EXPECT_LT(sum.low, sum.high);
}

TEST(StratifiedBootstrap, ComparisonOfPairedRuns) {
  // Two walls of three seeds each, pairs listed wall by wall alternately.
  const std::vector<double> transfer{10, 20, 12, 25, 11, 22}, control{14, 21, 13, 24, 19, 30};
  const std::vector<std::size_t> wall{0, 1, 0, 1, 0, 1};
  const StratifiedComparison c = stratified_comparison(transfer, control, wall, false, RandomStream(1, "test"));
  EXPECT_DOUBLE_EQ(c.iqm_a.value, interquartile_mean(transfer));
  EXPECT_DOUBLE_EQ(c.iqm_b.value, interquartile_mean(control));
  // Differences -4, -1, -1, +1, -8, -8, sorted -8, -8, -4, -1, -1, +1: the IQM keeps the
  // middle four, -8, -4, -1, -1: -3.5.
  EXPECT_DOUBLE_EQ(c.iqm_difference.value, -3.5);
  // Wall 0 (lower better): transfer {10, 12, 11} against control {14, 13, 19}: all 9 win.
  // Wall 1: {20, 25, 22} against {21, 24, 30}: 20 beats 3, 25 beats 1, 22 beats 2: 6 / 9.
  EXPECT_DOUBLE_EQ(c.probability_of_improvement.value, (1.0 + 6.0 / 9.0) / 2.0);
  for (const BootstrapEstimate& e : {c.iqm_a, c.iqm_b, c.iqm_difference, c.probability_of_improvement}) {
    EXPECT_LE(e.low, e.value);
    EXPECT_GE(e.high, e.value);
  }
  EXPECT_LT(c.iqm_difference.low, c.iqm_difference.high);
  EXPECT_TRUE(c.has_intervals);
  // One seed per wall: nothing to resample within a wall. The estimates stand, without an
  // interval rather than with one of zero width.
  const StratifiedComparison single =
      stratified_comparison({1, 5, 2}, {3, 4, 2}, {0, 1, 2}, true, RandomStream(1, "test"));
  EXPECT_FALSE(single.has_intervals);
  EXPECT_DOUBLE_EQ(single.iqm_difference.value, -1.0 / 3.0);
  // Wall 0: 1 < 3 loses, wall 1: 5 > 4 wins, wall 2: a tie: (0 + 1 + 1/2) / 3.
  EXPECT_DOUBLE_EQ(single.probability_of_improvement.value, 0.5);
  for (const BootstrapEstimate& e :
       {single.iqm_a, single.iqm_b, single.iqm_difference, single.probability_of_improvement}) {
    EXPECT_TRUE(std::isnan(e.low) && std::isnan(e.high));
  }
  // One wall of two seeds is enough to resample.
  const StratifiedComparison mixed =
      stratified_comparison({1, 5, 2}, {3, 4, 2}, {0, 1, 1}, true, RandomStream(1, "test"));
  EXPECT_TRUE(mixed.has_intervals);
  EXPECT_LE(mixed.iqm_difference.low, mixed.iqm_difference.high);
}

}  // namespace
}  // namespace crux
