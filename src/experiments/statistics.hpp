#pragma once
// Summary statistics for reporting runs: mean with a Student-t 95 % confidence interval,
// the paired t-test between two conditions run on the same walls, its clustered version
// (several seeds per wall), a correlation coefficient and a power calculation.

#include <cstddef>
#include <cstdint>
#include <span>
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

// Student's t distribution with `dof` degrees of freedom (Boost.Math's).
double student_t_cdf(double t, double dof);
double student_t_quantile(double probability, double dof);

// The mean of `values` per cluster, clusters in order of first appearance in
// cluster_of_value: the observations of an analysis whose unit is the wall.
std::vector<double> cluster_means(const std::vector<double>& values, const std::vector<std::size_t>& cluster_of_value);

// Sample Pearson correlation of the pairs (a_i, b_i). NaN when there are fewer than 2
// pairs or when either side has zero variance: r is undefined then, and NaN keeps a
// report from showing a made-up 0.
double pearson_correlation(const std::vector<double>& a, const std::vector<double>& b);

// The q-quantile (q in [0, 1]) of `sorted`, which must be sorted ascending and non-empty,
// by linear interpolation between order statistics: h = (n - 1) q,
// result = x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]). This is Hyndman &
// Fan's type 7, the default of R's quantile() and numpy.percentile.
double percentile(std::span<const double> sorted, double q);

// Paired comparison (a_i vs b_i, e.g. transfer run vs control run) when pairs are
// clustered (several seeds on the same wall): pairs on one wall are not independent, so
// the unit of inference is the cluster. Each cluster is reduced to the mean of its
// differences a_i - b_i and every cluster weighs the same, whatever its number of pairs.
struct ClusteredDifference {
  int clusters = 0;                                  // distinct cluster ids (walls)
  int pairs = 0;                                     // run pairs
  double mean = 0.0;                                 // mean over clusters of the per-cluster mean difference
  double standard_deviation = 0.0;                   // sample sd of the per-cluster mean differences
  double t_low = 0.0, t_high = 0.0;                  // 95 % Student-t interval, df = clusters - 1
  double t = 0.0, p_value = 1.0;                     // two-sided one-sample t-test of the cluster means
  double bootstrap_low = 0.0, bootstrap_high = 0.0;  // 95 % cluster-bootstrap percentile interval
};
// cluster_of_pair[i] is the cluster id (any value) of pair i. Clusters are ordered by
// first appearance in cluster_of_pair, which fixes which cluster the bootstrap's draw k
// means, so the result for a given seed is deterministic. The t-test treats the cluster
// means exactly as paired_t_test treats differences (so with one pair per cluster the
// mean, sd, t and p equal paired_t_test(a, b)'s). The bootstrap draws `clusters` clusters
// with replacement `resamples` times (Random(bootstrap_seed)), takes the mean of the drawn
// cluster means, and reports its 2.5 % and 97.5 % percentiles (see percentile()).
// With fewer than 2 clusters there is no spread to estimate: sd = 0, both intervals
// collapse to the mean, t = 0 and p = 1.
ClusteredDifference clustered_paired_difference(const std::vector<double>& a, const std::vector<double>& b,
                                                const std::vector<std::size_t>& cluster_of_pair,
                                                std::uint64_t bootstrap_seed, int resamples = 10000);

// Number of clusters (walls) needed for the clustered paired design: the smallest n >= 2
// for which a two-sided one-sample t-test at level `alpha` on n cluster means with
// standard deviation `standard_deviation` detects a true mean difference `effect` with
// probability at least `power`. Uses the usual approximation of the noncentral t power,
//   n >= ((t_{1-alpha/2, n-1} + t_{power, n-1}) * sd / |effect|)^2,
// solved by trying n upward (the z version of the formula, without the n-dependence,
// would underestimate n for small samples). Returns -1 when effect is 0 or not finite,
// when sd is negative or not finite, or when n would exceed max_clusters.
inline constexpr int kMaxClustersForPower = 100000;
int clusters_for_power(double effect, double standard_deviation, double power = 0.8, double alpha = 0.05,
                       int max_clusters = kMaxClustersForPower);

// Holm's step-down adjustment of p-values for m comparisons (Holm 1979): the i-th
// smallest becomes max over j <= i of min(1, (m - j + 1) p_(j)), in the input's order.
// Rejecting where the adjusted p < alpha keeps the family-wise error rate at alpha.
std::vector<double> holm_adjusted(const std::vector<double>& p_values);

}  // namespace crux
