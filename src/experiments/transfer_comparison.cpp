#include "experiments/transfer_comparison.hpp"

#include <algorithm>

#include <fmt/format.h>

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

double early_episodes(const RunResult& run, int, int window) { return episodes_between(run, 0, window); }
double late_episodes(const RunResult& run, int iterations, int window) {
  return episodes_between(run, iterations - window, iterations);
}
double first_episodes(const RunResult& run, int iterations, int) {
  return iterations_to_complete(run, kEarlyEpisodes, iterations);
}
// Fewer than 10 completed episodes: the mean of those there are; none: the run's length.
double last_lengths(const RunResult& run, int iterations, int) {
  const std::size_t n = run.episode_lengths.size();
  if (n == 0) return iterations;
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

std::vector<EpisodeMetric> episode_metrics(int iterations, int window) {
  std::vector<EpisodeMetric> metrics{
      {"early_episodes", fmt::format("episodes completed in the first {} iterations", window), early_episodes},
      {"first_5_iterations", "iterations to complete the first 5 episodes (capped at the run)", first_episodes},
  };
  if (iterations >= 2 * window) {
    metrics.push_back(
        {"late_episodes", fmt::format("episodes completed in the last {} iterations", window), late_episodes});
  }
  metrics.push_back({"last_10_length", "mean length of the last 10 episodes (iterations)", last_lengths});
  return metrics;
}

std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, int iterations, int window) {
  std::vector<MetricComparison> out;
  for (const EpisodeMetric& metric : episode_metrics(iterations, window)) {
    MetricComparison comparison;
    comparison.metric = metric;
    std::array<std::vector<double>, 3> values;
    for (const Condition c : kConditions) {
      for (const RunResult& run : result.conditions[static_cast<int>(c)].runs) {
        values[static_cast<int>(c)].push_back(metric.of_run(run, iterations, window));
      }
      comparison.per_condition[static_cast<int>(c)] = mean_interval(values[static_cast<int>(c)]);
    }
    comparison.transfer_minus_control = paired_t_test(values[static_cast<int>(Condition::Transfer)],
                                                      values[static_cast<int>(Condition::Control)]);
    out.push_back(comparison);
  }
  return out;
}

}  // namespace crux
