#include "experiments/statistics.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>

#include <boost/math/distributions/students_t.hpp>

#include "common/random.hpp"

namespace crux {

namespace {

// Boost.Math's defaults, except for a NaN argument: NaN in the data comes out as a NaN
// p-value or interval, like the data's other statistics, rather than as an exception.
using StudentTPolicy =
    boost::math::policies::policy<boost::math::policies::domain_error<boost::math::policies::ignore_error>>;
using StudentT = boost::math::students_t_distribution<double, StudentTPolicy>;

}  // namespace

double student_t_cdf(double t, double dof) { return boost::math::cdf(StudentT(dof), t); }

double student_t_quantile(double probability, double dof) {
  assert(probability > 0.0 && probability < 1.0);
  return boost::math::quantile(StudentT(dof), probability);
}

MeanInterval mean_interval(const std::vector<double>& values) {
  MeanInterval out;
  out.n = static_cast<int>(values.size());
  if (out.n == 0) return out;
  for (const double v : values) out.mean += v / out.n;
  if (out.n < 2) return out;
  double squares = 0.0;
  for (const double v : values) squares += (v - out.mean) * (v - out.mean);
  out.standard_deviation = std::sqrt(squares / (out.n - 1));
  out.half_width = student_t_quantile(0.975, out.n - 1) * out.standard_deviation / std::sqrt(out.n);
  return out;
}

namespace {

// Two-sided one-sample t-test that the mean of `values` is 0. Shared by the paired test
// and the clustered one so both treat their samples identically (including sd == 0:
// t = +-inf and p = 0 for a nonzero mean, t = 0 and p = 1 for a zero mean).
PairedTest one_sample_t_test(const std::vector<double>& values) {
  PairedTest out;
  out.difference = mean_interval(values);
  if (out.difference.n < 2) return out;
  const double standard_error = out.difference.standard_deviation / std::sqrt(out.difference.n);
  if (standard_error == 0.0) {
    out.t =
        out.difference.mean == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), out.difference.mean);
    out.p_value = out.difference.mean == 0.0 ? 1.0 : 0.0;
    return out;
  }
  out.t = out.difference.mean / standard_error;
  // The upper tail computed directly: 1 - cdf would lose the digits of a small p-value.
  out.p_value = 2.0 * boost::math::cdf(boost::math::complement(StudentT(out.difference.n - 1), std::abs(out.t)));
  return out;
}

// Standard normal quantile by bisection on the erfc form of the cdf; only used for the
// starting point of the power search, so speed does not matter.
double normal_quantile(double probability) {
  double low = -40.0, high = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < probability ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace

PairedTest paired_t_test(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  std::vector<double> differences(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) differences[i] = a[i] - b[i];
  return one_sample_t_test(differences);
}

double pearson_correlation(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  const std::size_t n = a.size();
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean_a = 0.0, mean_b = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_a += a[i] / n;
    mean_b += b[i] / n;
  }
  // Centred sums (two passes) rather than sum(xy) - n mean_x mean_y, which cancels badly.
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double da = a[i] - mean_a, db = b[i] - mean_b;
    ab += da * db;
    aa += da * da;
    bb += db * db;
  }
  if (aa == 0.0 || bb == 0.0) return std::numeric_limits<double>::quiet_NaN();
  // Rounding can push |r| a hair past 1 for collinear data; r is a correlation, so clamp.
  return std::clamp(ab / std::sqrt(aa * bb), -1.0, 1.0);
}

double percentile(std::span<const double> sorted, double q) {
  assert(!sorted.empty());
  assert(q >= 0.0 && q <= 1.0);
  assert(std::is_sorted(sorted.begin(), sorted.end()));
  const double h = (sorted.size() - 1) * q;
  const std::size_t below = static_cast<std::size_t>(std::floor(h));
  if (below + 1 >= sorted.size()) return sorted.back();  // q == 1 (or h rounding to n - 1)
  return sorted[below] + (h - below) * (sorted[below + 1] - sorted[below]);
}

