#include "experiments/statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace crux {
namespace {

TEST(Statistics, StudentTAgainstPublishedTables) {
  // Two-sided 95 % critical values from standard t tables.
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.7062, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 5), 2.5706, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 9), 2.262157, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.975, 29), 2.0452, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.995, 9), 3.249836, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.95, 9), 1.833113, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.8, 9), 0.883404, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.025, 9), -2.262157, 1e-6) << "symmetric about 0";
  EXPECT_NEAR(student_t_cdf(0.0, 7), 0.5, 1e-15);
  EXPECT_NEAR(student_t_cdf(2.0, 10), 0.963306, 1e-6);  // tables: 1 - 0.036694
  EXPECT_NEAR(student_t_cdf(-2.0, 10), 0.036694, 1e-6);
  EXPECT_NEAR(student_t_cdf(2.262157, 9), 0.975, 1e-6);
}

TEST(Statistics, StudentTAgainstClosedForms) {
  // With 1 degree of freedom t is Cauchy: cdf(t) = 1/2 + atan(t) / pi, so the 0.975
  // quantile is tan(0.475 pi). With 2: cdf(t) = 1/2 + t / (2 sqrt(2 + t^2)), whose
  // inverse gives the quantile (2p - 1) / sqrt(2 p (1 - p)) = 0.95 / sqrt(0.04875).
  EXPECT_NEAR(student_t_quantile(0.975, 1), std::tan(0.475 * M_PI), 1e-13);
  EXPECT_NEAR(student_t_quantile(0.975, 2), 0.95 / std::sqrt(0.04875), 1e-14);
  for (const double t : {-7.5, -1.0, 0.3, 2.0, 40.0}) {
    EXPECT_NEAR(student_t_cdf(t, 1), 0.5 + std::atan(t) / M_PI, 1e-15) << t;
    EXPECT_NEAR(student_t_cdf(t, 2), 0.5 + t / (2.0 * std::sqrt(2.0 + t * t)), 1e-15) << t;
  }
}

TEST(Statistics, SmallPValuesKeepTheirDigits) {
  // Differences 1 - 1e-6 and 1 + 1e-6: t is about 1e6 with 1 degree of freedom, where the
  // two-sided p is 2 atan(1 / t) / pi, about 6.4e-7. Computed as 1 - cdf(t) it would keep
  // only its first 9 or 10 digits; the upper tail itself keeps them all.
  const PairedTest test = paired_t_test({1.0 - 1e-6, 1.0 + 1e-6}, {0.0, 0.0});
  EXPECT_NEAR(test.t, 1e6, 1.0);
  const double expected = 2.0 * std::atan(1.0 / test.t) / M_PI;
  EXPECT_NEAR(test.p_value / expected, 1.0, 1e-13);
}

TEST(Statistics, NaNInTheDataGivesNaNStatisticsNotAnException) {
  const double nan = std::nan("");
  const PairedTest test = paired_t_test({1.0, nan, 3.0}, {0.0, 0.0, 0.0});
  EXPECT_TRUE(std::isnan(test.t));
  EXPECT_TRUE(std::isnan(test.p_value));
  EXPECT_TRUE(std::isnan(test.difference.half_width));
  EXPECT_TRUE(std::isnan(student_t_cdf(nan, 4)));
}

