#pragma once
// Summary statistics for reporting runs: mean with a Student-t 95 % confidence interval,
// and the paired t-test between two conditions run on the same walls.

#include <vector>

namespace crux {

struct MeanInterval {
  int n = 0;
  double mean = 0.0;
  double standard_deviation = 0.0;
  double half_width = 0.0;  // of the 95 % confidence interval (0 when n < 2)
};

MeanInterval mean_interval(const std::vector<double>& values);

// Two-sided p-value of the paired t-test that the mean of (a_i - b_i) is 0.
struct PairedTest {
  MeanInterval difference;  // of a - b
  double t = 0.0;
  double p_value = 1.0;
};
PairedTest paired_t_test(const std::vector<double>& a, const std::vector<double>& b);

// Student's t distribution with `dof` degrees of freedom.
double student_t_cdf(double t, double dof);
double student_t_quantile(double probability, double dof);

}  // namespace crux
