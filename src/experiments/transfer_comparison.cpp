#include "experiments/transfer_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/counted.hpp"

namespace crux {

namespace {

constexpr std::size_t kEarlyEpisodes = 5, kLateEpisodes = 10;

// Episodes completed whose last action falls in (first, last].
double episodes_between(const RunResult& run, int first, int last) {
  int end = 0, count = 0;
  for (const int length : run.episode_lengths) {
    end += length;
    if (end > first && end <= last) ++count;
  }
  return count;
}

double early_episodes(const RunResult& run, const MetricWindows& w) { return episodes_between(run, 0, w.window); }
double late_episodes(const RunResult& run, const MetricWindows& w) {
  return episodes_between(run, w.iterations - w.window, w.iterations);
}
double first_episodes(const RunResult& run, const MetricWindows& w) {
  return iterations_to_complete(run, kEarlyEpisodes, w.iterations);
}
// A run that completes no episode: its length, a lower bound.
double jumpstart(const RunResult& run, const MetricWindows& w) {
  return run.episode_lengths.empty() ? w.iterations : run.episode_lengths.front();
}
// A run that never completes an episode that short: its length, a lower bound.
double iterations_to_length(const RunResult& run, long long threshold_length, int iterations) {
  int end = 0;
  for (const int length : run.episode_lengths) {
    end += length;
    if (length <= threshold_length) return end;
  }
  return iterations;
}
double time_to_threshold(const RunResult& run, const MetricWindows& w) {
  return iterations_to_length(run, w.threshold_length, w.iterations);
}
// Time to threshold at a multiple of threshold_length (episode lengths are whole, so
// half of an odd threshold rounds down without changing which episodes qualify).
template <int Doubled>
double time_to_scaled_threshold(const RunResult& run, const MetricWindows& w) {
  return iterations_to_length(run, Doubled * static_cast<long long>(w.threshold_length) / 2, w.iterations);
}
double total_reward(const RunResult& run, const MetricWindows&) {
  double sum = 0.0;
  for (const IterationRecord& r : run.iterations) sum += r.reward;
  return sum;
}
// Fewer than 10 completed episodes: the mean of those there are; none: the run's length.
double last_lengths(const RunResult& run, const MetricWindows& w) {
  const std::size_t n = run.episode_lengths.size();
  if (n == 0) return w.iterations;
  const std::size_t from = n - std::min(kLateEpisodes, n);
  double sum = 0;
  for (std::size_t i = from; i < n; ++i) sum += run.episode_lengths[i];
  return sum / static_cast<double>(n - from);
}

}  // namespace

double iterations_to_complete(const RunResult& run, std::size_t episodes, int iterations) {
  if (run.episode_lengths.size() < episodes) return iterations;
  double total = 0;
  for (std::size_t e = 0; e < episodes; ++e) total += run.episode_lengths[e];
  return total;
}

int take_off_iteration(const RunResult& run, int threshold_length) {
  int start = 0;
  for (const int length : run.episode_lengths) {
    if (length <= threshold_length) {
      int w_greedy = 0;
      for (int i = start; i < start + length; ++i) w_greedy += run.iterations[i].regime == Regime::WGreedy;
      if (2 * w_greedy >= length) return start + length;
    }
    start += length;
  }
  return -1;
}

int first_divergence(const RunResult& a, const RunResult& b) {
  const std::size_t n = std::min(a.iterations.size(), b.iterations.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (a.iterations[i].hold_id != b.iterations[i].hold_id || a.iterations[i].success != b.iterations[i].success) {
      return static_cast<int>(i) + 1;
    }
  }
  return -1;
}

std::vector<EpisodeMetric> episode_metrics(const MetricWindows& w) {
  std::vector<EpisodeMetric> metrics{
      {"early_episodes", fmt::format("episodes completed in the first {}", counted(w.window, "iteration")), true,
       early_episodes},
      {"jumpstart", "length of the first episode (iterations; the run's length if none)", false, jumpstart},
      {"time_to_threshold",
       fmt::format("iterations to the end of the first episode of at most {} (the run's length if none)",
                   w.threshold_length),
       false, time_to_threshold},
      {"first_5_iterations", "iterations to complete the first 5 episodes (capped at the run)", false, first_episodes},
      {"total_reward", "total reward of the run (area under its reward curve)", true, total_reward},
  };
  if (w.iterations >= 2 * w.window) {
    metrics.push_back({"late_episodes",
                       fmt::format("episodes completed in the last {}", counted(w.window, "iteration")), true,
                       late_episodes});
  }
  metrics.push_back(
      {"last_10_length", "mean length of the last 10 episodes (asymptotic performance)", false, last_lengths});
  // Several thresholds (issue 28), after the metrics of earlier versions so their order holds.
  const auto at_length = [&](const char* name, int doubled, double (*of_run)(const RunResult&, const MetricWindows&)) {
    metrics.push_back(
        {name,
         fmt::format("iterations to the end of the first episode of at most {} (the run's length if none)",
                     doubled * static_cast<long long>(w.threshold_length) / 2),
         false, of_run});
  };
  at_length("time_to_threshold_half", 1, time_to_scaled_threshold<1>);
  at_length("time_to_threshold_2x", 4, time_to_scaled_threshold<4>);
  at_length("time_to_threshold_4x", 8, time_to_scaled_threshold<8>);
  return metrics;
}

std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, const MetricWindows& windows,
                                               std::uint64_t bootstrap_seed, int bootstrap_resamples,
                                               const RandomStream& stratified_stream) {
  std::vector<MetricComparison> out;
  const auto& transfer = result.conditions[static_cast<int>(Condition::Transfer)];
  for (const EpisodeMetric& metric : episode_metrics(windows)) {
    MetricComparison comparison;
    comparison.metric = metric;
    std::array<std::vector<double>, 3> values;
    for (const Condition c : kConditions) {
      const ConditionResult& condition = result.conditions[static_cast<int>(c)];
      for (const RunResult& run : condition.runs) values[static_cast<int>(c)].push_back(metric.of_run(run, windows));
      comparison.per_condition[static_cast<int>(c)] =
          mean_interval(cluster_means(values[static_cast<int>(c)], condition.cluster_of_run));
    }
    const auto& t = values[static_cast<int>(Condition::Transfer)];
    const auto& c = values[static_cast<int>(Condition::Control)];
    comparison.transfer_minus_control =
        clustered_paired_difference(t, c, transfer.cluster_of_run, bootstrap_seed, bootstrap_resamples);
    const double control_mean = comparison.per_condition[static_cast<int>(Condition::Control)].mean;
    comparison.relative_difference = control_mean != 0.0
                                         ? comparison.transfer_minus_control.mean / std::abs(control_mean)
                                         : std::numeric_limits<double>::quiet_NaN();
    comparison.paired_correlation = pearson_correlation(t, c);
    comparison.wall_correlation =
        pearson_correlation(cluster_means(t, transfer.cluster_of_run), cluster_means(c, transfer.cluster_of_run));
    // One wall has no spread to plan from.
    comparison.walls_for_power = comparison.transfer_minus_control.clusters < 2
                                     ? -1
                                     : clusters_for_power(comparison.transfer_minus_control.mean,
                                                          comparison.transfer_minus_control.standard_deviation);
    comparison.stratified =
        stratified_comparison(t, c, transfer.cluster_of_run, metric.higher_is_better, stratified_stream);
    out.push_back(comparison);
  }
  return out;
}

}  // namespace crux