std::vector<double> cluster_means(const std::vector<double>& values, const std::vector<std::size_t>& cluster_of_value) {
  assert(values.size() == cluster_of_value.size());
  // A linear search over the ids seen so far: there are tens of walls, not millions.
  std::vector<std::size_t> ids;
  std::vector<double> sums;
  std::vector<int> counts;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto found = std::find(ids.begin(), ids.end(), cluster_of_value[i]);
    const std::size_t k = static_cast<std::size_t>(found - ids.begin());
    if (found == ids.end()) {
      ids.push_back(cluster_of_value[i]);
      sums.push_back(0.0);
      counts.push_back(0);
    }
    sums[k] += values[i];
    ++counts[k];
  }
  for (std::size_t k = 0; k < ids.size(); ++k) sums[k] /= counts[k];
  return sums;
}

ClusteredDifference clustered_paired_difference(const std::vector<double>& a, const std::vector<double>& b,
                                                const std::vector<std::size_t>& cluster_of_pair,
                                                std::uint64_t bootstrap_seed, int resamples) {
  assert(a.size() == b.size() && a.size() == cluster_of_pair.size());
  assert(resamples > 0);

  // Per-cluster mean difference, clusters in order of first appearance.
  std::vector<double> differences(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) differences[i] = a[i] - b[i];
  const std::vector<double> means = cluster_means(differences, cluster_of_pair);

  ClusteredDifference out;
  out.clusters = static_cast<int>(means.size());
  out.pairs = static_cast<int>(a.size());
  // The clusters are now the independent observations: a one-sample t-test on their means.
  const PairedTest test = one_sample_t_test(means);
  out.mean = test.difference.mean;
  out.standard_deviation = test.difference.standard_deviation;
  out.t = test.t;
  out.p_value = test.p_value;
  out.t_low = out.mean - test.difference.half_width;
  out.t_high = out.mean + test.difference.half_width;
  out.bootstrap_low = out.bootstrap_high = out.mean;
  if (out.clusters < 2) return out;

  // Cluster bootstrap: resample whole walls, so the within-wall dependence is kept.
  Random random(bootstrap_seed);
  const std::size_t c = means.size();
  std::vector<double> statistics(static_cast<std::size_t>(resamples));
  for (double& statistic : statistics) {
    double sum = 0.0;
    for (std::size_t k = 0; k < c; ++k) sum += means[random.below(c)];
    statistic = sum / c;
  }
  std::sort(statistics.begin(), statistics.end());
  out.bootstrap_low = percentile(statistics, 0.025);
  out.bootstrap_high = percentile(statistics, 0.975);
  return out;
}

int clusters_for_power(double effect, double standard_deviation, double power, double alpha, int max_clusters) {
  assert(power > 0.0 && power < 1.0);
  assert(alpha > 0.0 && alpha < 1.0);
  if (effect == 0.0 || !std::isfinite(effect)) return -1;
  if (!(standard_deviation >= 0.0) || !std::isfinite(standard_deviation)) return -1;
  const double ratio = standard_deviation / std::abs(effect);
  const auto required = [&](double quantile_sum) { return quantile_sum * ratio * quantile_sum * ratio; };

  // For power >= 0.5 both t quantiles exceed the normal ones, so the required n is always
  // above the z approximation: no n below it can qualify. Starting there keeps the search
  // short (and lets a hopeless request fail at once) without changing the answer.
  int start = 2;
  if (power >= 0.5) {
    const double z_approximation = required(normal_quantile(1.0 - alpha / 2.0) + normal_quantile(power));
    if (!(z_approximation <= max_clusters)) return -1;
    start = std::max(2, static_cast<int>(std::floor(z_approximation)));
  }
  for (int n = start; n <= max_clusters; ++n) {
    const double dof = n - 1;
    if (n >= required(student_t_quantile(1.0 - alpha / 2.0, dof) + student_t_quantile(power, dof))) return n;
  }
  return -1;
}

std::vector<double> holm_adjusted(const std::vector<double>& p_values) {
  const std::size_t m = p_values.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Ties keep their input order (a plain sort with the index as tie-break: libstdc++'s
  // stable_sort buffer trips AddressSanitizer's alloc-dealloc check).
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return p_values[a] < p_values[b] || (p_values[a] == p_values[b] && a < b);
  });
  std::vector<double> adjusted(m);
  double running = 0.0;
  for (std::size_t rank = 0; rank < m; ++rank) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - rank) * p_values[order[rank]]));
    adjusted[order[rank]] = running;
  }
  return adjusted;
}

}  // namespace crux