TEST(Statistics, MeanIntervalByHand) {
  // mean 3, sample sd sqrt(2.5), half-width t(0.975, 4) * sd / sqrt(5) = 2.7764 * 0.7071.
  const MeanInterval m = mean_interval({1, 2, 3, 4, 5});
  EXPECT_DOUBLE_EQ(m.mean, 3.0);
  EXPECT_NEAR(m.standard_deviation, std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(m.half_width, 2.776445 * std::sqrt(2.5) / std::sqrt(5.0), 1e-5);
}

TEST(Statistics, PairedTestByHand) {
  // Differences 1, 2, 3: mean 2, sd 1, t = 2 / (1 / sqrt 3) = 3.4641, two-sided p with
  // 2 degrees of freedom = 0.07418.
  const PairedTest test = paired_t_test({11, 12, 13}, {10, 10, 10});
  EXPECT_NEAR(test.t, 3.464102, 1e-6);
  EXPECT_NEAR(test.p_value, 0.074180, 1e-5);
  EXPECT_DOUBLE_EQ(paired_t_test({1, 2}, {1, 2}).p_value, 1.0);
}

TEST(Statistics, PearsonCorrelationByHand) {
  // a = 1..4 (mean 2.5, deviations -1.5 -0.5 0.5 1.5), b = 2 4 5 9 (mean 5, deviations
  // -3 -1 0 4): sum of products 4.5 + 0.5 + 0 + 6 = 11, sums of squares 5 and 26,
  // r = 11 / sqrt(130) = 0.9647638.
  EXPECT_NEAR(pearson_correlation({1, 2, 3, 4}, {2, 4, 5, 9}), 0.9647638, 1e-7);
  // Symmetric in its arguments.
  EXPECT_NEAR(pearson_correlation({2, 4, 5, 9}, {1, 2, 3, 4}), 0.9647638, 1e-7);
  // An exact decreasing line b = 3 - 2a: r = -1.
  EXPECT_DOUBLE_EQ(pearson_correlation({0, 1, 2, 5}, {3, 1, -1, -7}), -1.0);
  // Scale and shift do not change r: b' = 10 b - 7.
  EXPECT_NEAR(pearson_correlation({1, 2, 3, 4}, {13, 33, 43, 83}), 0.9647638, 1e-7);
}

TEST(Statistics, PearsonCorrelationUndefinedIsNaN) {
  EXPECT_TRUE(std::isnan(pearson_correlation({}, {})));
  EXPECT_TRUE(std::isnan(pearson_correlation({1}, {2})));                 // fewer than 2 pairs
  EXPECT_TRUE(std::isnan(pearson_correlation({3, 3, 3}, {1, 2, 4})));     // a has no variance
  EXPECT_TRUE(std::isnan(pearson_correlation({1, 2, 4}, {-2, -2, -2})));  // b has no variance
  EXPECT_FALSE(std::isnan(pearson_correlation({1, 2}, {2, 1})));          // 2 pairs suffice: r = -1
  EXPECT_DOUBLE_EQ(pearson_correlation({1, 2}, {2, 1}), -1.0);
}

TEST(Statistics, PercentileIsNumpyType7) {
  // h = (n - 1) q, then linear interpolation between x[floor h] and x[floor h + 1].
  const std::vector<double> x{1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(percentile(x, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(x, 0.25), 1.75);  // h = 0.75: 1 + 0.75 (2 - 1)
  EXPECT_DOUBLE_EQ(percentile(x, 0.5), 2.5);    // h = 1.5: 2 + 0.5 (3 - 2)
  EXPECT_NEAR(percentile(x, 0.9), 3.7, 1e-12);  // h = 2.7: 3 + 0.7 (4 - 3)
  EXPECT_DOUBLE_EQ(percentile(x, 1.0), 4.0);
  const std::vector<double> y{10, 20, 40};
  EXPECT_DOUBLE_EQ(percentile(y, 0.25), 15.0);     // h = 0.5: 10 + 0.5 (20 - 10)
  EXPECT_NEAR(percentile(y, 0.8), 32.0, 1e-12);    // h = 1.6: 20 + 0.6 (40 - 20)
  EXPECT_NEAR(percentile(y, 0.025), 10.5, 1e-12);  // h = 0.05: 10 + 0.05 (20 - 10)
  EXPECT_DOUBLE_EQ(percentile(std::vector<double>{7}, 0.3), 7.0);
}

// Three walls with two run pairs each, listed interleaved (ids 7 3 7 9 3 9).
// Differences a - b: wall 7: 1, 3 (mean 2); wall 3: 0, 2 (mean 1); wall 9: 4, 2 (mean 3).
const std::vector<double> kWallA{6, 7, 5, 10, 3, 5};
const std::vector<double> kWallB{5, 7, 2, 6, 1, 3};
const std::vector<std::size_t> kWallIds{7, 3, 7, 9, 3, 9};

TEST(Statistics, ClusterMeansInOrderOfFirstAppearance) {
  // Walls 7 3 7 9 3 9 with values 1 0 3 4 2 2: wall 7 (1 + 3) / 2 = 2, wall 3 (0 + 2) / 2
  // = 1, wall 9 (4 + 2) / 2 = 3, listed as first seen: 7, 3, 9.
  EXPECT_EQ(cluster_means({1, 0, 3, 4, 2, 2}, {7, 3, 7, 9, 3, 9}), (std::vector<double>{2, 1, 3}));
  EXPECT_EQ(cluster_means({5, 1, 2}, {1, 0, 0}), (std::vector<double>{5, 1.5}));
  EXPECT_TRUE(cluster_means({}, {}).empty());
}

TEST(Statistics, ClusteredDifferenceByHand) {
  // Cluster means 2, 1, 3: mean 2, sd 1, t = 2 / (1 / sqrt 3) = 3.4641, two-sided p with
  // 2 df = 0.07418 (as in PairedTestByHand), half-width t(0.975, 2) / sqrt 3 =
  // 4.302653 / 1.732051 = 2.484138.
  const ClusteredDifference d = clustered_paired_difference(kWallA, kWallB, kWallIds, 1);
  EXPECT_EQ(d.clusters, 3);
  EXPECT_EQ(d.pairs, 6);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  EXPECT_NEAR(d.standard_deviation, 1.0, 1e-12);
  EXPECT_NEAR(d.t, 3.464102, 1e-6);
  EXPECT_NEAR(d.p_value, 0.074180, 1e-5);
  EXPECT_NEAR(d.t_low, 2.0 - 2.484138, 1e-5);
  EXPECT_NEAR(d.t_high, 2.0 + 2.484138, 1e-5);
  // Bootstrap means of 3 draws from {1, 2, 3}: the smallest, 1, needs all three draws on
  // wall 3 (probability 1/27 = 3.7 % > 2.5 %), the largest, 3, likewise, so with 10000
  // resamples (about 370 of each, sd 19) the type-7 percentiles at ranks 249.975 and
  // 9749.025 are exactly 1 and 3. Resampling single pairs instead would reach 0 and 4.
  EXPECT_DOUBLE_EQ(d.bootstrap_low, 1.0);
  EXPECT_DOUBLE_EQ(d.bootstrap_high, 3.0);
}

TEST(Statistics, ClusteredDifferenceWeighsClustersEqually) {
  // Wall 0 has three pairs with difference 0, wall 1 one pair with difference 4: cluster
  // means 0 and 4, so the mean is 2 (pooling the pairs would give 1). sd = sqrt(8),
  // t = 2 / (sqrt 8 / sqrt 2) = 1 with 1 df (Cauchy): p = P(|T| > 1) = 0.5. Half-width
  // t(0.975, 1) sqrt 8 / sqrt 2 = 12.706205 * 2 = 25.41241.
  const ClusteredDifference d = clustered_paired_difference({1, 2, 3, 9}, {1, 2, 3, 5}, {0, 0, 0, 1}, 5);
  EXPECT_EQ(d.clusters, 2);
  EXPECT_EQ(d.pairs, 4);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  EXPECT_NEAR(d.standard_deviation, std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(d.t, 1.0, 1e-12);
  EXPECT_NEAR(d.p_value, 0.5, 1e-9);
  EXPECT_NEAR(d.t_low, 2.0 - 25.41241, 1e-4);
  EXPECT_NEAR(d.t_high, 2.0 + 25.41241, 1e-4);
  // Bootstrap of 2 clusters {0, 4}: draws give 0 (1/4), 2 (1/2) or 4 (1/4): percentiles
  // 2.5 % and 97.5 % are 0 and 4.
  EXPECT_DOUBLE_EQ(d.bootstrap_low, 0.0);
  EXPECT_DOUBLE_EQ(d.bootstrap_high, 4.0);
}

TEST(Statistics, ClusteredDifferenceOrdersClustersByFirstAppearance) {
  // Relabelling the walls while keeping their order of first appearance changes nothing,
  // not even the bootstrap (draw k still means the same wall).
  const ClusteredDifference d = clustered_paired_difference(kWallA, kWallB, kWallIds, 42, 2000);
  const ClusteredDifference e = clustered_paired_difference(kWallA, kWallB, {0, 1, 0, 2, 1, 2}, 42, 2000);
  EXPECT_EQ(d.mean, e.mean);
  EXPECT_EQ(d.t, e.t);
  EXPECT_EQ(d.bootstrap_low, e.bootstrap_low);
  EXPECT_EQ(d.bootstrap_high, e.bootstrap_high);
  // Merging walls 7 and 3 into one cluster does change the result: means (1+0+3+2)/4 = 1.5
  // and 3, mean 2.25.
  EXPECT_DOUBLE_EQ(clustered_paired_difference(kWallA, kWallB, {7, 7, 7, 9, 7, 9}, 42).mean, 2.25);
}

TEST(Statistics, ClusteredDifferenceWithOnePairPerClusterIsThePairedTest) {
  const std::vector<double> a{3.1, 4.7, 2.2, 5.9, 4.4};
  const std::vector<double> b{2.0, 4.9, 1.1, 4.0, 3.3};
  const PairedTest paired = paired_t_test(a, b);
  const ClusteredDifference d = clustered_paired_difference(a, b, {4, 2, 0, 1, 3}, 3);
  EXPECT_EQ(d.clusters, 5);
  EXPECT_EQ(d.pairs, 5);
  EXPECT_DOUBLE_EQ(d.mean, paired.difference.mean);
  EXPECT_DOUBLE_EQ(d.standard_deviation, paired.difference.standard_deviation);
  EXPECT_DOUBLE_EQ(d.t, paired.t);
  EXPECT_DOUBLE_EQ(d.p_value, paired.p_value);
  EXPECT_DOUBLE_EQ(d.t_low, paired.difference.mean - paired.difference.half_width);
  EXPECT_DOUBLE_EQ(d.t_high, paired.difference.mean + paired.difference.half_width);
  // And the shared values are not trivial: differences 1.1 -0.2 1.1 1.9 1.1, mean 1.0.
  EXPECT_NEAR(d.mean, 1.0, 1e-12);
  EXPECT_GT(d.t, 0.0);
  EXPECT_LT(d.p_value, 1.0);
}

TEST(Statistics, ClusteredDifferenceWithoutSpread) {
  // One wall: no between-wall spread to estimate, intervals collapse to the mean, p = 1.
  // Differences 4 5 6, mean 5.
  const ClusteredDifference one = clustered_paired_difference({5, 6, 7}, {1, 1, 1}, {2, 2, 2}, 9);
  EXPECT_EQ(one.clusters, 1);
  EXPECT_EQ(one.pairs, 3);
  EXPECT_DOUBLE_EQ(one.mean, 5.0);
  EXPECT_DOUBLE_EQ(one.standard_deviation, 0.0);
  EXPECT_DOUBLE_EQ(one.t_low, 5.0);
  EXPECT_DOUBLE_EQ(one.t_high, 5.0);
  EXPECT_DOUBLE_EQ(one.bootstrap_low, 5.0);
  EXPECT_DOUBLE_EQ(one.bootstrap_high, 5.0);
  EXPECT_DOUBLE_EQ(one.t, 0.0);
  EXPECT_DOUBLE_EQ(one.p_value, 1.0);

  const ClusteredDifference none = clustered_paired_difference({}, {}, {}, 9);
  EXPECT_EQ(none.clusters, 0);
  EXPECT_EQ(none.pairs, 0);
  EXPECT_DOUBLE_EQ(none.mean, 0.0);
  EXPECT_DOUBLE_EQ(none.p_value, 1.0);

  // Two walls with the same mean difference 1.5 (differences 1, 2 and 2, 1): sd 0 and a
  // nonzero mean, handled as paired_t_test does: t = +inf, p = 0.
  const ClusteredDifference flat = clustered_paired_difference({2, 3, 3, 2}, {1, 1, 1, 1}, {0, 0, 1, 1}, 9);
  const PairedTest flat_paired = paired_t_test({1.5, 1.5}, {0, 0});
  EXPECT_DOUBLE_EQ(flat.mean, 1.5);
  EXPECT_TRUE(std::isinf(flat.t) && flat.t > 0);
  EXPECT_EQ(flat.t, flat_paired.t);
  EXPECT_DOUBLE_EQ(flat.p_value, 0.0);
  EXPECT_DOUBLE_EQ(flat.bootstrap_low, 1.5);
  EXPECT_DOUBLE_EQ(flat.bootstrap_high, 1.5);
}

TEST(Statistics, ClusterBootstrapIsDeterministicAndPlausible) {
  // Ten walls, one pair each, differences 1..10: cluster means 1..10, mean 5.5.
  std::vector<double> a, b;
  std::vector<std::size_t> ids;
  for (int k = 1; k <= 10; ++k) {
    a.push_back(k + 0.5 * k * k);
    b.push_back(0.5 * k * k);
    ids.push_back(static_cast<std::size_t>(100 - k));
  }
  const ClusteredDifference d = clustered_paired_difference(a, b, ids, 2024);
  const ClusteredDifference again = clustered_paired_difference(a, b, ids, 2024);
  EXPECT_EQ(d.bootstrap_low, again.bootstrap_low);
  EXPECT_EQ(d.bootstrap_high, again.bootstrap_high);
  EXPECT_DOUBLE_EQ(d.mean, 5.5);
  // Inside the range of the cluster means, strictly (reaching 1 or 10 needs all ten
  // draws on one wall), and around the mean.
  EXPECT_GT(d.bootstrap_low, 1.0);
  EXPECT_LT(d.bootstrap_high, 10.0);
  EXPECT_LT(d.bootstrap_low, d.mean);
  EXPECT_GT(d.bootstrap_high, d.mean);
  // Normal approximation: the bootstrap sd of the mean is the population sd of 1..10,
  // sqrt(8.25), over sqrt(10): 0.9083, so about 5.5 -+ 1.96 * 0.9083 = [3.72, 7.28].
  EXPECT_NEAR(d.bootstrap_low, 3.72, 0.25);
  EXPECT_NEAR(d.bootstrap_high, 7.28, 0.25);
  // Narrower than the t interval with 9 df: 5.5 -+ 2.2622 * sqrt(55/6) / sqrt(10) = -+ 2.166.
  EXPECT_NEAR(d.t_high - d.mean, 2.166, 1e-3);
  EXPECT_LT(d.bootstrap_high - d.bootstrap_low, d.t_high - d.t_low);
}

TEST(Statistics, ClusterBootstrapDependsOnTheSeed) {
  // Irregular cluster means, so that two seeds all but surely give different percentiles.
  const std::vector<double> a{0.31, 2.72, -1.41, 1.73, 0.58, 3.14, -0.69, 1.62};
  const std::vector<double> b(a.size(), 0.0);
  const std::vector<std::size_t> ids{0, 1, 2, 3, 4, 5, 6, 7};
  const ClusteredDifference one = clustered_paired_difference(a, b, ids, 1);
  const ClusteredDifference two = clustered_paired_difference(a, b, ids, 2);
  EXPECT_NE(one.bootstrap_low, two.bootstrap_low);
  EXPECT_NE(one.bootstrap_high, two.bootstrap_high);
  EXPECT_EQ(one.mean, two.mean);  // the point estimate does not depend on the seed
  const double lowest = *std::min_element(a.begin(), a.end());
  const double highest = *std::max_element(a.begin(), a.end());
  for (const ClusteredDifference& d : {one, two}) {
    EXPECT_GE(d.bootstrap_low, lowest);
    EXPECT_LE(d.bootstrap_high, highest);
    EXPECT_LT(d.bootstrap_low, d.mean);
    EXPECT_GT(d.bootstrap_high, d.mean);
  }
}

TEST(Statistics, ClustersForPowerByHand) {
  // effect = sd, power 0.8, alpha 0.05. The z formula gives (1.95996 + 0.84162)^2 = 7.85.
  // With t quantiles (published tables) n must satisfy n >= (t(0.975, n-1) + t(0.8, n-1))^2:
  //   n = 8: (2.365 + 0.896)^2 = 3.261^2 = 10.63 > 8, no
  //   n = 9: (2.306 + 0.889)^2 = 3.195^2 = 10.21 > 9, no
  //   n = 10: (2.262 + 0.883)^2 = 3.145^2 = 9.89 <= 10, yes.
  EXPECT_EQ(clusters_for_power(1.0, 1.0), 10);
  EXPECT_EQ(clusters_for_power(-2.0, 2.0), 10);  // only |effect| / sd matters
  EXPECT_EQ(clusters_for_power(1.0, 1.0, 0.8, 0.05, 10), 10);
  EXPECT_EQ(clusters_for_power(1.0, 1.0, 0.8, 0.05, 9), -1);
  // effect = sd / 2 (factor (sd / effect)^2 = 4):
  //   n = 33: 4 (2.0369 + 0.8531)^2 = 4 * 8.352 = 33.41 > 33, no
  //   n = 34: 4 (2.0345 + 0.8530)^2 = 4 * 8.338 = 33.35 <= 34, yes.
  EXPECT_EQ(clusters_for_power(0.5, 1.0), 34);
  // effect = sd, power 0.9:
  //   n = 12: (2.201 + 1.363)^2 = 3.564^2 = 12.70 > 12, no
  //   n = 13: (2.179 + 1.356)^2 = 3.535^2 = 12.50 <= 13, yes.
  EXPECT_EQ(clusters_for_power(1.0, 1.0, 0.9), 13);
  // No noise: the smallest design allowed.
  EXPECT_EQ(clusters_for_power(1.0, 0.0), 2);
}

TEST(Statistics, ClustersForPowerImpossibleRequests) {
  EXPECT_EQ(clusters_for_power(0.0, 1.0), -1);
  EXPECT_EQ(clusters_for_power(std::nan(""), 1.0), -1);
  EXPECT_EQ(clusters_for_power(INFINITY, 1.0), -1);
  EXPECT_EQ(clusters_for_power(1.0, std::nan("")), -1);
  EXPECT_EQ(clusters_for_power(1.0, -1.0), -1);
  // effect = sd / 1000 needs about 7.85e6 clusters, far above the cap.
  EXPECT_EQ(clusters_for_power(0.001, 1.0), -1);
  EXPECT_EQ(clusters_for_power(0.001, 1.0, 0.8, 0.05, 1000), -1);
}

// Holm (1979) by hand: p = (0.01, 0.04, 0.03, 0.5) sorted 0.01, 0.03, 0.04, 0.5 gives
// 4 x 0.01 = 0.04, 3 x 0.03 = 0.09, 2 x 0.04 = 0.08 -> 0.09 (monotone), 1 x 0.5 = 0.5.
TEST(Statistics, HolmAdjustmentByHand) {
  const std::vector<double> adjusted = holm_adjusted({0.01, 0.04, 0.03, 0.5});
  ASSERT_EQ(adjusted.size(), 4u);
  EXPECT_DOUBLE_EQ(adjusted[0], 0.04);
  EXPECT_DOUBLE_EQ(adjusted[1], 0.09);
  EXPECT_DOUBLE_EQ(adjusted[2], 0.09);
  EXPECT_DOUBLE_EQ(adjusted[3], 0.5);
  EXPECT_EQ(holm_adjusted({0.6, 0.7}), (std::vector<double>{1.0, 1.0})) << "capped at 1";
  EXPECT_EQ(holm_adjusted({0.02}), (std::vector<double>{0.02})) << "one comparison is not adjusted";
  EXPECT_TRUE(holm_adjusted({}).empty());
}

}  // namespace
}  // namespace crux
