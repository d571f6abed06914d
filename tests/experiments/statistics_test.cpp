#include "experiments/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace crux {
namespace {

TEST(Statistics, StudentTAgainstPublishedTables) {
  // Two-sided 95 % critical values from standard t tables.
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.7062, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 5), 2.5706, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 29), 2.0452, 1e-4);
  EXPECT_NEAR(student_t_cdf(0.0, 7), 0.5, 1e-15);
  EXPECT_NEAR(student_t_cdf(2.0, 10), 0.963306, 1e-6);  // tables: 1 - 0.036694
  EXPECT_NEAR(student_t_cdf(-2.0, 10), 0.036694, 1e-6);
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

}  // namespace
}  // namespace crux
