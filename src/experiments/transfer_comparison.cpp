#include "experiments/transfer_comparison.hpp"

#include <algorithm>

namespace crux {

namespace {

constexpr int kWindow = 2000;
constexpr std::size_t kEarlyEpisodes = 5, kLateEpisodes = 10;

// Episodes completed whose last action falls in [first, last).
double episodes_between(const RunResult& run, int first, int last) {
  int end = 0, count = 0;
  for (const int length : run.episode_lengths) {
    end += length;
    if (end > first && end <= last) ++count;
  }
  return count;
}

double mean_length(const std::vector<int>& lengths, std::size_t from, std::size_t to) {
  if (to <= from) return 0.0;
  double sum = 0;
  for (std::size_t i = from; i < to; ++i) sum += lengths[i];
  return sum / static_cast<double>(to - from);
}

double early_episodes(const RunResult& run, int) { return episodes_between(run, 0, kWindow); }
double late_episodes(const RunResult& run, int iterations) {
  return episodes_between(run, iterations - kWindow, iterations);
}
double first_lengths(const RunResult& run, int iterations) {
  // A run that never finishes counts its whole length, a lower bound on its first episode.
  if (run.episode_lengths.empty()) return iterations;
  return mean_length(run.episode_lengths, 0, std::min(kEarlyEpisodes, run.episode_lengths.size()));
}
double last_lengths(const RunResult& run, int iterations) {
  const std::size_t n = run.episode_lengths.size();
  if (n == 0) return iterations;
  return mean_length(run.episode_lengths, n - std::min(kLateEpisodes, n), n);
}

}  // namespace

const std::vector<EpisodeMetric>& episode_metrics() {
  static const std::vector<EpisodeMetric> metrics{
      {"early_episodes", "episodes completed in the first 2000 iterations", early_episodes, true},
      {"first_5_length", "mean length of the first 5 episodes (iterations)", first_lengths, false},
      {"late_episodes", "episodes completed in the last 2000 iterations", late_episodes, true},
      {"last_10_length", "mean length of the last 10 episodes (iterations)", last_lengths, false},
  };
  return metrics;
}

std::vector<MetricComparison> compare_transfer(const ExperimentResult& result, int iterations) {
  std::vector<MetricComparison> out;
  for (const EpisodeMetric& metric : episode_metrics()) {
    MetricComparison comparison;
    comparison.metric = &metric;
    std::array<std::vector<double>, 3> values;
    for (const Condition c : kConditions) {
      for (const RunResult& run : result.conditions[static_cast<int>(c)].runs) {
        values[static_cast<int>(c)].push_back(metric.of_run(run, iterations));
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
